#ifndef signorini_elasticity_linear_system_solver_h
#define signorini_elasticity_linear_system_solver_h

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/timer.h>
#include <deal.II/lac/solver_gmres.h>
#include <deal.II/lac/trilinos_precondition.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <signorini/elasticity/linear_solver_parameters.h>

#include <memory>
#include <string>
#include <vector>

class Amesos_BaseSolver;
class Epetra_LinearProblem;

namespace signorini
{
  /** GMRES for the non-symmetric Newton systems (friction's): right
   * preconditioning, so that it stops on the true residual as CG does, and
   * restarts after 100 vectors. */
  template <typename VectorType>
  typename dealii::SolverGMRES<VectorType>::AdditionalData
  gmres_data()
  {
    return typename dealii::SolverGMRES<VectorType>::AdditionalData(100, true);
  }

  /**
   * The linear solver of the Newton steps, with what it can keep between
   * them:
   * - direct: the symbolic factorisation (the sparsity pattern is fixed for
   *   a mesh), and the numeric one while the matrix is unchanged (e.g. over
   *   the multiplier updates of the augmented Lagrangian method);
   * - amg cg: the AMG hierarchy while the matrix is unchanged, and also
   *   while it changes only in a few rows and columns (an active-set
   *   update): the old hierarchy remains a good preconditioner, and it is
   *   rebuilt only when CG needs markedly more iterations per digit than it
   *   did with a fresh one.
   *
   * The solver is the one LinearSolverParameters::resolved_type() names for
   * the number of displacement components and the processes of the
   * matrix's communicator, at every solve.
   *
   * With @p remedies, a CG solve that fails is retried with a fresh
   * hierarchy (if it was kept), then by the direct solver; each remedy is
   * reported on a `remedy:` line, and only a system the direct solver cannot
   * solve either throws SolverFailure.
   */
  class LinearSystemSolver
  {
  public:
    LinearSystemSolver(const LinearSolverParameters &parameters,
                       const bool                    remedies,
                       dealii::ConditionalOStream   &pcout,
                       dealii::TimerOutput          &timer);
    ~LinearSystemSolver();

    /** Forgets everything: call when the matrix is built anew (new mesh). */
    void
    reset();

    /**
     * The matrix changed. With @p few_rows (only the rows and columns of a
     * few constraints changed), an AMG hierarchy may be kept; otherwise the
     * next solve factorises or builds the hierarchy anew.
     */
    void
    matrix_changed(const bool few_rows);

    /**
     * Solves @p matrix x = @p rhs; @p solution is the initial guess of CG
     * (GMRES if the matrix is not @p symmetric), which stops at a residual
     * of @p relative_tolerance times the norm of @p rhs (the direct solver
     * ignores it). @p components is the number
     * of displacement components, which the dofs of each vertex hold in
     * consecutive order: the AMG aggregates vertices whole and takes the
     * translations as its near-null space. Returns the iterations (1 for
     * the direct solver); throws SolverFailure if even the direct solver
     * fails.
     */
    unsigned int
    solve(const dealii::TrilinosWrappers::SparseMatrix &matrix,
          dealii::TrilinosWrappers::MPI::Vector        &solution,
          const dealii::TrilinosWrappers::MPI::Vector  &rhs,
          const unsigned int                            components,
          const double                                  relative_tolerance,
          const bool                                    symmetric = true);

  private:
    void
    factorise(const dealii::TrilinosWrappers::SparseMatrix &matrix);
    void
    solve_direct(const dealii::TrilinosWrappers::SparseMatrix &matrix,
                 dealii::TrilinosWrappers::MPI::Vector        &solution,
                 const dealii::TrilinosWrappers::MPI::Vector  &rhs);
    void
    build_amg(const dealii::TrilinosWrappers::SparseMatrix &matrix,
              const unsigned int                            components);
    /** CG (GMRES if not @p symmetric) iterations with the AMG; throws
     * SolverFailure if it does not converge. */
    unsigned int
    solve_iterative(const dealii::TrilinosWrappers::SparseMatrix &matrix,
                    dealii::TrilinosWrappers::MPI::Vector        &solution,
                    const dealii::TrilinosWrappers::MPI::Vector  &rhs,
                    const double relative_tolerance,
                    const bool   symmetric);

    const LinearSolverParameters         &parameters;
    const bool                            remedies;
    dealii::ConditionalOStream           &pcout;
    dealii::TimerOutput                  &timer;
    std::unique_ptr<Epetra_LinearProblem> problem;
    std::unique_ptr<Amesos_BaseSolver>    direct;
    bool                                  factorised = false;
    std::unique_ptr<dealii::TrilinosWrappers::PreconditionAMG> amg;
    /** The AMG was built for an earlier matrix. */
    bool amg_stale = false;
    /** Rebuild the AMG at the next change of the matrix. */
    bool rebuild_amg = false;
    /** CG iterations per digit of residual reduction with a fresh AMG. */
    double fresh_rate = 0.;
  };
} // namespace signorini

#endif
