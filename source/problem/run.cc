#include <deal.II/base/utilities.h>

#include <signorini/base/memory.h>
#include <signorini/problem/contact_problem.h>

#include <chrono>

namespace signorini
{
  using namespace dealii;

  template <int dim>
  void
  ContactProblem<dim>::run(const bool resume)
  {
    try
      {
        run_cycles(resume);
      }
    catch (...)
      {
        // A failed run reports one line, not a timer summary, and keeps the
        // files of its finished cycles.
        timer.disable_output();
        try
          {
            background_writer.launch();
            background_writer.wait();
          }
        catch (...)
          {
          }
        throw;
      }
  }

  template <int dim>
  void
  ContactProblem<dim>::run_cycles(const bool resume)
  {
    // Wall time on the slowest process.
    const auto now = [this]() {
      MPI_Barrier(mpi_communicator);
      return std::chrono::duration<double>(
               std::chrono::steady_clock::now().time_since_epoch())
        .count();
    };
    double run_time = 0., start = now();
    make_grid();
    setup_system();
    run_time += now() - start;
    const unsigned int first_cycle = start_output(resume, run_time);
    for (unsigned int cycle = first_cycle;
         cycle < parameters.refinement.n_cycles;
         ++cycle)
      {
        CycleTimings timings;
        timings.cycle = cycle;
        start         = now();
        if (cycle > 0)
          refine_grid();
        pcout << "Cycle " << cycle << ": "
              << triangulation->n_global_active_cells() << " cells, "
              << dof_handler.n_dofs() << " dofs" << std::endl;
        const double solve_start = now();
        solve_contact_problem(cycle);
        timings.contact_solve = now() - solve_start;
        // The matrix and its factorisation or AMG are rebuilt on the next
        // mesh: free them before the error estimate and the output's
        // patches take their memory. (The timing table solves once more on
        // this mesh.)
        if (!parameters.output.timing_table)
          {
            linear_system_solver.reset();
            system_matrix.clear();
            matrix_assembled = false;
            release_free_memory();
          }
        estimate_error();
        run_time += now() - start;
        timings.run_time = run_time;
        record_statistics(cycle);
        output_results(cycle);
        if (parameters.output.timing_table)
          {
            timings.linear_solve = time_linear_solve();
            write_timings(timings);
          }
        save_checkpoint(cycle, run_time);
        background_writer.launch();
        release_free_memory();
      }
    {
      TimerOutput::Scope t(timer, "Output");
      background_writer.wait();
    }
    if (parameters.output.print_timings)
      {
        Utilities::System::MemoryStats memory;
        Utilities::System::get_memory_stats(memory);
        const double peak =
          Utilities::MPI::sum(static_cast<double>(memory.VmHWM),
                              mpi_communicator) /
          1024.;
        pcout << "Peak memory: " << number(peak) << " MB on "
              << Utilities::MPI::n_mpi_processes(mpi_communicator)
              << " processes, " << number(peak * 1024. / dof_handler.n_dofs())
              << " kB per dof of the final mesh" << std::endl;
      }
  }

  template void
  ContactProblem<2>::run_cycles(bool);
  template void
  ContactProblem<3>::run_cycles(bool);
  template void
  ContactProblem<2>::run(bool);
  template void
  ContactProblem<3>::run(bool);
} // namespace signorini
