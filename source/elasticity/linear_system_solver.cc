#include <deal.II/base/mpi.h>
#include <deal.II/lac/solver_cg.h>
#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/solver_gmres.h>

#include <signorini/base/failures.h>
#include <signorini/base/memory.h>
#include <signorini/elasticity/direct_solver_status.h>
#include <signorini/elasticity/linear_system_solver.h>

#include <Amesos.h>
#include <Amesos_BaseSolver.h>
#include <Epetra_LinearProblem.h>
#include <Epetra_MultiVector.h>
#include <Teuchos_ParameterList.hpp>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <sstream>

namespace signorini
{
  using namespace dealii;

  namespace
  {
    const char *singular = "linear solver failed: the system is singular or "
                           "the solver broke down";

    /**
     * Runs @p phase of the direct solver @p solver (a symbolic or numeric
     * factorisation, a solve) with its messages on standard error held
     * back (Amesos' MUMPS prints its failures there and returns success),
     * and throws what failed: OutOfMemory where MUMPS lacked memory, else
     * a SolverFailure.
     */
    template <typename Phase>
    void
    run_direct_phase(Amesos_BaseSolver &solver, const Phase &phase)
    {
      std::ostringstream held;
      std::streambuf    *error_stream = std::cerr.rdbuf(held.rdbuf());
      int                result       = 0;
      try
        {
          result = phase();
        }
      catch (...)
        {
          std::cerr.rdbuf(error_stream);
          throw;
        }
      std::cerr.rdbuf(error_stream);
      const auto status = direct_solver_status(solver);
      if (status.out_of_memory())
        throw OutOfMemory(status.text());
      if (status.error != 0)
        throw SolverFailure(exit_status::linear_solver,
                            "linear solver failed: " + status.text());
      if (result != 0)
        throw SolverFailure(exit_status::linear_solver, singular);
    }

    /** The digits by which CG reduced the residual, at least one. */
    double
    digits(const SolverControl &control)
    {
      if (!(control.initial_value() > 0) || !(control.last_value() > 0))
        return 1.;
      return std::max(1.,
                      std::log10(control.initial_value() /
                                 control.last_value()));
    }
  } // namespace

  LinearSystemSolver::LinearSystemSolver(
    const LinearSolverParameters &parameters,
    const bool                    remedies,
    ConditionalOStream           &pcout,
    TimerOutput                  &timer)
    : parameters(parameters)
    , remedies(remedies)
    , pcout(pcout)
    , timer(timer)
  {
  }

  LinearSystemSolver::~LinearSystemSolver() = default;

  void
  LinearSystemSolver::reset()
  {
    direct.reset();
    problem.reset();
    factorised = false;
    amg.reset();
    amg_stale   = false;
    rebuild_amg = false;
  }

  void
  LinearSystemSolver::matrix_changed(const bool few_rows)
  {
    factorised = false;
    if (amg && (!few_rows || rebuild_amg))
      amg.reset();
    amg_stale = amg != nullptr;
  }

  void
  LinearSystemSolver::factorise(const TrilinosWrappers::SparseMatrix &matrix)
  {
    TimerOutput::Scope t(timer, "Solve: factorisation");
    // The symbolic factorisation depends on the sparsity pattern only,
    // which is fixed until the next reset(). MUMPS (with its fill-reducing
    // ordering) factorised the 2D Hertz scene at 234k dofs 2.8 times faster
    // than KLU on one process, and factorises in parallel on several; KLU
    // is the fallback of a Trilinos built without it.
    if (!direct)
      {
        problem = std::make_unique<Epetra_LinearProblem>();
        problem->SetOperator(
          const_cast<Epetra_CrsMatrix *>(&matrix.trilinos_matrix()));
        Amesos      factory;
        const char *name =
          factory.Query("Amesos_Mumps") ? "Amesos_Mumps" : "Amesos_Klu";
        direct.reset(factory.Create(name, *problem));
        AssertThrow(direct, ExcMessage("Trilinos Amesos has no direct solver"));
        run_direct_phase(*direct,
                         [&]() { return direct->SymbolicFactorization(); });
      }
    run_direct_phase(*direct, [&]() { return direct->NumericFactorization(); });
    factorised = true;
  }

