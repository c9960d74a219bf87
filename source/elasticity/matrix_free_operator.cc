#include <deal.II/lac/solver_cg.h>
#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/solver_gmres.h>

#include <signorini/base/failures.h>
#include <signorini/base/memory.h>
#include <signorini/base/owned_values.h>
#include <signorini/elasticity/assembled_operator.h>
#include <signorini/elasticity/matrix_free_operator.h>
#include <signorini/input/input_error.h>

#include <algorithm>
#include <cmath>

namespace signorini
{
  using namespace dealii;

  namespace
  {
    /** The multigrid V-cycle as CG's preconditioner, zero at the rows that
     * are the identity (constrained and held dofs). */
    template <int dim>
    struct MultigridOnFreeDofs
    {
      const ElasticMultigrid<dim>     &multigrid;
      const ElasticLevelOperator<dim> &fine;

      void
      vmult(LinearAlgebra::distributed::Vector<double>       &dst,
            const LinearAlgebra::distributed::Vector<double> &src) const
      {
        multigrid.vmult(dst, src);
        for (const unsigned int i : fine.identity_rows())
          dst.local_element(i) = 0.;
      }
    };

    /** The Newton system of the fine level for GMRES, where it is not
     * symmetric (the multigrid smooths with its symmetric part). */
    template <int dim>
    struct NewtonSystem
    {
      const ElasticLevelOperator<dim> &fine;

      void
      vmult(LinearAlgebra::distributed::Vector<double>       &dst,
            const LinearAlgebra::distributed::Vector<double> &src) const
      {
        fine.vmult_newton(dst, src);
      }
    };
  } // namespace

  template <int dim>
  MatrixFreeOperator<dim>::MatrixFreeOperator(
    const Discretisation<dim>     &discretisation,
    const Material                &material,
    const BoundaryConditions<dim> &boundary_conditions,
    Loads<dim>                    &loads,
    const LinearSolverParameters  &parameters,
    const bool                     remedies,
    const bool                     verbose,
    ConditionalOStream            &pcout,
    TimerOutput                   &timer)
    : discretisation(discretisation)
    , material(material)
    , boundary_conditions(boundary_conditions)
    , loads(loads)
    , parameters(parameters)
    , remedies(remedies)
    , verbose(verbose)
    , pcout(pcout)
    , timer(timer)
    , multigrid(material)
  {
  }

  template <int dim>
  MatrixFreeOperator<dim>::~MatrixFreeOperator() = default;

  template <int dim>
  void
  MatrixFreeOperator<dim>::reinit()
  {
    if (discretisation.simplex())
      throw InputError(
        "Linear solver/Type",
        "matrix-free needs quadrilaterals or hexahedra (Q1, Q2); "
        "the mesh has triangles or tetrahedra: use amg cg or "
        "direct");
    release();
    fallback.reset();
    load_vector.reinit(discretisation.locally_owned_dofs(),
                       discretisation.mpi_communicator());
  }

  template <int dim>
  void
  MatrixFreeOperator<dim>::setup_fine()
  {
    if (fine)
      return;
    TimerOutput::Scope t(timer, "Setup: matrix-free operator");
    fine = std::make_shared<ElasticLevelOperator<dim>>(material);
    // Where the operator needs a MatrixFree (curved cells), its reinit()
    // passes through about 1 kB per cell more than it keeps: the pages
    // freed since the last trim go back first, so that its transient does
    // not stand on top of them.
    release_free_memory();
    fine->reinit(discretisation.mapping(),
                 discretisation.dof_handler(),
                 discretisation.constraints());
    fine->initialize_dof_vector(load_la);
    to_la(load_vector, load_la);
  }

  template <int dim>
  void
  MatrixFreeOperator<dim>::setup_levels()
  {
    setup_fine();
    if (!levels_ready)
      {
        TimerOutput::Scope t(timer, "Setup: multigrid levels");
        multigrid.setup(discretisation.mapping(),
                        fine,
                        discretisation.constraints(),
                        boundary_conditions.dirichlet);
        levels_ready  = true;
        contact_ready = false;
        if (verbose)
          {
            pcout << "   multigrid levels (dofs):";
            for (const auto size : multigrid.level_sizes())
              pcout << ' ' << size;
            pcout << std::endl;
          }
      }
  }

  template <int dim>
  void
  MatrixFreeOperator<dim>::assemble_load()
  {
    TimerOutput::Scope t(timer, "Assembly: load");
    loads.assemble(load_vector);
    if (fine)
      to_la(load_vector, load_la);
    if (fallback)
      fallback->assemble_load();
  }

  template <int dim>
  const typename MatrixFreeOperator<dim>::VectorType &
  MatrixFreeOperator<dim>::load() const
  {
    return load_vector;
  }

  template <int dim>
  void
  MatrixFreeOperator<dim>::to_la(const VectorType &in, LAVector &out) const
  {
    copy_owned(in, discretisation.locally_owned_dofs(), out);
  }

