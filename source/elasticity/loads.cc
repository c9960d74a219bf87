#include <deal.II/base/mpi.h>

#include <signorini/elasticity/loads.h>
#include <signorini/input/parsed_function.h>

namespace signorini
{
  using namespace dealii;

  template <int dim>
  Loads<dim>::Loads(const BoundaryConditions<dim> &boundary_conditions,
                    const Discretisation<dim>     &discretisation)
    : boundary_conditions(boundary_conditions)
    , discretisation(discretisation)
  {
  }

  template <int dim>
  void
  Loads<dim>::set_time(const double t)
  {
    // The functions' time is the state of their evaluation, not a
    // parameter: the parameters hold them for every user of the loads.
    boundary_conditions.traction->set_time(t);
    boundary_conditions.body_force->set_time(t);
    time = t;
  }

  template <int dim>
  bool
  Loads<dim>::traction_face(
    const typename DoFHandler<dim>::active_cell_iterator &cell,
    const unsigned int                                    f) const
  {
    return cell->face(f)->at_boundary() &&
           boundary_conditions.traction_ids.count(cell->face(f)->boundary_id());
  }

  template <int dim>
  bool
  Loads<dim>::loaded(
    const typename DoFHandler<dim>::active_cell_iterator &cell) const
  {
    const auto &bc = boundary_conditions;
    if (!vanishes(*bc.body_force))
      return true;
    if (bc.traction_ids.empty() || !cell->at_boundary())
      return false;
    for (const unsigned int f : cell->face_indices())
      if (traction_face(cell, f))
        return true;
    return false;
  }

  template <int dim>
  void
  Loads<dim>::cell_load(
    const typename DoFHandler<dim>::active_cell_iterator &cell,
    FEValues<dim>                                        &fe_values,
    FEFaceValues<dim>                                    &fe_face_values,
    Vector<double>                                       &cell_load) const
  {
    const auto        &bc = boundary_conditions;
    const auto        &fe = discretisation.fe();
    const unsigned int n  = fe.n_dofs_per_cell();
    Vector<double>     value(dim);
    cell_load = 0;

    // Adds the integral of the vector function f times the shape functions.
    const auto integrate = [&](const auto &values, const Function<dim> &f) {
      for (const unsigned int q : values.quadrature_point_indices())
        {
          const Point<dim> &x   = values.quadrature_point(q);
          const double      JxW = values.JxW(q) * discretisation.weight(x);
          f.vector_value(x, value);
          for (unsigned int i = 0; i < n; ++i)
            cell_load(i) += values.shape_value(i, q) *
                            value(fe.system_to_component_index(i).first) * JxW;
        }
    };

    fe_values.reinit(cell);
    if (!vanishes(*bc.body_force))
      integrate(fe_values, *bc.body_force);
    for (const unsigned int f : cell->face_indices())
      if (traction_face(cell, f))
        {
          fe_face_values.reinit(cell, f);
          integrate(fe_face_values, *traction);
        }
  }

  template <int dim>
  void
  Loads<dim>::assemble(TrilinosWrappers::MPI::Vector &load)
  {
    load                 = 0;
    const auto       &fe = discretisation.fe();
    FEValues<dim>     fe_values(discretisation.mapping(),
                            fe,
                            discretisation.quadrature(),
                            update_flags());
    FEFaceValues<dim> fe_face_values(discretisation.mapping(),
                                     fe,
                                     discretisation.face_quadrature(),
                                     update_flags());
    Vector<double>    cell_vector(fe.n_dofs_per_cell());
    std::vector<types::global_dof_index> dof_indices(fe.n_dofs_per_cell());

    // A load by a force: the uniform traction of that resultant on the
    // traction boundaries of this mesh.
    const auto &bc = boundary_conditions;
    traction       = bc.traction.get();
    if (bc.traction_resultant)
      {
        double area = 0.;
        for (const auto &cell :
             discretisation.dof_handler().active_cell_iterators())
          if (cell->is_locally_owned())
            for (const unsigned int f : cell->face_indices())
              if (traction_face(cell, f))
                {
                  fe_face_values.reinit(cell, f);
                  for (const unsigned int q :
                       fe_face_values.quadrature_point_indices())
                    area +=
                      fe_face_values.JxW(q) *
                      discretisation.weight(fe_face_values.quadrature_point(q));
                }
        area = Utilities::MPI::sum(area, discretisation.mpi_communicator());
        const Tensor<1, dim> resultant = bc.traction_resultant->value(time);
        Vector<double>       value(dim);
        for (unsigned int d = 0; d < dim; ++d)
          value(d) = resultant[d] / area;
        uniform_traction =
          std::make_unique<Functions::ConstantFunction<dim>>(value);
        traction = uniform_traction.get();
      }

    // Only the cells with a load: the others add nothing (the constraints'
    // inhomogeneities do not enter a vector alone), and in a scene loaded
    // at its supports and its contact alone, such as sphere_indentation,
    // the loop over every cell was 2 % of a 3D run.
    for (const auto &cell :
         discretisation.dof_handler().active_cell_iterators())
      if (cell->is_locally_owned() && loaded(cell))
        {
          cell_load(cell, fe_values, fe_face_values, cell_vector);
          cell->get_dof_indices(dof_indices);
          discretisation.constraints().distribute_local_to_global(cell_vector,
                                                                  dof_indices,
                                                                  load);
        }
    load.compress(VectorOperation::add);
    check_finite(*bc.body_force, discretisation.mpi_communicator());
    check_finite(*traction, discretisation.mpi_communicator());
  }

  template class Loads<2>;
  template class Loads<3>;
} // namespace signorini
