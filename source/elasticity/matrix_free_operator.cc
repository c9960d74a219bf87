#include <deal.II/lac/solver_cg.h>
#include <deal.II/lac/solver_control.h>

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
      throw InputError("Linear solver/Type",
                       "matrix-free needs quadrilaterals or hexahedra (Q1); "
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
  MatrixFreeOperator<dim>::setup_contact(
    const ContactLinearisation<dim> &linearisation)
  {
    TimerOutput::Scope t(timer, "Solve: multigrid contact");
    // Held nodes sit on the obstacle: n.u = -gap; closed with the
    // discretisation's constraints as AssembledOperator does.
    constraints.clear();
    constraints.reinit(discretisation.locally_relevant_dofs());
    linearisation.add_held_constraints(constraints);
    std::vector<types::global_dof_index> held_dofs;
    for (const auto &line : constraints.get_lines())
      held_dofs.push_back(line.index);
    constraints.merge(discretisation.constraints(),
                      AffineConstraints<double>::left_object_wins);
    constraints.close();
    local_constraints.reinit(constraints, load_la.get_partitioner());

    const auto &owned = discretisation.locally_owned_dofs();
    std::vector<typename ElasticLevelOperator<dim>::HeldLine> held;
    for (const auto dof : held_dofs)
      if (owned.is_element(dof))
        {
          typename ElasticLevelOperator<dim>::HeldLine line;
          line.dof = dof;
          if (const auto *entries = constraints.get_constraint_entries(dof))
            line.entries = *entries;
          held.push_back(line);
        }

    // The springs k n n^T at their nodes (owned ones); on the coarser
    // levels also the held nodes, as springs as stiff as the fine
    // operator's diagonal there.
    std::vector<typename ElasticLevelOperator<dim>::NodalBlock> blocks;
    LAVector diagonal, off_diagonal;
    fine->initialize_dof_vector(diagonal);
    fine->initialize_dof_vector(off_diagonal);
    const auto add_stiffness = [&](const ContactNode<dim> &node,
                                   const double            k) {
      for (unsigned int a = 0; a < dim; ++a)
        diagonal(node.dofs[a]) += k * node.normal[a] * node.normal[a];
      off_diagonal(node.dofs[0]) += k * node.normal[0] * node.normal[1];
      if (dim == 3)
        {
          off_diagonal(node.dofs[1]) +=
            k * node.normal[1] * node.normal[dim - 1];
          off_diagonal(node.dofs[dim - 1]) +=
            k * node.normal[0] * node.normal[dim - 1];
        }
    };
    if (linearisation.penalised)
      for (const auto &spring : linearisation.springs)
        {
          const auto                                    &node = *spring.node;
          typename ElasticLevelOperator<dim>::NodalBlock block;
          block.dofs = node.dofs;
          for (unsigned int a = 0; a < dim; ++a)
            for (unsigned int b = 0; b < dim; ++b)
              block.stiffness[a][b] =
                spring.stiffness * node.normal[a] * node.normal[b];
          blocks.push_back(block);
          add_stiffness(node, spring.stiffness);
        }
    for (const auto *node : linearisation.held)
      if (node->owned)
        add_stiffness(*node, fine->diagonal()(node->scalar_dof));
    fine->set_contact(held, blocks);
    multigrid.update(diagonal, off_diagonal);
    contact_for   = linearisation.key;
    contact_ready = true;
  }

  template <int dim>
  void
  MatrixFreeOperator<dim>::newton_residual(
    const ContactLinearisation<dim> &linearisation,
    const LAVector                  &u,
    LAVector                        &r) const
  {
    fine->internal_force(r, u);
    r -= load_la;
    // The springs' force (k n.u + rest force - extra force) n on their
    // nodes' free components.
    if (linearisation.penalised)
      for (const auto &spring : linearisation.springs)
        {
          const auto &node = *spring.node;
          double      un   = 0.;
          for (unsigned int b = 0; b < dim; ++b)
            if (node.normal[b] != 0.)
              un += node.normal[b] * u(node.dofs[b]);
          double force = spring.stiffness * un + spring.rest_force;
          if (linearisation.extra_forces)
            force -= spring.extra_force;
          for (unsigned int a = 0; a < dim; ++a)
            if (node.normal[a] != 0. && node.free[a])
              r(node.dofs[a]) += force * node.normal[a];
        }
    else if (linearisation.extra_forces)
      for (const auto &spring : linearisation.springs)
        for (unsigned int a = 0; a < dim; ++a)
          if (spring.node->normal[a] != 0. && spring.node->free[a])
            r(spring.node->dofs[a]) -=
              spring.extra_force * spring.node->normal[a];
    fine->condense(r);
  }

  template <int dim>
  unsigned int
  MatrixFreeOperator<dim>::solve_cg(
    const ContactLinearisation<dim> &linearisation,
    VectorType                      &u,
    const bool                       final_step)
  {
    setup_levels();
    if (!contact_ready || linearisation.key != contact_for)
      setup_contact(linearisation);
    // The previous step's vectors and contact constraints are free by now;
    // returned to the system, they are not resident beside this step's
    // (they were 150 MB of the peak at 1.49M dofs on two processes).
    release_free_memory();

    TimerOutput::Scope t(timer, "Solve: CG");
    // u0: the current displacement with the constraints applied; the
    // right-hand side's norm is that of the system for d = u - G(0).
    // (The lifting and its residual are freed before CG takes its memory.)
    double rhs_norm = 0.;
    {
      LAVector lifting, reference;
      fine->initialize_dof_vector(lifting);
      fine->initialize_dof_vector(reference);
      local_constraints.distribute(lifting);
      newton_residual(linearisation, lifting, reference);
      rhs_norm = reference.l2_norm();
    }
    LAVector u0, rhs, d;
    fine->initialize_dof_vector(u0);
    to_la(u, u0);
    local_constraints.distribute(u0);
    fine->initialize_dof_vector(rhs);
    fine->initialize_dof_vector(d);
    newton_residual(linearisation, u0, rhs);
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
        SolverCG<LAVector>             cg(control);
        const MultigridOnFreeDofs<dim> preconditioner{multigrid, *fine};
        cg.solve(*fine, d, rhs, preconditioner);
      }
    catch (const SolverControl::NoConvergence &failure)
      {
        throw SolverFailure(exit_status::linear_solver,
                            "linear solver (CG with geometric multigrid) did "
                            "not converge in " +
                              std::to_string(failure.last_step) +
                              " iterations (residual " +
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
  MatrixFreeOperator<dim>::solve(const ContactLinearisation<dim> &linearisation,
                                 VectorType                      &u,
                                 const bool                       final_step)
  {
    if (!fallback)
      try
        {
          const unsigned int iterations =
            solve_cg(linearisation, u, final_step);
          // CG's vectors, free now, before the Newton step's residual.
          release_free_memory();
          if (verbose)
            pcout << "   multigrid CG: " << iterations << " iterations, "
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
    fallback->solve(linearisation, u, final_step);
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