  template <int dim>
  void
  MatrixFreeOperator<dim>::from_la(const LAVector &in, VectorType &out) const
  {
    copy_owned(in, discretisation.locally_owned_dofs(), out);
  }

  template <int dim>
  void
  MatrixFreeOperator<dim>::residual(const VectorType &u, VectorType &residual)
  {
    setup_fine();
    TimerOutput::Scope t(timer, "Assembly: residual");
    LAVector           x, force;
    fine->initialize_dof_vector(x);
    fine->initialize_dof_vector(force);
    to_la(u, x);
    fine->internal_force(force, x);
    force -= load_la;
    from_la(force, residual);
  }

  template <int dim>
  void
  MatrixFreeOperator<dim>::setup_contact(const SystemAdditions<dim> &additions)
  {
    TimerOutput::Scope t(timer, "Solve: multigrid contact");
    // The additions' constraint lines, closed with the discretisation's
    // constraints as AssembledOperator does; and with their test weights
    // (a slipping node's lines: the equations' side).
    const auto &relevant = discretisation.locally_relevant_dofs();
    additions.close(constraints, discretisation.constraints(), relevant, false);
    local_constraints.reinit(constraints, load_la.get_partitioner());
    AffineConstraints<double> test_constraints;
    if (additions.has_test_weights)
      additions.close(test_constraints,
                      discretisation.constraints(),
                      relevant,
                      true);

    const auto &owned = discretisation.locally_owned_dofs();
    std::vector<typename ElasticLevelOperator<dim>::HeldLine> held;
    for (const auto &added : additions.constraints)
      if (owned.is_element(added.dof))
        {
          typename ElasticLevelOperator<dim>::HeldLine line;
          line.dof = added.dof;
          if (const auto *entries =
                constraints.get_constraint_entries(added.dof))
            line.entries = *entries;
          if (added.petrov_galerkin)
            if (const auto *entries =
                  test_constraints.get_constraint_entries(added.dof))
              {
                line.petrov_galerkin = true;
                line.test_entries    = *entries;
              }
          held.push_back(line);
        }

    // The blocks at their vertices (owned ones); on the coarser levels
    // their symmetric parts, and the constraint springs as stiff as the
    // fine operator's diagonal there.
    std::vector<typename ElasticLevelOperator<dim>::NodalBlock> blocks;
    LAVector diagonal, off_diagonal;
    fine->initialize_dof_vector(diagonal);
    fine->initialize_dof_vector(off_diagonal);
    const auto add_stiffness =
      [&](const std::array<types::global_dof_index, dim> &dofs,
          const auto                                     &entry) {
        for (unsigned int a = 0; a < dim; ++a)
          diagonal(dofs[a]) += entry(a, a);
        off_diagonal(dofs[0]) += entry(0, 1);
        if (dim == 3)
          {
            off_diagonal(dofs[1]) += entry(1, dim - 1);
            off_diagonal(dofs[dim - 1]) += entry(0, dim - 1);
          }
      };
    if (additions.has_blocks)
      for (const auto &block : additions.blocks)
        {
          if (block.rows != block.columns)
            throw SolverFailure(exit_status::linear_solver,
                                "the matrix-free operator adds blocks at one "
                                "vertex only, not between two: use Linear "
                                "solver/Type = amg cg or direct");
          typename ElasticLevelOperator<dim>::NodalBlock nodal;
          nodal.dofs      = block.rows;
          nodal.stiffness = block.matrix;
          blocks.push_back(nodal);
          add_stiffness(block.rows,
                        [&](const unsigned int a, const unsigned int b) {
                          return a == b || additions.symmetric ?
                                   block.matrix[a][b] :
                                   0.5 *
                                     (block.matrix[a][b] + block.matrix[b][a]);
                        });
        }
    for (const auto &spring : additions.constraint_springs)
      {
        const double k = fine->diagonal()(spring.scale_dof);
        const auto  &d = spring.direction;
        add_stiffness(spring.dofs,
                      [&](const unsigned int a, const unsigned int b) {
                        return k * d[a] * d[b];
                      });
      }
    fine->set_contact(held, blocks);
    multigrid.update(diagonal, off_diagonal, constraints);
    contact_for   = additions.key;
    contact_ready = true;
  }

  template <int dim>
  void
  MatrixFreeOperator<dim>::newton_residual(
    const SystemAdditions<dim> &additions,
    const LAVector             &u,
    LAVector                   &r) const
  {
    fine->internal_force(r, u);
    r -= load_la;
    // The blocks' force M u - rhs, and the forces, on the rows that are
    // not constrained (condense() zeroes the others, after moving a held
    // row's force to its masters with its test weights).
    if (additions.has_blocks)
      for (const auto &block : additions.blocks)
        for (unsigned int a = 0; a < dim; ++a)
          {
            double force = -block.rhs[a];
            for (unsigned int b = 0; b < dim; ++b)
              if (block.matrix[a][b] != 0.)
                force += block.matrix[a][b] * u(block.columns[b]);
            if (force != 0.)
              r(block.rows[a]) += force;
          }
    if (additions.has_forces)
      for (const auto &force : additions.forces)
        r(force.dof) -= force.value;
    fine->condense(r);
  }