  void
  LinearSystemSolver::solve_direct(const TrilinosWrappers::SparseMatrix &matrix,
                                   TrilinosWrappers::MPI::Vector &solution,
                                   const TrilinosWrappers::MPI::Vector &rhs)
  {
    if (!factorised)
      factorise(matrix);
    TimerOutput::Scope t(timer, "Solve: back-substitution");
    problem->SetLHS(&solution.trilinos_vector());
    problem->SetRHS(const_cast<Epetra_MultiVector *>(&rhs.trilinos_vector()));
    run_direct_phase(*direct, [&]() { return direct->Solve(); });
    // KLU does not report a singular matrix, nor MUMPS a badly
    // conditioned one: check the result.
    TrilinosWrappers::MPI::Vector residual(rhs);
    matrix.vmult(residual, solution);
    residual -= rhs;
    const double error = residual.l2_norm();
    if (!std::isfinite(error) || error > 1e-6 * rhs.l2_norm())
      throw SolverFailure(exit_status::linear_solver,
                          "linear solver failed: the system is singular "
                          "or too ill-conditioned");
  }

  void
  LinearSystemSolver::build_amg(const TrilinosWrappers::SparseMatrix &matrix,
                                const unsigned int components)
  {
    TimerOutput::Scope t(timer, "Solve: AMG setup");
    amg.reset();
    // The setup's peak comes on top of what the assembly left free.
    release_free_memory();
    try
      {
        // ML's parameters as deal.II sets them for an elliptic problem.
        TrilinosWrappers::PreconditionAMG::AdditionalData data;
        data.elliptic              = true;
        data.higher_order_elements = false;
        data.smoother_sweeps       = 2;
        data.aggregation_threshold = 0.02;
        Teuchos::ParameterList              ml_parameters;
        std::unique_ptr<Epetra_MultiVector> unused;
        data.set_parameters(ml_parameters, unused, matrix);
        // Aggregate whole vertices, all displacement components together,
        // with ML's default near-null space for them: the translations.
        // (deal.II leaves ML's default of one equation per node, which
        // aggregates single components: CG needed many times the
        // iterations, and failed on bodies held by contact alone.) Adding
        // the rotations made the hierarchy twice as costly in time and
        // memory (3D, 165k dofs: setup 2.97 s against 1.43 s, peak 5.1
        // against 3.9 kB per dof) and CG no faster.
        ml_parameters.set("PDE equations", static_cast<int>(components));
        ml_parameters.set("null space: type", "default vectors");
        // In 3D, unsmoothed aggregation with W-cycles. Smoothing the
        // prolongator gives A P some 80 nonzeros per row, which ML's
        // Galerkin product holds twice: the setup peaked at 1.4 kB per dof
        // on top of the matrix (indentation scene, 493k dofs, one
        // process: peak 1.58 GB; unsmoothed 1.19 to 1.23 GB). Unsmoothed,
        // a V-cycle needs twice the CG iterations (39 against 20 for 8
        // digits); a W-cycle, almost free where each level has 1/27 of the
        // unknowns of the one above, takes 33, and the setup costs a third.
        // In 2D, where memory is no concern, the smoothed V-cycles measured
        // before stay.
        if (components == 3)
          {
            ml_parameters.set("aggregation: damping factor", 0.);
            ml_parameters.set("prec type", "MGW");
          }
        amg = std::make_unique<TrilinosWrappers::PreconditionAMG>();
        amg->initialize(matrix, ml_parameters);
      }
    catch (const ExceptionBase &)
      {
        amg.reset();
        throw SolverFailure(exit_status::linear_solver, singular);
      }
    amg_stale   = false;
    rebuild_amg = false;
  }

