#ifndef signorini_elasticity_loads_h
#define signorini_elasticity_loads_h

#include <deal.II/base/function.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/lac/trilinos_vector.h>
#include <deal.II/lac/vector.h>

#include <signorini/discretisation/boundary_conditions.h>
#include <signorini/discretisation/discretisation.h>

#include <memory>

namespace signorini
{
  /**
   * The loads on the body: body force and traction (Boundary conditions),
   * with a Traction resultant turned into the uniform traction of that force
   * on each mesh. Integrals are weighted by Discretisation::weight (over the
   * whole revolution of an axisymmetric model).
   */
  template <int dim>
  class Loads
  {
  public:
    Loads(const BoundaryConditions<dim> &boundary_conditions,
          const Discretisation<dim>     &discretisation);

    /** The loads at the pseudo-time @p t of the load history: the time of
     * the traction and body force functions, and of the traction
     * resultant at the next assemble(). */
    void
    set_time(const double t);

    /** The load vector f [N] of the current mesh, with the hanging nodes and
     * Dirichlet dofs condensed; sets the traction of this mesh. Throws
     * InputError if a load is not finite. */
    void
    assemble(dealii::TrilinosWrappers::MPI::Vector &load);

    /** Whether @p cell carries a load: a body force (unless it vanishes),
     * or a face with the traction. Elsewhere cell_load() is zero. */
    bool
    loaded(
      const typename dealii::DoFHandler<dim>::active_cell_iterator &cell) const;

    /** The load vector of one cell, body force and traction [N], with the
     * traction of the last assemble(). */
    void
    cell_load(
      const typename dealii::DoFHandler<dim>::active_cell_iterator &cell,
      dealii::FEValues<dim>                                        &fe_values,
      dealii::FEFaceValues<dim> &fe_face_values,
      dealii::Vector<double>    &cell_load) const;

    /** The update flags cell_load() needs. */
    static dealii::UpdateFlags
    update_flags()
    {
      return dealii::update_values | dealii::update_quadrature_points |
             dealii::update_JxW_values;
    }

  private:
    /** Whether face @p f of @p cell carries the traction. */
    bool
    traction_face(
      const typename dealii::DoFHandler<dim>::active_cell_iterator &cell,
      const unsigned int                                            f) const;

    const BoundaryConditions<dim>         &boundary_conditions;
    const Discretisation<dim>             &discretisation;
    const dealii::Function<dim>           *traction = nullptr;
    std::unique_ptr<dealii::Function<dim>> uniform_traction;
    /** The pseudo-time of the loads. */
    double time = 0.;
  };
} // namespace signorini

#endif
