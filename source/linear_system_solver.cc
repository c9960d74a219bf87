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
  }

  LinearSystemSolver::LinearSystemSolver(const LinearSolver &parameters)
    : parameters(parameters)
  {
  }

  LinearSystemSolver::~LinearSystemSolver() = default;

  void
  LinearSystemSolver::reset()
  {
    direct.reset();
    problem.reset();
    amg.reset();
  }

  void
  LinearSystemSolver::prepare(
    const TrilinosWrappers::SparseMatrix             &matrix,
    const std::vector<TrilinosWrappers::MPI::Vector> &rigid_body_modes)
  {
    try
      {
        if (parameters.type == LinearSolver::Type::direct)
          {
            // The symbolic factorisation depends on the sparsity pattern
            // only, which is fixed until the next reset().
            if (!direct)
              {
                problem = std::make_unique<Epetra_LinearProblem>();
                problem->SetOperator(
                  const_cast<Epetra_CrsMatrix *>(&matrix.trilinos_matrix()));
                Amesos factory;
                direct.reset(factory.Create("Amesos_Klu", *problem));
                AssertThrow(direct, ExcMessage("Amesos_Klu is not available"));
                if (direct->SymbolicFactorization() != 0)
                  throw SolverFailure(exit_status::linear_solver, singular);
              }
            if (direct->NumericFactorization() != 0)
              throw SolverFailure(exit_status::linear_solver, singular);
            return;
          }

        // ML's parameters as deal.II sets them for an elliptic problem, with
        // the rigid-body modes (rotations included) as near-null space.
        TrilinosWrappers::PreconditionAMG::AdditionalData data;
        data.elliptic              = true;
        data.higher_order_elements = false;
        data.smoother_sweeps       = 2;
        data.aggregation_threshold = 0.02;
        Teuchos::ParameterList              ml_parameters;
        std::unique_ptr<Epetra_MultiVector> unused;
        data.set_parameters(ml_parameters, unused, matrix);
        const auto        &map = matrix.trilinos_matrix().DomainMap();
        Epetra_MultiVector modes(map, rigid_body_modes.size());
        for (unsigned int k = 0; k < rigid_body_modes.size(); ++k)
          for (int i = 0; i < map.NumMyElements(); ++i)
            modes[k][i] = rigid_body_modes[k].trilinos_vector()[0][i];
        ml_parameters.set("null space: type", "pre-computed");
        ml_parameters.set("null space: dimension", modes.NumVectors());
        ml_parameters.set("null space: vectors", modes.Values());
        amg = std::make_unique<TrilinosWrappers::PreconditionAMG>();
        amg->initialize(matrix, ml_parameters);
      }
    catch (const ExceptionBase &)
      {
        throw SolverFailure(exit_status::linear_solver, singular);
      }
  }

  unsigned int
  LinearSystemSolver::solve(const TrilinosWrappers::SparseMatrix &matrix,
                            TrilinosWrappers::MPI::Vector        &solution,
                            const TrilinosWrappers::MPI::Vector  &rhs)
  {
    if (parameters.type == LinearSolver::Type::direct)
      {
        Assert(direct, ExcMessage("prepare() was not called"));
        problem->SetLHS(&solution.trilinos_vector());
        problem->SetRHS(
          const_cast<Epetra_MultiVector *>(&rhs.trilinos_vector()));
        if (direct->Solve() != 0)
          throw SolverFailure(exit_status::linear_solver, singular);
        // KLU does not report a singular matrix: check the result.
        TrilinosWrappers::MPI::Vector residual(rhs);
        matrix.vmult(residual, solution);
        residual -= rhs;
        const double error = residual.l2_norm();
        char         relative[32];
        std::snprintf(relative,
                      sizeof(relative),
                      "%.3g",
                      error / rhs.l2_norm());
        if (!std::isfinite(error) || error > 1e-6 * rhs.l2_norm())
          throw SolverFailure(exit_status::linear_solver,
                              "linear solver failed: the system is singular "
                              "or too ill-conditioned");
        return 1;
      }

    Assert(amg, ExcMessage("prepare() was not called"));
    try
      {
        SolverControl control(parameters.max_iterations,
                              parameters.tolerance * rhs.l2_norm());
        SolverCG<TrilinosWrappers::MPI::Vector> cg(control);
        cg.solve(matrix, solution, rhs, *amg);
        return control.last_step();
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
  }
} // namespace signorini
