#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_values.h>

#include <signorini/input/parsed_function.h>
#include <signorini/postprocessing/contact_zone.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace signorini
{
  using namespace dealii;

  template <int dim>
  ContactZone<dim>
  evaluate_contact_zone(const Discretisation<dim>           &discretisation,
                        const ContactSurface<dim>           &surface,
                        const Obstacle<dim>                 &obstacle,
                        const TrilinosWrappers::MPI::Vector &pressure,
                        const Reference<dim>                &reference)
  {
    const MPI_Comm   comm = discretisation.mpi_communicator();
    ContactZone<dim> zone;
    double           max_pressure = -std::numeric_limits<double>::max();
    double           x_min = std::numeric_limits<double>::max(), x_max = -x_min;
    for (const auto &node : surface.nodes())
      if (node.owned)
        {
          max_pressure = std::max(max_pressure, pressure(node.scalar_dof));
          if (node.active)
            {
              x_min = std::min(x_min, node.position[0]);
              x_max = std::max(x_max, node.position[0]);
            }
        }
    max_pressure = Utilities::MPI::max(max_pressure, comm);
    zone.max_pressure =
      max_pressure == -std::numeric_limits<double>::max() ? 0. : max_pressure;
    x_min              = Utilities::MPI::min(x_min, comm);
    x_max              = Utilities::MPI::max(x_max, comm);
    zone.contact_width = x_max >= x_min ? x_max - x_min : 0.;

    // The nodal pressures sit at one dof per node, the others hold zero:
    // summed over all components, the shape functions interpolate them.
    const auto               &ids   = surface.contact_ids();
    const Function<dim>      *exact = reference.contact_pressure.get();
    const Quadrature<dim - 1> rule =
      discretisation.simplex() && dim == 3 ?
        Quadrature<dim - 1>(QGaussSimplex<dim - 1>(4)) :
        Quadrature<dim - 1>(QGauss<dim - 1>(6));
    const auto        &fe          = discretisation.fe();
    const auto        &constraints = discretisation.constraints();
    FEFaceValues<dim>  fe_face_values(discretisation.mapping(),
                                     fe,
                                     rule,
                                     update_values | update_quadrature_points |
                                       update_JxW_values);
    const unsigned int n = fe.n_dofs_per_cell();
    std::vector<types::global_dof_index> dof_indices(n);
    std::vector<double>                  nodal(n);
    const auto nodal_pressure = [&](const types::global_dof_index i) {
      if (!constraints.is_constrained(i))
        return pressure(i);
      double value = 0.;
      if (const auto *entries = constraints.get_constraint_entries(i))
        for (const auto &[master, weight] : *entries)
          value += weight * pressure(master);
      return value;
    };

    double         integral = 0., error_squared = 0., norm_squared = 0.;
    Tensor<1, dim> resultant, normal;
    for (const auto &cell :
         discretisation.dof_handler().active_cell_iterators())
      if (cell->is_locally_owned())
        for (const unsigned int f : cell->face_indices())
          if (cell->face(f)->at_boundary() &&
              ids.count(cell->face(f)->boundary_id()))
            {
              fe_face_values.reinit(cell, f);
              cell->get_dof_indices(dof_indices);
              for (unsigned int i = 0; i < n; ++i)
                nodal[i] = nodal_pressure(dof_indices[i]);
              for (const unsigned int q :
                   fe_face_values.quadrature_point_indices())
                {
                  double p_h = 0.;
                  for (unsigned int i = 0; i < n; ++i)
                    p_h += nodal[i] * fe_face_values.shape_value(i, q);
                  const auto  &x = fe_face_values.quadrature_point(q);
                  const double JxW =
                    fe_face_values.JxW(q) * discretisation.weight(x);
                  integral += p_h * JxW;
                  obstacle.gap(x, normal);
                  resultant += p_h * JxW * normal;
                  if (exact)
                    {
                      const double p = exact->value(x);
                      error_squared += (p_h - p) * (p_h - p) * JxW;
                      norm_squared += p * p * JxW;
                    }
                }
            }
    zone.integrated_pressure = Utilities::MPI::sum(integral, comm);
    zone.pressure_resultant  = Utilities::MPI::sum(resultant, comm);
    zone.pressure_error      = std::numeric_limits<double>::quiet_NaN();
    if (exact)
      {
        check_finite(*exact, comm);
        error_squared       = Utilities::MPI::sum(error_squared, comm);
        norm_squared        = Utilities::MPI::sum(norm_squared, comm);
        zone.pressure_error = norm_squared > 0 ?
                                std::sqrt(error_squared / norm_squared) :
                                std::sqrt(error_squared);
      }
    return zone;
  }

  template ContactZone<2>
  evaluate_contact_zone(const Discretisation<2> &,
                        const ContactSurface<2> &,
                        const Obstacle<2> &,
                        const TrilinosWrappers::MPI::Vector &,
                        const Reference<2> &);
  template ContactZone<3>
  evaluate_contact_zone(const Discretisation<3> &,
                        const ContactSurface<3> &,
                        const Obstacle<3> &,
                        const TrilinosWrappers::MPI::Vector &,
                        const Reference<3> &);
} // namespace signorini
