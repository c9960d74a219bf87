#ifndef signorini_linear_solver_h
#define signorini_linear_solver_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <vector>

namespace signorini
{
  /**
   * The linear solver used in every Newton step: subsection `Linear solver`.
   * `direct` factorises with Trilinos Amesos (KLU); `amg cg` runs conjugate
   * gradients preconditioned by Trilinos ML algebraic multigrid, with the
   * rigid-body modes as near-null space; `automatic` takes direct in 2D and
   * amg cg in 3D.
   */
  class LinearSolver
  {
  public:
    enum class Type
    {
      direct,
      amg_cg
    };

    static void
    declare_parameters(dealii::ParameterHandler &prm);

    /** Resolves `automatic` for @p dim space dimensions. */
    void
    parse_parameters(dealii::ParameterHandler &prm, const unsigned int dim);

    /**
     * Solves @p matrix x = @p rhs. @p rigid_body_modes, the near-null space
     * of elasticity (translations and rotations as displacement vectors),
     * are used by the AMG. Returns the number of iterations (1 for the direct
     * solver); throws SolverFailure if the solve fails.
     */
    unsigned int
    solve(const dealii::TrilinosWrappers::SparseMatrix &matrix,
          dealii::TrilinosWrappers::MPI::Vector        &solution,
          const dealii::TrilinosWrappers::MPI::Vector  &rhs,
          const std::vector<dealii::TrilinosWrappers::MPI::Vector>
            &rigid_body_modes) const;

    Type         type           = Type::direct;
    double       tolerance      = 1e-12;
    unsigned int max_iterations = 2000;
  };
} // namespace signorini

#endif
