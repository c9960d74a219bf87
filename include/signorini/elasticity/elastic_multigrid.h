#ifndef signorini_elasticity_elastic_multigrid_h
#define signorini_elasticity_elastic_multigrid_h

#include <deal.II/fe/component_mask.h>
#include <deal.II/lac/diagonal_matrix.h>
#include <deal.II/lac/precondition.h>
#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/trilinos_solver.h>
#include <deal.II/multigrid/mg_base.h>
#include <deal.II/multigrid/mg_matrix.h>
#include <deal.II/multigrid/mg_smoother.h>
#include <deal.II/multigrid/multigrid.h>

#include <signorini/elasticity/elastic_level_operator.h>
#include <signorini/elasticity/level_transfer.h>

#include <memory>
#include <utility>
#include <vector>

namespace signorini
{
  /**
   * Geometric multigrid for ElasticLevelOperator by global coarsening: the
   * levels are the fine mesh coarsened once, twice, ... down to the coarse
   * mesh (coarsening_sequence), connected by LevelTransfer, each with its
   * hanging nodes and the homogeneous Dirichlet data. A fine level of
   * degree 2 has Q1 on its own mesh below it (a p-step), and Q1 on the
   * coarsened meshes below that. Chebyshev smoothing
   * (degree 3) on the inverse diagonal, the levels' cell matrices applied
   * in single precision; the coarsest level solved directly (Trilinos
   * Amesos KLU) on its assembled matrix.
   *
   * Contact on the coarser levels: the fine level has its held lines and
   * springs exactly; a coarser level has the springs, and the held nodes as
   * springs, restricted to it (sum_f phi_c(x_f) k_f n_f n_f^T at its
   * vertex c): a body held by contact alone stays held on every level.
   */
  template <int dim>
  class ElasticMultigrid
  {
  public:
    using VectorType    = dealii::LinearAlgebra::distributed::Vector<double>;
    using LevelOperator = ElasticLevelOperator<dim>;

    ElasticMultigrid(const Material &material);
    ~ElasticMultigrid();

    /**
     * The coarser levels below @p fine, whose mesh is coarsened globally,
     * with the Dirichlet data @p dirichlet (boundary ids and components)
     * made homogeneous; @p fine_constraints are those of @p fine.
     */
    void
    setup(const dealii::Mapping<dim>                          &mapping,
          const std::shared_ptr<LevelOperator>                &fine,
          const dealii::AffineConstraints<double>             &fine_constraints,
          const std::vector<std::pair<dealii::types::boundary_id,
                                      dealii::ComponentMask>> &dirichlet);

    /**
     * The contact of the coarser levels from the fine level's nodal
     * stiffnesses: @p diagonal holds sum k n_a^2 at component a of a
     * vertex, @p off_diagonal k n_x n_y (2D), or k n_x n_y, k n_y n_z,
     * k n_x n_z (3D) at its components; then the smoothers and the coarse
     * factorisation anew (also when the fine level's contact changed).
     * @p fine_contact: the fine level's constraints with its contact's
     * lines, which the factorisation takes where the fine level is the
     * only one. Throws SolverFailure if the coarse matrix is singular.
     */
    void
    update(const VectorType                        &diagonal,
           const VectorType                        &off_diagonal,
           const dealii::AffineConstraints<double> &fine_contact);

    /** One V-cycle: dst = M^-1 src. */
    void
    vmult(VectorType &dst, const VectorType &src) const;

    /** The number of levels, the fine one included. */
    unsigned int
    n_levels() const;

    /** The number of dofs of each level, coarsest first. */
    std::vector<dealii::types::global_dof_index>
    level_sizes() const;

    /** Whether setup() was called since the last clear(). */
    bool
    ready() const;

    void
    clear();

  private:
    /**
     * A level's operator as the V-cycle applies it, in its smoothing and
     * its residuals: with the cells' shape matrices in single precision
     * (LevelOperator::vmult_single()). A preconditioner needs no more than
     * that; CG's own products and residuals stay in double.
     */
    class SinglePrecisionLevel : public dealii::Subscriptor
    {
    public:
      using value_type = double;

      explicit SinglePrecisionLevel(std::shared_ptr<const LevelOperator> op)
        : op(std::move(op))
      {
      }

      void
      vmult(VectorType &dst, const VectorType &src) const
      {
        op->vmult_single(dst, src);
      }

      void
      Tvmult(VectorType &dst, const VectorType &src) const
      {
        op->vmult_single(dst, src);
      }

      dealii::types::global_dof_index
      m() const
      {
        return op->m();
      }

      double
      el(const dealii::types::global_dof_index i,
         const dealii::types::global_dof_index j) const
      {
        return op->el(i, j);
      }

    private:
      std::shared_ptr<const LevelOperator> op;
    };

    using Smoother =
      dealii::PreconditionChebyshev<SinglePrecisionLevel,
                                    VectorType,
                                    dealii::DiagonalMatrix<VectorType>>;

    const Material                                                &material;
    std::vector<std::shared_ptr<const dealii::Triangulation<dim>>> meshes;
    std::vector<std::unique_ptr<dealii::DoFHandler<dim>>>          dofs;
    dealii::MGLevelObject<dealii::AffineConstraints<double>>       constraints;
    dealii::MGLevelObject<std::shared_ptr<LevelOperator>>          operators;
    /** Per level, the largest eigenvalue of D^-1 A the smoother was set
     * up with at the first update() since setup() (times 1.2), which the
     * later updates reuse. */
    std::vector<double> max_eigenvalues;
    /** The operators as the V-cycle applies them. */
    dealii::MGLevelObject<std::shared_ptr<SinglePrecisionLevel>> applied;
    LevelTransfer<dim>                                           transfer;
    bool                           transfer_ready = false;
    dealii::mg::Matrix<VectorType> mg_matrix;
    dealii::MGSmootherPrecondition<SinglePrecisionLevel, Smoother, VectorType>
                                                            smoother;
    dealii::TrilinosWrappers::SparseMatrix                  coarse_matrix;
    dealii::SolverControl                                   coarse_control;
    std::unique_ptr<dealii::TrilinosWrappers::SolverDirect> direct;
    std::unique_ptr<dealii::MGCoarseGridBase<VectorType>>   coarse;
    std::unique_ptr<dealii::Multigrid<VectorType>>          multigrid;
    std::unique_ptr<dealii::PreconditionMG<dim, VectorType, LevelTransfer<dim>>>
      preconditioner;
  };
} // namespace signorini

#endif
