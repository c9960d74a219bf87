#include <deal.II/base/mpi.h>
#include <deal.II/lac/solver_cg.h>
#include <deal.II/lac/solver_control.h>

#include <signorini/failures.h>
#include <signorini/linear_system_solver.h>

#include <Amesos.h>
#include <Amesos_BaseSolver.h>
#include <Epetra_LinearProblem.h>
#include <Epetra_MultiVector.h>
#include <Teuchos_ParameterList.hpp>
#include <cmath>
#include <cstdio>

namespace signorini
{
  using namespace dealii;

  namespace
  {
    const char *singular = "linear solver failed: the system is singular or "
                           "the solver broke down";

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

  LinearSystemSolver::LinearSystemSolver(const LinearSolver &parameters,
                                         const bool          remedies,
                                         ConditionalOStream &pcout,
                                         TimerOutput        &timer)
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
        if (direct->SymbolicFactorization() != 0)
          throw SolverFailure(exit_status::linear_solver, singular);
      }
    if (direct->NumericFactorization() != 0)
      throw SolverFailure(exit_status::linear_solver, singular);
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
    if (direct->Solve() != 0)
      throw SolverFailure(exit_status::linear_solver, singular);
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
  LinearSystemSolver::build_amg(
    const TrilinosWrappers::SparseMatrix             &matrix,
    const std::vector<TrilinosWrappers::MPI::Vector> &modes)
  {
    TimerOutput::Scope t(timer, "Solve: AMG setup");
    amg.reset();
    try
      {
        // ML's parameters as deal.II sets them for an elliptic problem, with
        // the translations as near-null space.
        TrilinosWrappers::PreconditionAMG::AdditionalData data;
        data.elliptic              = true;
        data.higher_order_elements = false;
        data.smoother_sweeps       = 2;
        data.aggregation_threshold = 0.02;
        Teuchos::ParameterList              ml_parameters;
        std::unique_ptr<Epetra_MultiVector> unused;
        data.set_parameters(ml_parameters, unused, matrix);
        const auto        &map = matrix.trilinos_matrix().DomainMap();
        Epetra_MultiVector null_space(map, modes.size());
        for (unsigned int k = 0; k < modes.size(); ++k)
          for (int i = 0; i < map.NumMyElements(); ++i)
            null_space[k][i] = modes[k].trilinos_vector()[0][i];
        ml_parameters.set("null space: type", "pre-computed");
        ml_parameters.set("null space: dimension", null_space.NumVectors());
        ml_parameters.set("null space: vectors", null_space.Values());
        // Aggregate whole vertices, all displacement components together.
        // (deal.II leaves ML's default of one equation per node, which
        // aggregates single components: CG needed many times the
        // iterations, and failed on bodies held by contact alone.) With
        // whole vertices, adding the rotations to the near-null space made
        // the hierarchy twice as costly in time and memory (3D, 165k dofs:
        // setup 2.97 s against 1.43 s, peak 5.1 against 3.9 kB per dof)
        // and CG no faster.
        ml_parameters.set("PDE equations", static_cast<int>(modes.size()));
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
  LinearSystemSolver::solve_cg(const TrilinosWrappers::SparseMatrix &matrix,
                               TrilinosWrappers::MPI::Vector        &solution,
                               const TrilinosWrappers::MPI::Vector  &rhs,
                               const double relative_tolerance)
  {
    TimerOutput::Scope t(timer, "Solve: CG");
    SolverControl      control(parameters.max_iterations,
                          relative_tolerance * rhs.l2_norm());
    try
      {
        SolverCG<TrilinosWrappers::MPI::Vector> cg(control);
        cg.solve(matrix, solution, rhs, *amg);
      }
    catch (const SolverControl::NoConvergence &failure)
      {
        throw SolverFailure(exit_status::linear_solver,
                            "linear solver (CG with AMG) did not converge in " +
                              std::to_string(failure.last_step) +
                              " iterations (residual " +
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
  LinearSystemSolver::solve(
    const TrilinosWrappers::SparseMatrix             &matrix,
    TrilinosWrappers::MPI::Vector                    &solution,
    const TrilinosWrappers::MPI::Vector              &rhs,
    const std::vector<TrilinosWrappers::MPI::Vector> &modes,
    const double                                      relative_tolerance)
  {
    if (parameters.type == LinearSolver::Type::direct)
      {
        solve_direct(matrix, solution, rhs);
        return 1;
      }

    const TrilinosWrappers::MPI::Vector initial_guess = solution;
    try
      {
        if (!amg)
          build_amg(matrix, modes);
        return solve_cg(matrix, solution, rhs, relative_tolerance);
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
            solution = initial_guess;
            try
              {
                build_amg(matrix, modes);
                return solve_cg(matrix, solution, rhs, relative_tolerance);
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