  template <int dim>
  unsigned int
  MatrixFreeOperator<dim>::solve_iterative(
    const SystemAdditions<dim> &additions,
    VectorType                 &u,
    const bool                  final_step)
  {
    setup_levels();
    if (!contact_ready || additions.key != contact_for)
      setup_contact(additions);
    // The previous step's vectors and contact constraints are free by now;
    // returned to the system, they are not resident beside this step's
    // (they were 150 MB of the peak at 1.49M dofs on two processes).
    release_free_memory();

    TimerOutput::Scope t(timer,
                         additions.symmetric ? "Solve: CG" : "Solve: GMRES");
    // u0: the current displacement with the constraints applied; the
    // right-hand side's norm is that of the system for d = u - G(0).
    // (The lifting and its residual are freed before CG takes its memory.)
    double rhs_norm = 0.;
    {
      LAVector lifting, reference;
      fine->initialize_dof_vector(lifting);
      fine->initialize_dof_vector(reference);
      local_constraints.distribute(lifting);
      newton_residual(additions, lifting, reference);
      rhs_norm = reference.l2_norm();
    }
    LAVector u0, rhs, d;
    fine->initialize_dof_vector(u0);
    to_la(u, u0);
    local_constraints.distribute(u0);
    fine->initialize_dof_vector(rhs);
    fine->initialize_dof_vector(d);
    newton_residual(additions, u0, rhs);
    rhs *= -1.;

    const double relative =
      final_step ? parameters.tolerance : parameters.newton_tolerance;
    double tolerance = relative * rhs_norm;
    if (relative > parameters.tolerance)
      tolerance = std::max(parameters.tolerance * rhs_norm,
                           std::min(tolerance, 0.1 * rhs.l2_norm()));
    SolverControl control(parameters.max_iterations, tolerance);
    try
      {
        const MultigridOnFreeDofs<dim> preconditioner{multigrid, *fine};
        if (additions.symmetric)
          {
            SolverCG<LAVector> cg(control);
            cg.solve(*fine, d, rhs, preconditioner);
          }
        else
          {
            SolverGMRES<LAVector> gmres(control, gmres_data<LAVector>());
            gmres.solve(NewtonSystem<dim>{*fine}, d, rhs, preconditioner);
          }
      }
    catch (const SolverControl::NoConvergence &failure)
      {
        throw SolverFailure(exit_status::linear_solver,
                            std::string("linear solver (") +
                              (additions.symmetric ? "CG" : "GMRES") +
                              " with geometric multigrid) did not converge "
                              "in " +
                              std::to_string(failure.last_step) +
                              " iterations (Linear solver/Maximum iterations; "
                              "residual " +
                              std::to_string(failure.last_residual) + ")");
      }
    d += u0;
    local_constraints.distribute(d);
    const MPI_Comm comm = discretisation.mpi_communicator();
    VectorType     result(discretisation.locally_owned_dofs(), comm);
    from_la(d, result);
    u = result;
    return control.last_step();
  }

  template <int dim>
  void
  MatrixFreeOperator<dim>::solve(const SystemAdditions<dim> &additions,
                                 VectorType                 &u,
                                 const bool                  final_step)
  {
    if (!fallback)
      try
        {
          const unsigned int iterations =
            solve_iterative(additions, u, final_step);
          // The solver's vectors, free now, before the Newton step's
          // residual.
          release_free_memory();
          if (verbose)
            pcout << "   multigrid " << (additions.symmetric ? "CG" : "GMRES")
                  << ": " << iterations << " iterations, "
                  << multigrid.n_levels() << " levels" << std::endl;
          return;
        }
      catch (const SolverFailure &failure)
        {
          if (!remedies)
            throw;
          pcout << "   remedy: " << failure.what()
                << "; solved by the assembled operator instead, on this mesh"
                << std::endl;
          release();
          fallback = std::make_unique<AssembledOperator<dim>>(discretisation,
                                                              material,
                                                              loads,
                                                              parameters,
                                                              remedies,
                                                              pcout,
                                                              timer);
          fallback->reinit();
          fallback->assemble_load();
        }
    fallback->solve(additions, u, final_step);
  }

  template <int dim>
  void
  MatrixFreeOperator<dim>::forget_operator()
  {
    multigrid.clear();
    local_constraints.clear();
    if (fine)
      fine->clear();
    fine.reset();
    levels_ready  = false;
    contact_ready = false;
  }

  template <int dim>
  void
  MatrixFreeOperator<dim>::invalidate()
  {
    // The operator of this mesh, its levels and their contact are built
    // anew by the next solve, as the assembled operator assembles anew.
    forget_operator();
    if (fallback)
      fallback->invalidate();
  }

  template <int dim>
  void
  MatrixFreeOperator<dim>::release()
  {
    forget_operator();
    load_la.reinit(0);
    if (fallback)
      fallback->release();
    release_free_memory();
  }

  template class MatrixFreeOperator<2>;
  template class MatrixFreeOperator<3>;
} // namespace signorini
