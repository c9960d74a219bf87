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
    Vector<double>                       cell_load(n), internal(n);
    std::vector<types::global_dof_index> dof_indices(n);

    const auto displacement = discretisation.relevant_copy(u);

    Tensor<1, dim> applied, reaction;
    double         energy = 0.;
    for (const auto &cell :
         discretisation.dof_handler().active_cell_iterators())
      if (cell->is_locally_owned())
        {
          loads.cell_load(cell, fe_values, fe_face_values, cell_load);
          energy +=
            cell_internal_force(material, fe_values, displacement, internal);
          cell->get_dof_indices(dof_indices);
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