  unsigned int
  LinearSystemSolver::solve_iterative(
    const TrilinosWrappers::SparseMatrix &matrix,
    TrilinosWrappers::MPI::Vector        &solution,
    const TrilinosWrappers::MPI::Vector  &rhs,
    const double                          relative_tolerance,
    const bool                            symmetric)
  {
    TimerOutput::Scope t(timer, symmetric ? "Solve: CG" : "Solve: GMRES");
    double             tolerance = relative_tolerance * rhs.l2_norm();
    if (relative_tolerance > parameters.tolerance)
      {
        // A loose Newton step reduces its initial residual by a digit at
        // least: after an update of a few contact nodes the warm start may
        // already meet the loose tolerance, and a step without a solve
        // would leave the active set as it was and end the loose steps
        // early (indentation at 1.49M dofs: a tight solve, then 8 more
        // nodes, then another tight solve).
        TrilinosWrappers::MPI::Vector residual(rhs);
        matrix.vmult(residual, solution);
        residual -= rhs;
        tolerance = std::max(parameters.tolerance * rhs.l2_norm(),
                             std::min(tolerance, 0.1 * residual.l2_norm()));
      }
    SolverControl control(parameters.max_iterations, tolerance);
    try
      {
        if (symmetric)
          {
            SolverCG<TrilinosWrappers::MPI::Vector> cg(control);
            cg.solve(matrix, solution, rhs, *amg);
          }
        else
          {
            SolverGMRES<TrilinosWrappers::MPI::Vector> gmres(
              control, gmres_data<TrilinosWrappers::MPI::Vector>());
            gmres.solve(matrix, solution, rhs, *amg);
          }
      }
    catch (const SolverControl::NoConvergence &failure)
      {
        throw SolverFailure(exit_status::linear_solver,
                            std::string("linear solver (") +
                              (symmetric ? "CG" : "GMRES") +
                              " with AMG) did not converge in " +
                              std::to_string(failure.last_step) +
                              " iterations (Linear solver/Maximum iterations; "
                              "residual " +
                              std::to_string(failure.last_residual) + ")");
      }
    catch (const ExceptionBase &)
      {
        throw SolverFailure(exit_status::linear_solver, singular);
      }
    // A kept hierarchy serves while CG needs at most half again the
    // iterations per digit that it needed with a fresh one.
    const double rate = control.last_step() / digits(control);
    if (!amg_stale)
      fresh_rate = rate;
    else if (rate > 1.5 * fresh_rate)
      rebuild_amg = true;
    return control.last_step();
  }

  unsigned int
  LinearSystemSolver::solve(const TrilinosWrappers::SparseMatrix &matrix,
                            TrilinosWrappers::MPI::Vector        &solution,
                            const TrilinosWrappers::MPI::Vector  &rhs,
                            const unsigned int                    components,
                            const double relative_tolerance,
                            const bool   symmetric)
  {
    if (parameters.resolved_type(
          components,
          Utilities::MPI::n_mpi_processes(matrix.get_mpi_communicator()),
          matrix.m()) == LinearSolverParameters::Type::direct)
      {
        solve_direct(matrix, solution, rhs);
        return 1;
      }

    try
      {
        if (!amg)
          build_amg(matrix, components);
        return solve_iterative(
          matrix, solution, rhs, relative_tolerance, symmetric);
      }
    catch (const SolverFailure &failure)
      {
        if (!remedies)
          throw;
        if (amg_stale)
          {
            pcout << "   remedy: " << failure.what()
                  << " with the kept AMG; solved again with a fresh one"
                  << std::endl;
            // The failed iterate is no warm start.
            solution = 0.;
            try
              {
                build_amg(matrix, components);
                return solve_iterative(
                  matrix, solution, rhs, relative_tolerance, symmetric);
              }
            catch (const SolverFailure &)
              {
              }
          }
        pcout << "   remedy: " << failure.what()
              << "; solved by the direct solver instead" << std::endl;
        amg.reset();
        solve_direct(matrix, solution, rhs);
        // The factorisation is for this matrix only: forget it (and its
        // memory) rather than keep it for the next one.
        direct.reset();
        problem.reset();
        factorised = false;
        return 1;
      }
  }
} // namespace signorini
