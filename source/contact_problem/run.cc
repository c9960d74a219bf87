#include <signorini/contact_problem.h>

namespace signorini
{
  using namespace dealii;

  template <int dim>
  void
  ContactProblem<dim>::run()
  {
    try
      {
        run_cycles();
      }
    catch (...)
      {
        // A failed run reports one line, not a timer summary.
        timer.disable_output();
        throw;
      }
  }

  template <int dim>
  void
  ContactProblem<dim>::run_cycles()
  {
    make_grid();
    setup_system();
    write_obstacle_and_parameters();
    for (unsigned int cycle = 0; cycle < parameters.refinement.n_cycles;
         ++cycle)
      {
        if (cycle > 0)
          refine_grid();
        pcout << "Cycle " << cycle << ": "
              << triangulation->n_global_active_cells() << " cells, "
              << dof_handler.n_dofs() << " dofs" << std::endl;
        solve_contact_problem(cycle);
        estimate_error();
        record_statistics(cycle);
        output_results(cycle);
      }
  }

  template void
  ContactProblem<2>::run_cycles();
  template void
  ContactProblem<3>::run_cycles();
  template void
  ContactProblem<2>::run();
  template void
  ContactProblem<3>::run();
} // namespace signorini
