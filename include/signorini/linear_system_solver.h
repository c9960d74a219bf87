#ifndef signorini_linear_system_solver_h
#define signorini_linear_system_solver_h

#include <deal.II/lac/trilinos_precondition.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <signorini/linear_solver.h>

#include <memory>
#include <vector>

class Amesos_BaseSolver;
class Epetra_LinearProblem;

namespace signorini
{
  /**
   * The linear solver of the Newton steps, with what it can keep between
   * them: the direct solver's symbolic factorisation (the sparsity pattern is
   * fixed for a mesh) and its numeric factorisation or the AMG hierarchy
   * (valid while the matrix is unchanged, e.g. over the multiplier updates of
   * the augmented Lagrangian method, whose matrix changes only with the
   * active set).
   */
  class LinearSystemSolver
  {
  public:
    explicit LinearSystemSolver(const LinearSolver &parameters);
    ~LinearSystemSolver();

    /** Forgets everything: call when the matrix is built anew (new mesh). */
    void
    reset();

    /**
     * Factorises @p matrix (reusing the symbolic factorisation since the last
     * reset()) or builds its AMG hierarchy with @p rigid_body_modes, the
     * near-null space of elasticity, for the solves that follow.
     */
    void
    prepare(const dealii::TrilinosWrappers::SparseMatrix             &matrix,
            const std::vector<dealii::TrilinosWrappers::MPI::Vector> &modes);

    /**
     * Solves @p matrix x = @p rhs with what prepare() made of the same
     * matrix; @p solution is the initial guess of the iterative solver.
     * Returns the iterations (1 for the direct solver); throws SolverFailure
     * if the solve fails.
     */
    unsigned int
    solve(const dealii::TrilinosWrappers::SparseMatrix &matrix,
          dealii::TrilinosWrappers::MPI::Vector        &solution,
          const dealii::TrilinosWrappers::MPI::Vector  &rhs);

  private:
    const LinearSolver                                        &parameters;
    std::unique_ptr<Epetra_LinearProblem>                      problem;
    std::unique_ptr<Amesos_BaseSolver>                         direct;
    std::unique_ptr<dealii::TrilinosWrappers::PreconditionAMG> amg;
  };
} // namespace signorini

#endif
