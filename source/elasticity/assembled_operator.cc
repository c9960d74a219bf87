#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/lac/trilinos_sparsity_pattern.h>

#include <signorini/base/memory.h>
#include <signorini/elasticity/assembled_operator.h>

#include <cmath>

namespace signorini
{
  using namespace dealii;

  template <int dim>
  AssembledOperator<dim>::AssembledOperator(
    const Discretisation<dim>    &discretisation,
    const Material               &material,
    Loads<dim>                   &loads,
    const LinearSolverParameters &parameters,
    const bool                    remedies,
    ConditionalOStream           &pcout,
    TimerOutput                  &timer)
    : discretisation(discretisation)
    , loads(loads)
    , parameters(parameters)
    , timer(timer)
    , cell_stiffness(material,
                     [&discretisation](const auto &cell) {
                       return discretisation.curved(cell);
                     })
    , material(material)
    , linear_system_solver(parameters, remedies, pcout, timer)
  {
  }

  template <int dim>
  void
  AssembledOperator<dim>::reinit()
  {
    const auto    &owned_dofs = discretisation.locally_owned_dofs();
    const MPI_Comm comm       = discretisation.mpi_communicator();
    TrilinosWrappers::SparsityPattern sparsity(
      owned_dofs, owned_dofs, discretisation.locally_relevant_dofs(), comm);
    DoFTools::make_sparsity_pattern(discretisation.dof_handler(),
                                    sparsity,
                                    discretisation.constraints(),
                                    false,
                                    Utilities::MPI::this_mpi_process(comm));
    sparsity.compress();
    // The pattern's construction left much of the heap free.
    release_free_memory();
    // The solver's factorisation refers to the old matrix: drop it first.
    linear_system_solver.reset();
    system_matrix.reinit(sparsity);
    cell_stiffness.clear();
    matrix_assembled = false;
    sparsity.clear();

    system_rhs.reinit(owned_dofs, comm);
    base_rhs.reinit(owned_dofs, comm);
    load_vector.reinit(owned_dofs, comm);
  }

  template <int dim>
  void
  AssembledOperator<dim>::assemble_load()
  {
    TimerOutput::Scope t(timer, "Assembly: load");
    loads.assemble(load_vector);
  }

  template <int dim>
  const typename AssembledOperator<dim>::VectorType &
  AssembledOperator<dim>::load() const
  {
    return load_vector;
  }

  template <int dim>
  void
  AssembledOperator<dim>::residual(const VectorType &u, VectorType &residual)
  {
    TimerOutput::Scope t(timer, "Assembly: residual");
    residual                                = 0;
    const auto                          &fe = discretisation.fe();
    FEValues<dim>                        fe_values(discretisation.mapping(),
                            fe,
                            discretisation.quadrature(),
                            elastic_update_flags(material));
    const unsigned int                   n = fe.n_dofs_per_cell();
    Vector<double>                       cell_residual(n), cell_solution(n);
    std::vector<types::global_dof_index> dof_indices(n);

    for (const auto &cell :
         discretisation.dof_handler().active_cell_iterators())
      if (cell->is_locally_owned())
        {
          // The internal force K_cell u_cell; from the stresses where the
          // cell's matrix is not cached (curved meshes), which costs an
          // eighth of computing the matrix in 3D.
          if (const auto *matrix = cell_stiffness.cached(cell))
            {
              cell->get_dof_values(u, cell_solution);
              matrix->vmult(cell_residual, cell_solution);
            }
          else
            {
              fe_values.reinit(cell);
              cell_internal_force(material, fe_values, u, cell_residual);
            }
          cell->get_dof_indices(dof_indices);
          discretisation.constraints().distribute_local_to_global(cell_residual,
                                                                  dof_indices,
                                                                  residual);
        }
    residual.compress(VectorOperation::add);
    residual -= load_vector;
  }

  template <int dim>
  void
  AssembledOperator<dim>::assemble_newton_system(
    const SystemAdditions<dim> &additions)
  {
    TimerOutput::Scope t(timer, "Assembly: Newton system");
    const auto        &key = additions.key;
    if (!matrix_assembled || key != assembled_for)
      {
        linear_system_solver.matrix_changed(matrix_assembled &&
                                            additions.local_changes &&
                                            key.second == assembled_for.second);
        // The additions' constraint lines win over the discretisation's.
        const auto &relevant = discretisation.locally_relevant_dofs();
        additions.close(constraints,
                        discretisation.constraints(),
                        relevant,
                        false);
        test_constraints.clear();
        if (additions.has_test_weights)
          additions.close(test_constraints,
                          discretisation.constraints(),
                          relevant,
                          true);
        assemble_matrix(additions);
        base_rhs         = system_rhs;
        assembled_for    = key;
        matrix_assembled = true;
      }
    else
      system_rhs = base_rhs;

    if (additions.has_forces)
      {
        // Every process ends the copy's insertion together: the first
        // addition after an insertion makes a Trilinos vector assemble
        // (collectively) where it is made, and a process without forces
        // makes none (the augmented Lagrangian on two processes hung).
        system_rhs.compress(VectorOperation::insert);
        for (const auto &force : additions.forces)
          if (!constraints.is_constrained(force.dof))
            system_rhs(force.dof) += force.value;
        system_rhs.compress(VectorOperation::add);
      }
  }

