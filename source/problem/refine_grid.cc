#include <deal.II/numerics/error_estimator.h>

#include <signorini/mesh_adaptation/mesh_adaptation.h>
#include <signorini/problem/contact_problem.h>

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
    // The next cycle starts from this one's displacement and active set
    // when the mesh adaptation carries them over (not across a remesh).
    auto carried = mesh_adaptation->adapt(triangulation,
                                          dof_handler,
                                          estimated_error_per_cell,
                                          [this]() { setup_system(); },
                                          {&solution, &pressure});
    if (!carried.empty())
      {
        fixed_constraints.distribute(carried[0]);
        solution = carried[0];
        pressure = carried[1];
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
