#include <deal.II/distributed/grid_refinement.h>
#include <deal.II/distributed/solution_transfer.h>
#include <deal.II/distributed/tria.h>
#include <deal.II/numerics/error_estimator.h>
#include <deal.II/numerics/solution_transfer.h>

#include <signorini/contact_problem.h>

namespace signorini
{
  using namespace dealii;

  template <int dim>
  void
  ContactProblem<dim>::estimate_error()
  {
    TimerOutput::Scope t(timer, "Refine: error estimate");
    estimated_error_per_cell.reinit(triangulation->n_active_cells());
    KellyErrorEstimator<dim>::estimate(*mapping,
                                       dof_handler,
                                       face_quadrature,
                                       {},
                                       solution,
                                       estimated_error_per_cell);
  }

  template <int dim>
  void
  ContactProblem<dim>::refine_grid()
  {
    TimerOutput::Scope t(timer, "Refine: mesh and transfer");
    const auto        &refinement = parameters.refinement;
    auto              *distributed =
      dynamic_cast<parallel::distributed::Triangulation<dim> *>(
        triangulation.get());

    if (refinement.strategy == Refinement::Strategy::global)
      for (const auto &cell : triangulation->active_cell_iterators())
        if (cell->is_locally_owned())
          cell->set_refine_flag();
    if (refinement.strategy == Refinement::Strategy::kelly)
      parallel::distributed::GridRefinement::refine_and_coarsen_fixed_number(
        *distributed,
        estimated_error_per_cell,
        refinement.refine_fraction,
        refinement.coarsen_fraction);

    // Carry the displacement and the pressure over, so that the next cycle
    // starts from this one's solution and active set.
    using VectorType = TrilinosWrappers::MPI::Vector;
    if (distributed)
      {
        parallel::distributed::SolutionTransfer<dim, VectorType> transfer(
          dof_handler);
        triangulation->prepare_coarsening_and_refinement();
        transfer.prepare_for_coarsening_and_refinement(
          std::vector<const VectorType *>{&solution, &pressure});
        triangulation->execute_coarsening_and_refinement();
        setup_system();
        VectorType new_solution(locally_owned_dofs, mpi_communicator);
        VectorType new_pressure(locally_owned_dofs, mpi_communicator);
        std::vector<VectorType *> out{&new_solution, &new_pressure};
        transfer.interpolate(out);
        fixed_constraints.distribute(new_solution);
        solution = new_solution;
        pressure = new_pressure;
      }
    else
      {
        SolutionTransfer<dim, VectorType> transfer(dof_handler);
        const std::vector<VectorType>     old_vectors{solution, pressure};
        triangulation->prepare_coarsening_and_refinement();
        transfer.prepare_for_coarsening_and_refinement(old_vectors);
        triangulation->execute_coarsening_and_refinement();
        setup_system();
        std::vector<VectorType> new_vectors(2,
                                            VectorType(locally_owned_dofs,
                                                       mpi_communicator));
        transfer.interpolate(old_vectors, new_vectors);
        fixed_constraints.distribute(new_vectors[0]);
        solution = new_vectors[0];
        pressure = new_vectors[1];
      }
  }

  template void
  ContactProblem<2>::estimate_error();
  template void
  ContactProblem<3>::estimate_error();
  template void
  ContactProblem<2>::refine_grid();
  template void
  ContactProblem<3>::refine_grid();
} // namespace signorini
