#ifndef signorini_elasticity_matrix_free_operator_h
#define signorini_elasticity_matrix_free_operator_h

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/timer.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/la_parallel_vector.h>

#include <signorini/discretisation/boundary_conditions.h>
#include <signorini/discretisation/discretisation.h>
#include <signorini/elasticity/elastic_level_operator.h>
#include <signorini/elasticity/elastic_multigrid.h>
#include <signorini/elasticity/elastic_operator.h>
#include <signorini/elasticity/linear_solver_parameters.h>
#include <signorini/elasticity/loads.h>
#include <signorini/elasticity/local_constraints.h>
#include <signorini/elasticity/material.h>

#include <cstddef>
#include <memory>
#include <utility>

namespace signorini
{
  template <int dim>
  class AssembledOperator;

  /**
   * The elastic operator without a matrix (`Linear solver/Type =
   * matrix-free`): Q1 or Q2 on quadrilaterals and hexahedra evaluated cell by
   * cell (ElasticLevelOperator), the Newton systems solved by CG with geometric
   * multigrid (ElasticMultigrid).
   *
   * The Newton system with SystemAdditions: with G the discretisation's
   * constraints and the additions' lines (closed together, as
   * AssembledOperator condenses them), u = u0 + d, where u0 is the current
   * displacement with G applied and d solves P^T (K + B) P d = -R(u0) on
   * the dofs G leaves free; P sets the dofs of the added lines from the
   * other dofs of their vertex, B are the blocks (at one vertex each), and
   * R is the residual of the Newton system. CG solves it where the
   * additions are symmetric, GMRES where not, with the same multigrid. The
   * same system as the assembled one, to the solvers' tolerance.
   *
   * With @p remedies, a solve that fails is repeated by an AssembledOperator
   * (a `remedy:` line), which then serves until the next mesh.
   */
  template <int dim>
  class MatrixFreeOperator : public ElasticOperator<dim>
  {
  public:
    using VectorType = typename ElasticOperator<dim>::VectorType;

    /** Throws InputError (Linear solver/Type) unless the element is Q1 or Q2
     * (checked at reinit()). @p verbose: a line per solve with the CG
     * iterations. */
    MatrixFreeOperator(const Discretisation<dim>     &discretisation,
                       const Material                &material,
                       const BoundaryConditions<dim> &boundary_conditions,
                       Loads<dim>                    &loads,
                       const LinearSolverParameters  &parameters,
                       const bool                     remedies,
                       const bool                     verbose,
                       dealii::ConditionalOStream    &pcout,
                       dealii::TimerOutput           &timer);
    ~MatrixFreeOperator() override;

    void
    reinit() override;

    void
    assemble_load() override;

    const VectorType &
    load() const override;

    void
    residual(const VectorType &u, VectorType &residual) override;

    void
    solve(const SystemAdditions<dim> &additions,
          VectorType                 &u,
          const bool                  final_step) override;

    void
    invalidate() override;

    void
    release() override;

  private:
    using LAVector = dealii::LinearAlgebra::distributed::Vector<double>;

    /** Drops the fine operator, the levels and their contact (the next
     * solve builds them). */
    void
    forget_operator();

    /** The fine operator of the current mesh. */
    void
    setup_fine();

    /** The fine operator and the multigrid levels of the current mesh. */
    void
    setup_levels();

    /** The additions' constraint lines and blocks on the fine level, and
     * the multigrid's contact (blocks, constraint springs) for
     * @p additions. */
    void
    setup_contact(const SystemAdditions<dim> &additions);

    /** @p r = P^T (K u - f + B u - the blocks' and the forces' right-hand
     * side) for @p u with the constraints G applied; zero at the
     * constrained dofs. */
    void
    newton_residual(const SystemAdditions<dim> &additions,
                    const LAVector             &u,
                    LAVector                   &r) const;

    /** CG (GMRES for non-symmetric additions) with multigrid on d; returns
     * the iterations. */
    unsigned int
    solve_iterative(const SystemAdditions<dim> &additions,
                    VectorType                 &u,
                    const bool                  final_step);

    void
    to_la(const VectorType &in, LAVector &out) const;
    void
    from_la(const LAVector &in, VectorType &out) const;

    const Discretisation<dim>     &discretisation;
    const Material                &material;
    const BoundaryConditions<dim> &boundary_conditions;
    Loads<dim>                    &loads;
    const LinearSolverParameters  &parameters;
    const bool                     remedies;
    const bool                     verbose;
    dealii::ConditionalOStream    &pcout;
    dealii::TimerOutput           &timer;

    std::shared_ptr<ElasticLevelOperator<dim>> fine;
    ElasticMultigrid<dim>                      multigrid;
    bool                                       levels_ready = false;
    /** The discretisation's constraints plus the additions' lines. */
    dealii::AffineConstraints<double> constraints;
    /** distribute() of `constraints` on the fine operator's vectors. */
    LocalConstraints                   local_constraints;
    bool                               contact_ready = false;
    typename SystemAdditions<dim>::Key contact_for;
    VectorType                         load_vector;
    LAVector                           load_la;
    /** The assembled operator of a remedy, until the next mesh. */
    std::unique_ptr<AssembledOperator<dim>> fallback;
  };
} // namespace signorini

#endif
