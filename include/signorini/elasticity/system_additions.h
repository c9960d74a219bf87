#ifndef signorini_elasticity_system_additions_h
#define signorini_elasticity_system_additions_h

#include <deal.II/base/index_set.h>
#include <deal.II/base/tensor.h>
#include <deal.II/base/types.h>
#include <deal.II/lac/affine_constraints.h>

#include <array>
#include <cstddef>
#include <utility>
#include <vector>

namespace signorini
{
  /**
   * What a law adds to the elastic system K u = f for one Newton step, in
   * plain linear algebra: the door between contact (or any other law that
   * acts at vertices) and the elastic operators, which know nothing else of
   * it. Every index is a global displacement dof.
   *
   * - Constraint lines: x_dof = sum weight x_master + inhomogeneity, as
   *   AffineConstraints holds them (a node held on an obstacle, a node that
   *   sticks); merged with the discretisation's constraints, these win.
   *   A line may have test weights of its own (Petrov-Galerkin): the
   *   equation of its dof then enters its masters' equations with those
   *   weights rather than the line's (a slipping node's, whose tangential
   *   equation binds its tangential force to its normal force); the
   *   system is then not symmetric.
   * - Constraint springs: the same constraints as stiff springs, for the
   *   parts of a solver that cannot hold constraints (the coarser levels of
   *   a geometric multigrid): a stiffness d d^T at a vertex, scaled by the
   *   operator's diagonal at `scale_dof`.
   * - Blocks: a small dense matrix added at rows x columns (a vertex's dofs,
   *   or one vertex's rows and another's columns), possibly non-symmetric,
   *   with a right-hand side at its rows. Rows at constrained dofs do not
   *   enter; a column at a constrained dof enters through its constraint
   *   (its masters', and its inhomogeneity on the right-hand side; the
   *   matrix-free operator: at fixed values only).
   * - Forces: right-hand-side entries that do not change the matrix (the
   *   multipliers of an augmented Lagrangian); not at constrained dofs.
   */
  template <int dim>
  struct SystemAdditions
  {
    using Index = dealii::types::global_dof_index;

    struct ConstraintLine
    {
      Index                                 dof;
      std::vector<std::pair<Index, double>> entries;
      double                                inhomogeneity = 0.;
      /** Whether the test weights differ from the entries, and those
       * weights (the dofs whose equations receive this dof's). */
      bool                                  petrov_galerkin = false;
      std::vector<std::pair<Index, double>> test_entries;
    };

    struct ConstraintSpring
    {
      std::array<Index, dim> dofs;
      /** Unit direction d: the spring is k d d^T. */
      dealii::Tensor<1, dim> direction;
      /** Where the operator's diagonal gives k. */
      Index scale_dof;
    };

    struct Block
    {
      std::array<Index, dim>                   rows;
      std::array<Index, dim>                   columns;
      std::array<std::array<double, dim>, dim> matrix = {};
      /** Added to the right-hand side at the rows [N]. */
      std::array<double, dim> rhs = {};
    };

    struct Force
    {
      Index  dof;
      double value;
    };

    /** What the matrix depends on: equal keys, equal matrices, so that a
     * matrix and its factorisation or preconditioner are kept. */
    using Key = std::pair<std::pair<unsigned int, std::size_t>, double>;

    /** Every line a process knows (of its locally relevant dofs). */
    std::vector<ConstraintLine> constraints;
    /** At owned scale dofs. */
    std::vector<ConstraintSpring> constraint_springs;
    /** At owned rows. */
    std::vector<Block> blocks;
    /** At owned dofs. */
    std::vector<Force> forces;
    /** Whether any process has blocks, forces, or lines with test weights
     * of their own (the same on every process). */
    bool has_blocks       = false;
    bool has_forces       = false;
    bool has_test_weights = false;
    /** Whether the system stays symmetric (CG), or not (GMRES); the same on
     * every process. */
    bool symmetric = true;
    Key  key       = {};
    /** Whether a change of key with the same second entry changes only the
     * rows and columns of a few vertices (a preconditioner may be kept). */
    bool local_changes = false;

    /** Adds the constraint lines to @p constraints, in their order. */
    void
    add_constraints(dealii::AffineConstraints<double> &constraints) const;

    /** Adds the constraint lines with their test weights (those that have
     * them; the others as they are) to @p constraints: the constraints of
     * the equations' side of a Petrov-Galerkin condensation. */
    void
    add_test_constraints(dealii::AffineConstraints<double> &constraints) const;

    /** @p lines anew over the @p relevant dofs: the constraint lines (with
     * their test weights if @p test_weights) merged with @p given (the
     * discretisation's hanging-node and Dirichlet constraints; these lines
     * win), closed. */
    void
    close(dealii::AffineConstraints<double>       &lines,
          const dealii::AffineConstraints<double> &given,
          const dealii::IndexSet                  &relevant,
          const bool                               test_weights) const;
  };
} // namespace signorini

#endif
