#include <deal.II/base/mpi.h>
#include <deal.II/fe/fe_values.h>

#include <signorini/elasticity/cell_stiffness.h>
#include <signorini/postprocessing/balance.h>

namespace signorini
{
  using namespace dealii;

  template <int dim>
  Balance<dim>
  evaluate_balance(const Discretisation<dim>           &discretisation,
                   const Loads<dim>                    &loads,
                   const Material                      &material,
                   const TrilinosWrappers::MPI::Vector &u)
  {
    // Supported dofs carry no constraint entries, hanging ones do. Hanging
    // nodes alone, since closing them with the supports would drop supported
    // masters.
    const auto       &hanging_nodes = discretisation.hanging_node_constraints();
    const auto       &support_dofs  = discretisation.support_dofs();
    const auto       &fe            = discretisation.fe();
    FEValues<dim>     fe_values(discretisation.mapping(),
                            fe,
                            discretisation.quadrature(),
                            update_values | update_gradients |
                              update_quadrature_points | update_JxW_values);
    FEFaceValues<dim> fe_face_values(discretisation.mapping(),
                                     fe,
                                     discretisation.face_quadrature(),
                                     Loads<dim>::update_flags());
    const unsigned int                   n = fe.n_dofs_per_cell();
    Vector<double>                       cell_load(n), internal(n), values(n);
    std::vector<types::global_dof_index> dof_indices(n);

    const auto displacement = discretisation.relevant_copy(u);

    // The internal force K u of a cell by its shape's stiffness matrix
    // where cells share shapes (boxes, straight-sided adaptive meshes:
    // computed once per shape), else at the quadrature points (curved
    // cells, which rarely repeat, and whose vertices do not tell their
    // shape: two cells of one vertex shape may curve apart). At 1.49M dofs
    // in 3D the quadrature points took 1.8 s of a 32 s run on one process.
    CellStiffness<dim> stiffness(material, [&discretisation](const auto &cell) {
      return discretisation.curved(cell);
    });

    Tensor<1, dim> applied, reaction;
    double         energy = 0.;
    for (const auto &cell :
         discretisation.dof_handler().active_cell_iterators())
      if (cell->is_locally_owned())
        {
          cell->get_dof_indices(dof_indices);
          double factor;
          if (const auto *matrix = stiffness.shared(cell, fe_values, factor))
            {
              for (unsigned int i = 0; i < n; ++i)
                values(i) = displacement(dof_indices[i]);
              matrix->vmult(internal, values);
              internal *= factor;
              energy += 0.5 * (values * internal);
            }
          else
            {
              fe_values.reinit(cell);
              energy += cell_internal_force(material,
                                            fe_values,
                                            displacement,
                                            internal);
            }
          if (loads.loaded(cell))
            loads.cell_load(cell, fe_values, fe_face_values, cell_load);
          else
            cell_load = 0.;
          for (unsigned int i = 0; i < n; ++i)
            {
              const unsigned int d = fe.system_to_component_index(i).first;
              applied[d] += cell_load(i);
              energy -= cell_load(i) * displacement(dof_indices[i]);
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
    const MPI_Comm comm = discretisation.mpi_communicator();
    Balance<dim>   balance;
    balance.applied_force    = Utilities::MPI::sum(applied, comm);
    balance.support_reaction = Utilities::MPI::sum(reaction, comm);
    balance.energy           = Utilities::MPI::sum(energy, comm);
    return balance;
  }

  template Balance<2>
  evaluate_balance(const Discretisation<2> &,
                   const Loads<2> &,
                   const Material &,
                   const TrilinosWrappers::MPI::Vector &);
  template Balance<3>
  evaluate_balance(const Discretisation<3> &,
                   const Loads<3> &,
                   const Material &,
                   const TrilinosWrappers::MPI::Vector &);
} // namespace signorini
