#ifndef signorini_elasticity_linear_solver_parameters_h
#define signorini_elasticity_linear_solver_parameters_h

#include <deal.II/base/parameter_handler.h>

namespace signorini
{
  /**
   * The parameters of the linear solver used in every Newton step
   * (LinearSystemSolver): subsection `Linear solver`.
   * `direct` factorises with Trilinos Amesos (MUMPS); `amg cg` runs
   * conjugate gradients preconditioned by Trilinos ML algebraic multigrid,
   * with the translations as near-null space; `automatic` takes direct in
   * 2D on one process, amg cg in 3D and on several processes (see
   * resolved_type()). `matrix-free` holds no matrix: MatrixFreeOperator,
   * CG with geometric multigrid (Q1, pointwise volumetric strain, not
   * axisymmetric).
   */
  class LinearSolverParameters
  {
  public:
    enum class Type
    {
      automatic,
      direct,
      amg_cg,
      matrix_free
    };

    /** Declares the entries, with the defaults of a default-constructed
     * instance. */
    static void
    declare_parameters(dealii::ParameterHandler &prm);

    void
    parse_parameters(dealii::ParameterHandler &prm);

    /** The solver that runs for a system of @p dim displacement components
     * on @p n_processes MPI processes: `direct` or `amg_cg` as given;
     * `automatic` is direct for @p dim = 2 on one process and amg cg
     * otherwise; `matrix_free`, whose assembled system is solved only as a
     * remedy, as `automatic`. */
    Type
    resolved_type(const unsigned int dim, const unsigned int n_processes) const;

    Type type = Type::automatic;
    /** amg cg: residual reduction relative to the right-hand side. */
    double tolerance = 1e-12;
    /** amg cg: the looser reduction of the Newton steps taken while the
     * active set still changes (at least `tolerance`). */
    double newton_tolerance = 1e-4;
    /** amg cg: iterations allowed per solve. */
    unsigned int max_iterations = 2000;
  };
} // namespace signorini

#endif
