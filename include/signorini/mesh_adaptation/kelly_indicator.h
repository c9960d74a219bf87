#ifndef signorini_mesh_adaptation_kelly_indicator_h
#define signorini_mesh_adaptation_kelly_indicator_h

#include <deal.II/base/function.h>
#include <deal.II/base/quadrature.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/mapping.h>
#include <deal.II/lac/la_parallel_vector.h>
#include <deal.II/lac/vector.h>

namespace signorini
{
  /**
   * The Kelly error indicator of the displacement @p solution on the
   * locally owned cells (zero elsewhere):
   *
   *   eta_K^2 = h_K / 24 sum over the faces F of K of
   *             int_F |a [du/dn]|^2,
   *
   * the jump of the normal derivative of every component across the
   * interior faces, none on the boundary, h_K the cell's diameter [mm] and
   * a the scalar @p coefficient (one if null). These are the numbers of
   * deal.II's KellyErrorEstimator with its default strategy, no Neumann
   * boundary and all components, to rounding: the same faces, points,
   * normals and side that integrates.
   *
   * For Q1 on quadrilaterals and hexahedra with a linear mapping it is
   * computed here, each face once and only for the locally owned cells,
   * from the cell's vertices (deal.II's estimator also visits the ghost
   * cells, evaluates FEFaceValues on both sides of every face and keeps
   * the faces in a map). Any other element or mapping goes to deal.II's.
   *
   * @p solution must hold the locally relevant dofs (ghosts updated).
   */
  template <int dim>
  void
  estimate_kelly_indicators(
    const dealii::Mapping<dim>                               &mapping,
    const dealii::DoFHandler<dim>                            &dof_handler,
    const dealii::Quadrature<dim - 1>                        &face_quadrature,
    const dealii::LinearAlgebra::distributed::Vector<double> &solution,
    const dealii::Function<dim>                              *coefficient,
    dealii::Vector<float>                                    &indicators);
} // namespace signorini

#endif
