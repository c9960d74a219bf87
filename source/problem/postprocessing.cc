#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_values.h>

#include <signorini/output/file_output.h>
#include <signorini/problem/contact_problem.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <optional>

namespace signorini
{
  using namespace dealii;

  template <int dim>
  void
  ContactProblem<dim>::evaluate_contact_zone(CycleStatistics<dim> &row) const
  {
    // The contact zone: the active nodes (touching for the active set,
    // penetrating for the penalty method).
    const bool contact =
      parameters.contact.method != ContactParameters::Method::none;
    double max_pressure = -std::numeric_limits<double>::max();
    double x_min = std::numeric_limits<double>::max(), x_max = -x_min;
    for (const auto &node : contact_nodes)
      if (node.owned)
        {
          max_pressure = std::max(max_pressure, pressure(node.dofs[dim - 1]));
          if (contact && node.active)
            {
              x_min = std::min(x_min, node.position[0]);
              x_max = std::max(x_max, node.position[0]);
            }
        }
    max_pressure = Utilities::MPI::max(max_pressure, mpi_communicator);
    row.max_pressure =
      max_pressure == -std::numeric_limits<double>::max() ? 0. : max_pressure;
    x_min                     = Utilities::MPI::min(x_min, mpi_communicator);
    x_max                     = Utilities::MPI::max(x_max, mpi_communicator);
    row.contact_width         = x_max >= x_min ? x_max - x_min : 0.;
    const auto relative_error = [](const double                 value,
                                   const std::optional<double> &reference) {
      if (!reference)
        return std::numeric_limits<double>::quiet_NaN();
      return std::abs(value - *reference) /
             (*reference != 0 ? std::abs(*reference) : 1.);
    };
    row.max_pressure_error =
      relative_error(row.max_pressure, parameters.reference.max_pressure);
    row.contact_width_error =
      relative_error(row.contact_width, parameters.reference.contact_width);

    // The pressure field on the contact boundary interpolates the nodal
    // pressures; a hanging node takes the pressure its masters give it, a
    // supported one none. Integrated with a Gauss rule of high order, since
    // a closed-form pressure has a square-root edge.
    const auto          &ids   = parameters.obstacle.contact_ids;
    const Function<dim> *exact = parameters.reference.contact_pressure.get();
    const Quadrature<dim - 1> rule =
      simplex && dim == 3 ? Quadrature<dim - 1>(QGaussSimplex<dim - 1>(4)) :
                            Quadrature<dim - 1>(QGauss<dim - 1>(6));
    FEFaceValues<dim>                    fe_face_values(*mapping,
                                     *fe,
                                     rule,
                                     update_values | update_quadrature_points |
                                       update_JxW_values);
    const unsigned int                   n = fe->n_dofs_per_cell();
    std::vector<types::global_dof_index> dof_indices(n);
    std::vector<double>                  nodal(n);
    const auto nodal_pressure = [&](const types::global_dof_index i) {
      if (!fixed_constraints.is_constrained(i))
        return pressure(i);
      double value = 0.;
      if (const auto *entries = fixed_constraints.get_constraint_entries(i))
        for (const auto &[master, weight] : *entries)
          value += weight * pressure(master);
      return value;
    };

    double integral = 0., error_squared = 0., norm_squared = 0.;
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        for (const unsigned int f : cell->face_indices())
          if (cell->face(f)->at_boundary() &&
              ids.count(cell->face(f)->boundary_id()))
            {
              fe_face_values.reinit(cell, f);
              cell->get_dof_indices(dof_indices);
              for (unsigned int i = 0; i < n; ++i)
                nodal[i] = fe->system_to_component_index(i).first == dim - 1 ?
                             nodal_pressure(dof_indices[i]) :
                             0.;
              for (const unsigned int q :
                   fe_face_values.quadrature_point_indices())
                {
                  double p_h = 0.;
                  for (unsigned int i = 0; i < n; ++i)
                    p_h += nodal[i] * fe_face_values.shape_value(i, q);
                  const double JxW = fe_face_values.JxW(q);
                  integral += p_h * JxW;
                  if (exact)
                    {
                      const double p =
                        exact->value(fe_face_values.quadrature_point(q));
                      error_squared += (p_h - p) * (p_h - p) * JxW;
                      norm_squared += p * p * JxW;
                    }
                }
            }
    row.integrated_pressure = Utilities::MPI::sum(integral, mpi_communicator);
    row.pressure_error      = std::numeric_limits<double>::quiet_NaN();
    if (exact)
      {
        error_squared = Utilities::MPI::sum(error_squared, mpi_communicator);
        norm_squared  = Utilities::MPI::sum(norm_squared, mpi_communicator);
        row.pressure_error = norm_squared > 0 ?
                               std::sqrt(error_squared / norm_squared) :
                               std::sqrt(error_squared);
      }
  }

