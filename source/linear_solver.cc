#include <deal.II/lac/solver_cg.h>
#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/trilinos_precondition.h>
#include <deal.II/lac/trilinos_solver.h>

#include <signorini/failures.h>
#include <signorini/linear_solver.h>

#include <Epetra_MultiVector.h>
#include <Teuchos_ParameterList.hpp>
#include <cmath>

namespace signorini
{
  using namespace dealii;

  void
  LinearSolver::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Linear solver");
    prm.declare_entry("Type",
                      "automatic",
                      Patterns::Selection("automatic|direct|amg cg"),
                      "direct: sparse LU (Trilinos Amesos KLU); amg cg: "
                      "conjugate gradients with algebraic multigrid (Trilinos "
                      "ML); automatic: direct in 2D, amg cg in 3D, the faster "
                      "of the two as measured (see README).");
    prm.declare_entry("Tolerance",
                      "1e-12",
                      Patterns::Double(0.),
                      "amg cg: residual reduction relative to the right-hand "
                      "side.");
    prm.declare_entry("Maximum iterations",
                      "2000",
                      Patterns::Integer(1),
                      "amg cg: iterations allowed per solve.");
    prm.leave_subsection();
  }

  void
  LinearSolver::parse_parameters(ParameterHandler &prm, const unsigned int dim)
  {
    prm.enter_subsection("Linear solver");
    const std::string name = prm.get("Type");
    type           = name == "direct" || (name == "automatic" && dim == 2) ?
                       Type::direct :
                       Type::amg_cg;
    tolerance      = prm.get_double("Tolerance");
    max_iterations = prm.get_integer("Maximum iterations");
    prm.leave_subsection();
  }

  unsigned int
  LinearSolver::solve(
    const TrilinosWrappers::SparseMatrix             &matrix,
    TrilinosWrappers::MPI::Vector                    &solution,
    const TrilinosWrappers::MPI::Vector              &rhs,
    const std::vector<TrilinosWrappers::MPI::Vector> &rigid_body_modes) const
  {
    try
      {
        if (type == Type::direct)
          {
            SolverControl                  control(1, 0);
            TrilinosWrappers::SolverDirect solver(
              control,
              TrilinosWrappers::SolverDirect::AdditionalData(false,
                                                             "Amesos_Klu"));
            solver.solve(matrix, solution, rhs);
            // KLU does not report a singular matrix: check the result.
            dealii::TrilinosWrappers::MPI::Vector residual(rhs);
            matrix.vmult(residual, solution);
            residual -= rhs;
            const double error = residual.l2_norm();
            if (!std::isfinite(error) || error > 1e-6 * rhs.l2_norm())
              throw SolverFailure(exit_status::linear_solver,
                                  "linear solver failed: the system is "
                                  "singular (is the body held against rigid "
                                  "motion?)");
            return 1;
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
        TrilinosWrappers::PreconditionAMG amg;
        amg.initialize(matrix, ml_parameters);

        SolverControl control(max_iterations, tolerance * rhs.l2_norm());
        SolverCG<TrilinosWrappers::MPI::Vector> cg(control);
        cg.solve(matrix, solution, rhs, amg);
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
    catch (const ExceptionBase &failure)
      {
        throw SolverFailure(exit_status::linear_solver,
                            std::string("linear solver failed: ") +
                              "the system is singular or the solver broke "
                              "down (is the body held against rigid motion?)");
      }
  }
} // namespace signorini
