#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/sparse_direct.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/vector.h>

#include <signorini/postprocessing/pressure_recovery.h>

#include <map>
#include <vector>

namespace signorini
{
  using namespace dealii;

  template <int dim>
  TrilinosWrappers::MPI::Vector
  recover_pressure(const Discretisation<dim>           &discretisation,
                   const ContactSurface<dim>           &surface,
                   const TrilinosWrappers::MPI::Vector &pressure)
  {
    if (discretisation.degree() == 1)
      return pressure;
    const MPI_Comm comm = discretisation.mpi_communicator();

    // The nodes that take part, by the dof of their first component: (dof,
    // nodal force) of the owned ones, gathered.
    std::vector<double> owned_forces;
    for (const auto &node : surface.nodes())
      if (node.owned && node.primary &&
          node.corner == numbers::invalid_unsigned_int)
        {
          owned_forces.push_back(node.dofs[0]);
          owned_forces.push_back(pressure(node.scalar_dof) * node.mass);
        }
    std::map<types::global_dof_index, unsigned int> index;
    std::vector<double>                             force;
    for (const auto &part : Utilities::MPI::all_gather(comm, owned_forces))
      for (std::size_t i = 0; i + 2 <= part.size(); i += 2)
        {
          index.emplace(static_cast<types::global_dof_index>(part[i]),
                        force.size());
          force.push_back(part[i + 1]);
        }
    const unsigned int n = force.size();
    if (n == 0)
      return pressure;

    // The boundary mass matrix of the owned cells' contact faces, (row dof,
    // column dof, value) each, the hanging nodes condensed: by the rule with
    // which evaluate_contact_zone() integrates the pressure, so that its
    // integral is the sum of the nodal forces to round-off on curved faces
    // too (the face rule of degree 2 left 3e-5 of the Hertz load).
    const auto        &fe       = discretisation.fe();
    const auto        &base     = fe.base_element(0);
    const auto        &hanging  = discretisation.hanging_node_constraints();
    const unsigned int n_points = base.n_dofs_per_cell();
    FEFaceValues<dim>  fe_face_values(discretisation.mapping(),
                                     fe,
                                     discretisation.fine_face_quadrature(),
                                     update_values | update_JxW_values |
                                       discretisation.weight_flags());
    std::vector<types::global_dof_index> cell_dofs(fe.n_dofs_per_cell());
    std::vector<double>                  owned_entries;
    // A dof as the nodes it stands for, with weights.
    const auto masters = [&](const types::global_dof_index dof) {
      std::vector<std::pair<types::global_dof_index, double>> to;
      if (const auto *line = hanging.get_constraint_entries(dof))
        to.assign(line->begin(), line->end());
      else
        to.emplace_back(dof, 1.);
      return to;
    };
    surface.for_each_owned_face(
      discretisation, [&](const auto &cell, const unsigned int f) {
        fe_face_values.reinit(cell, f);
        cell->get_dof_indices(cell_dofs);
        std::vector<unsigned int> on_face;
        for (unsigned int b = 0; b < n_points; ++b)
          if (fe.has_support_on_face(fe.component_to_system_index(0, b), f))
            on_face.push_back(fe.component_to_system_index(0, b));
        for (const unsigned int i : on_face)
          for (const unsigned int j : on_face)
            {
              double m = 0.;
              for (const unsigned int q :
                   fe_face_values.quadrature_point_indices())
                m += fe_face_values.shape_value(i, q) *
                     fe_face_values.shape_value(j, q) * fe_face_values.JxW(q) *
                     discretisation.weight(fe_face_values, q);
              for (const auto &[row, a] : masters(cell_dofs[i]))
                for (const auto &[column, b] : masters(cell_dofs[j]))
                  {
                    owned_entries.push_back(row);
                    owned_entries.push_back(column);
                    owned_entries.push_back(a * b * m);
                  }
            }
      });

    // Gathered on every process, restricted to the nodes that take part.
    std::vector<std::map<unsigned int, double>> rows(n);
    for (const auto &part : Utilities::MPI::all_gather(comm, owned_entries))
      for (std::size_t k = 0; k + 3 <= part.size(); k += 3)
        {
          const auto i =
            index.find(static_cast<types::global_dof_index>(part[k]));
          const auto j =
            index.find(static_cast<types::global_dof_index>(part[k + 1]));
          if (i != index.end() && j != index.end())
            rows[i->second][j->second] += part[k + 2];
        }
    DynamicSparsityPattern pattern(n, n);
    for (unsigned int i = 0; i < n; ++i)
      {
        pattern.add(i, i);
        for (const auto &[j, value] : rows[i])
          pattern.add(i, j);
      }
    SparsityPattern sparsity;
    sparsity.copy_from(pattern);
    SparseMatrix<double> mass(sparsity);
    Vector<double>       rhs(n), recovered(n);
    for (unsigned int i = 0; i < n; ++i)
      {
        for (const auto &[j, value] : rows[i])
          mass.add(i, j, value);
        rhs(i) = force[i];
      }
    SparseDirectUMFPACK factorisation;
    factorisation.initialize(mass);
    factorisation.vmult(recovered, rhs);

    TrilinosWrappers::MPI::Vector owned(discretisation.locally_owned_dofs(),
                                        comm);
    // The pressure is zero but at the nodes' scalar dofs.
    for (const auto &node : surface.nodes())
      if (node.owned)
        owned(node.scalar_dof) =
          node.primary && node.corner == numbers::invalid_unsigned_int ?
            recovered(index.at(node.dofs[0])) :
            pressure(node.scalar_dof);
    owned.compress(VectorOperation::insert);
    TrilinosWrappers::MPI::Vector result(pressure);
    result = owned;
    return result;
  }

  template TrilinosWrappers::MPI::Vector
  recover_pressure(const Discretisation<2> &,
                   const ContactSurface<2> &,
                   const TrilinosWrappers::MPI::Vector &);
  template TrilinosWrappers::MPI::Vector
  recover_pressure(const Discretisation<3> &,
                   const ContactSurface<3> &,
                   const TrilinosWrappers::MPI::Vector &);
} // namespace signorini
