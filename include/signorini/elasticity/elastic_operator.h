#ifndef signorini_elasticity_elastic_operator_h
#define signorini_elasticity_elastic_operator_h

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/timer.h>
#include <deal.II/lac/trilinos_vector.h>

#include <signorini/elasticity/system_additions.h>

#include <memory>

namespace signorini
{
  /**
   * The linear elastic operator of the body on the current mesh: its load,
   * its residual, and the solution of a Newton system: the elastic operator
   * with what a law adds to it (SystemAdditions, the only thing it knows of
   * contact). Implementations: AssembledOperator (a Trilinos matrix, cell
   * stiffness cache, direct or AMG-CG/GMRES solves with their reuse) and
   * MatrixFreeOperator (cell kernels, geometric multigrid).
   */
  template <int dim>
  class ElasticOperator
  {
  public:
    using VectorType = dealii::TrilinosWrappers::MPI::Vector;

    virtual ~ElasticOperator() = default;

    /** Sizes the operator for the discretisation's current dofs; forgets
     * everything of the previous mesh. */
    virtual void
    reinit() = 0;

    /** Assembles the load vector f [N] of the current mesh. */
    virtual void
    assemble_load() = 0;

    /** The load vector f [N]. */
    virtual const VectorType &
    load() const = 0;

    /** @p residual = K u - f [N] for the ghosted displacement @p u, with the
     * hanging nodes and the Dirichlet dofs condensed. */
    virtual void
    residual(const VectorType &u, VectorType &residual) = 0;

    /**
     * Solves the Newton system K u = f with the @p additions for the ghosted
     * displacement @p u, which is the initial guess of an iterative solver
     * and is returned with all constraints satisfied: by CG where the
     * additions keep the system symmetric, by GMRES where they do not.
     * Iterative solvers stop at Linear solver/Tolerance on the
     * @p final_step of a Newton iteration, at its Newton tolerance before.
     * Throws SolverFailure.
     */
    virtual void
    solve(const SystemAdditions<dim> &additions,
          VectorType                 &u,
          const bool                  final_step) = 0;

    /** Forgets the system built last: the next solve builds it anew (the
     * matrix and its preconditioner, or the cell data and the multigrid
     * levels). */
    virtual void
    invalidate() = 0;

    /** Frees the memory of the system until the next reinit(). */
    virtual void
    release() = 0;
  };

  template <int dim>
  class Discretisation;
  template <int dim>
  class Loads;
  template <int dim>
  struct BoundaryConditions;
  struct Material;
  class LinearSolverParameters;

  /** The elastic operator that Linear solver/Type names: MatrixFreeOperator
   * for `matrix-free`, AssembledOperator otherwise. @p remedies: failed
   * solves are retried (see LinearSystemSolver, MatrixFreeOperator);
   * @p verbose: the matrix-free operator prints its CG iterations. */
  template <int dim>
  std::unique_ptr<ElasticOperator<dim>>
  create_elastic_operator(const Discretisation<dim>     &discretisation,
                          const Material                &material,
                          const BoundaryConditions<dim> &boundary_conditions,
                          Loads<dim>                    &loads,
                          const LinearSolverParameters  &parameters,
                          const bool                     remedies,
                          const bool                     verbose,
                          dealii::ConditionalOStream    &pcout,
                          dealii::TimerOutput           &timer);
} // namespace signorini

#endif