  template <int dim>
  void
  ContactProblem<dim>::evaluate_balance_and_energy(
    CycleStatistics<dim> &row) const
  {
    // Cell by cell, with the unconstrained cell matrices: the internal
    // force K u, the load f, their difference at the supported dofs (the
    // support reaction), and the energy 1/2 u.K u - f.u. Supported dofs
    // carry no constraint entries, hanging ones do. Hanging nodes alone,
    // since closing them with the supports would drop supported masters.
    AffineConstraints<double> hanging_nodes(locally_relevant_dofs);
    DoFTools::make_hanging_node_constraints(dof_handler, hanging_nodes);
    hanging_nodes.close();
    FEValues<dim>                        fe_values(*mapping,
                            *fe,
                            quadrature,
                            update_values | update_gradients |
                              update_quadrature_points | update_JxW_values);
    FEFaceValues<dim>                    fe_face_values(*mapping,
                                     *fe,
                                     face_quadrature,
                                     update_values | update_quadrature_points |
                                       update_JxW_values);
    const unsigned int                   n = fe->n_dofs_per_cell();
    Vector<double>                       cell_load(n), internal(n);
    std::vector<types::global_dof_index> dof_indices(n);

    Tensor<1, dim> applied, reaction;
    double         energy = 0.;
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          assemble_cell_load(cell, fe_values, fe_face_values, cell_load);
          energy += assemble_cell_internal_force(fe_values, internal);
          cell->get_dof_indices(dof_indices);
          for (unsigned int i = 0; i < n; ++i)
            {
              const unsigned int d = fe->system_to_component_index(i).first;
              applied[d] += cell_load(i);
              energy -= cell_load(i) * solution(dof_indices[i]);
              // A hanging node's force goes to its masters, some of which
              // may be supported even if it is not.
              const double force = internal(i) - cell_load(i);
              const auto  *masters =
                hanging_nodes.get_constraint_entries(dof_indices[i]);
              if (masters && !masters->empty())
                {
                  for (const auto &[master, weight] : *masters)
                    if (support_dofs.is_element(master))
                      reaction[d] += weight * force;
                }
              else if (support_dofs.is_element(dof_indices[i]))
                reaction[d] += force;
            }
        }
    row.applied_force    = Utilities::MPI::sum(applied, mpi_communicator);
    row.support_reaction = Utilities::MPI::sum(reaction, mpi_communicator);
    row.energy           = Utilities::MPI::sum(energy, mpi_communicator);

    // The obstacle pushes up (along +y in 2D, +z in 3D).
    Tensor<1, dim> balance = row.applied_force + row.support_reaction;
    balance[dim - 1] += row.integrated_pressure;
    const double scale    = row.applied_force.norm();
    row.equilibrium_error = scale > 0 ? balance.norm() / scale : balance.norm();

    row.energy_error = std::numeric_limits<double>::quiet_NaN();
    if (const auto &reference = parameters.reference.energy)
      row.energy_error =
        std::sqrt(std::abs(row.energy - *reference) /
                  (*reference != 0 ? std::abs(*reference) : 1.));
  }

  template <int dim>
  void
  ContactProblem<dim>::write_contact_pressure_table(
    const unsigned int cycle) const
  {
    // One row per contact node, gathered on process 0 and sorted by x.
    std::vector<std::array<double, dim + 1>> rows;
    for (const auto &node : contact_nodes)
      if (node.owned)
        {
          std::array<double, dim + 1> row;
          for (unsigned int d = 0; d < dim - 1; ++d)
            row[d] = node.position[d];
          row[dim - 1] = pressure(node.dofs[dim - 1]);
          row[dim]     = deformed_gap(node);
          rows.push_back(row);
        }
    const auto gathered = Utilities::MPI::gather(mpi_communicator, rows);
    if (Utilities::MPI::this_mpi_process(mpi_communicator) != 0)
      return;
    std::vector<std::array<double, dim + 1>> all;
    for (const auto &part : gathered)
      all.insert(all.end(), part.begin(), part.end());
    std::sort(all.begin(), all.end());

    const std::string name = parameters.output.directory +
                             "/contact_pressure-" +
                             Utilities::int_to_string(cycle, 2) + ".csv";
    write_atomically(name, [&](std::ostream &out) {
      out << (dim == 2 ? "x" : "x,y") << ",pressure,gap\n";
      char number[32];
      for (const auto &row : all)
        {
          for (unsigned int c = 0; c <= dim; ++c)
            {
              std::snprintf(number, sizeof(number), "%.10e", row[c]);
              out << (c > 0 ? "," : "") << number;
            }
          out << '\n';
        }
    });
  }

  template void
  ContactProblem<2>::evaluate_contact_zone(CycleStatistics<2> &) const;
  template void
  ContactProblem<3>::evaluate_contact_zone(CycleStatistics<3> &) const;
  template void
  ContactProblem<2>::evaluate_balance_and_energy(CycleStatistics<2> &) const;
  template void
  ContactProblem<3>::evaluate_balance_and_energy(CycleStatistics<3> &) const;
  template void
  ContactProblem<2>::write_contact_pressure_table(unsigned int) const;
  template void
  ContactProblem<3>::write_contact_pressure_table(unsigned int) const;
} // namespace signorini
