#ifndef signorini_elasticity_linear_solver_parameters_h
#define signorini_elasticity_linear_solver_parameters_h

#include <deal.II/base/parameter_handler.h>

#include <signorini/input/entry_text.h>

namespace signorini
{
  /**
   * The parameters of the linear solver used in every Newton step
   * (LinearSystemSolver): subsection `Linear solver`.
   * `direct` factorises with Trilinos Amesos (MUMPS); `amg cg` runs
   * conjugate gradients preconditioned by Trilinos ML algebraic multigrid,
   * with the translations as near-null space. `matrix-free` holds no
   * matrix: MatrixFreeOperator, CG with geometric multigrid (Q1, pointwise
   * volumetric strain, not axisymmetric). `automatic` takes matrix-free on
   * hexahedra in 3D where it is faster (AutomaticOperator), else the
   * assembled operator with the solver of resolved_type().
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

    /** The solver that runs for a system of @p n_dofs unknowns with @p dim
     * displacement components on @p n_processes MPI processes: `direct` or
     * `amg_cg` as given; `automatic` is direct for @p dim = 2 on one
     * process below `direct_below` dofs and amg cg otherwise;
     * `matrix_free`, whose assembled system is solved only as a remedy, as
     * `automatic`. */
    Type
    resolved_type(const unsigned int                    dim,
                  const unsigned int                    n_processes,
                  const dealii::types::global_dof_index n_dofs) const;

    /** `automatic`, 2D, one process: the size from which amg cg solves.
     * Measured on the 2D Hertz scene (one process, contact solve): amg cg
     * 0.41 s against the direct solver's 0.67 s at 65,810 dofs, 1.31 s
     * against 1.66 s at 234,146, 2.62 s against 3.45 s at 442,450, and
     * half the memory; below 100,000 dofs the direct solve takes a few
     * hundredths of a second and needs no preconditioner that a penalty's
     * stiffness could spoil. */
    static constexpr dealii::types::global_dof_index direct_below = 100000;

    /** Each type's name in a parameter file and what it does. A new
     * elastic operator adds its value to Type, its line here, and a line
     * in create_elastic_operator(). */
    static const Choices<Type> &
    types()
    {
      static const Choices<Type> choices{
        {Type::automatic,
         "automatic",
         "matrix-free on hexahedra in 3D (at least half of them "
         "parallelepipeds with flat manifolds, the volumetric strain at every "
         "point), else direct in 2D on one process below 100,000 dofs and "
         "amg cg above, in 3D and on several processes, the faster choices "
         "as measured (see doc/linear-solvers.md)"},
        {Type::direct, "direct", "sparse LU (Trilinos Amesos MUMPS)"},
        {Type::amg_cg,
         "amg cg",
         "conjugate gradients with algebraic multigrid (Trilinos ML), GMRES "
         "where the Newton system is not symmetric"},
        {Type::matrix_free,
         "matrix-free",
         "no matrix, the elastic operator evaluated cell by cell and CG "
         "(GMRES where the Newton system is not symmetric) with geometric "
         "multigrid (quadrilaterals and hexahedra, not axisymmetric, "
         "volumetric strain pointwise; Tolerance, Newton tolerance and "
         "Maximum iterations as for amg cg)"}};
      return choices;
    }

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