  template <int dim>
  void
  AssembledOperator<dim>::assemble_matrix(const SystemAdditions<dim> &additions)
  {
    system_matrix         = 0;
    system_rhs            = 0;
    const auto        &fe = discretisation.fe();
    FEValues<dim>      fe_values(discretisation.mapping(),
                            fe,
                            discretisation.quadrature(),
                            elastic_update_flags(material));
    const unsigned int n = fe.n_dofs_per_cell();
    // The right-hand side gets only the lifting of inhomogeneous
    // constraints here; the load vector is added below.
    Vector<double>                       cell_rhs(n), cell_lifted(n);
    std::vector<types::global_dof_index> dof_indices(n);
    const bool petrov_galerkin = additions.has_test_weights;

    for (const auto &cell :
         discretisation.dof_handler().active_cell_iterators())
      if (cell->is_locally_owned())
        {
          const auto &cell_matrix = cell_stiffness.matrix(cell, fe_values);
          cell->get_dof_indices(dof_indices);
          if (!petrov_galerkin)
            constraints.distribute_local_to_global(
              cell_matrix, cell_rhs, dof_indices, system_matrix, system_rhs);
          else
            add_petrov_galerkin(cell_matrix, dof_indices, cell_lifted);
        }
    system_matrix.compress(VectorOperation::add);
    system_rhs.compress(VectorOperation::add);
    system_rhs += load_vector;
    // The load at a dof that an added constraint line solves for goes to
    // the dofs it depends on (as distribute_local_to_global puts a cell's
    // load): along the obstacle's surface it moves the node.
    const auto &equations = petrov_galerkin ? test_constraints : constraints;
    for (const auto &line : additions.constraints)
      if (const auto dof = line.dof;
          discretisation.locally_owned_dofs().is_element(dof))
        if (const auto *entries = equations.get_constraint_entries(dof))
          if (!entries->empty())
            {
              for (const auto &[other, weight] : *entries)
                system_rhs(other) += weight * load_vector(dof);
              system_rhs(dof) -= load_vector(dof);
            }
    system_rhs.compress(VectorOperation::add);

    if (additions.has_blocks)
      {
        // On the rows that are not constrained; a column at a fixed dof
        // moves its share to the right-hand side.
        for (const auto &block : additions.blocks)
          for (unsigned int a = 0; a < dim; ++a)
            if (!constraints.is_constrained(block.rows[a]))
              {
                for (unsigned int b = 0; b < dim; ++b)
                  if (const double value = block.matrix[a][b]; value != 0.)
                    {
                      const auto column = block.columns[b];
                      if (!constraints.is_constrained(column))
                        system_matrix.add(block.rows[a], column, value);
                      else
                        {
                          // x_column = sum w x_master + g.
                          for (const auto &[master, weight] :
                               *constraints.get_constraint_entries(column))
                            system_matrix.add(block.rows[a],
                                              master,
                                              value * weight);
                          system_rhs(block.rows[a]) -=
                            value * constraints.get_inhomogeneity(column);
                        }
                    }
                if (block.rhs[a] != 0.)
                  system_rhs(block.rows[a]) += block.rhs[a];
              }
        system_matrix.compress(VectorOperation::add);
        system_rhs.compress(VectorOperation::add);
      }
  }

  template <int dim>
  void
  AssembledOperator<dim>::add_petrov_galerkin(
    const FullMatrix<double>                   &cell_matrix,
    const std::vector<types::global_dof_index> &dof_indices,
    Vector<double>                             &cell_lifted)
  {
    // Q^T K P: the rows by the test weights, the columns by the lines';
    // the lifting -K g of the inhomogeneities g by the test weights too;
    // a constrained row gets its diagonal (its value comes from
    // distribute()).
    test_constraints.distribute_local_to_global(
      cell_matrix, dof_indices, constraints, dof_indices, system_matrix);
    const unsigned int n       = dof_indices.size();
    bool               lifting = false;
    for (unsigned int j = 0; j < n; ++j)
      if (constraints.is_constrained(dof_indices[j]))
        {
          system_matrix.add(dof_indices[j], dof_indices[j], cell_matrix(j, j));
          lifting = lifting ||
                    constraints.is_inhomogeneously_constrained(dof_indices[j]);
        }
    if (!lifting)
      return;
    cell_lifted = 0.;
    for (unsigned int j = 0; j < n; ++j)
      if (const double g = constraints.is_constrained(dof_indices[j]) ?
                             constraints.get_inhomogeneity(dof_indices[j]) :
                             0.;
          g != 0.)
        for (unsigned int i = 0; i < n; ++i)
          cell_lifted(i) -= cell_matrix(i, j) * g;
    test_constraints.distribute_local_to_global(cell_lifted,
                                                dof_indices,
                                                system_rhs);
  }

  template <int dim>
  void
  AssembledOperator<dim>::solve(const SystemAdditions<dim> &additions,
                                VectorType                 &u,
                                const bool                  final_step)
  {
    assemble_newton_system(additions);
    VectorType distributed(discretisation.locally_owned_dofs(),
                           discretisation.mpi_communicator());
    distributed = u; // a warm start for the iterative solver
    constraints.set_zero(distributed);
    linear_system_solver.solve(system_matrix,
                               distributed,
                               system_rhs,
                               discretisation.fe().n_components(),
                               final_step ? parameters.tolerance :
                                            parameters.newton_tolerance,
                               additions.symmetric);
    constraints.distribute(distributed);
    u = distributed;
  }

  template <int dim>
  void
  AssembledOperator<dim>::invalidate()
  {
    matrix_assembled = false;
  }

  template <int dim>
  void
  AssembledOperator<dim>::release()
  {
    linear_system_solver.reset();
    system_matrix.clear();
    matrix_assembled = false;
    release_free_memory();
  }

  template class AssembledOperator<2>;
  template class AssembledOperator<3>;
} // namespace signorini
