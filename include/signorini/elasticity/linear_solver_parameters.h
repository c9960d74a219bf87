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
   * 2D on one process, amg cg in 3D and on several processes.
   */
  class LinearSolverParameters
  {
  public:
    enum class Type
    {
      direct,
      amg_cg
    };

    static void
    declare_parameters(dealii::ParameterHandler &prm);

    /** Resolves `automatic` for @p dim space dimensions on @p n_processes
     * MPI processes. */
    void
    parse_parameters(dealii::ParameterHandler &prm,
                     const unsigned int        dim,
                     const unsigned int        n_processes);

    Type   type      = Type::direct;
    double tolerance = 1e-12;
    /** amg cg: the looser reduction of the Newton steps taken while the
     * active set still changes. */
    double       newton_tolerance = 1e-4;
    unsigned int max_iterations   = 2000;
  };
} // namespace signorini

#endif
