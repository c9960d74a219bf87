#ifndef signorini_elasticity_level_transfer_h
#define signorini_elasticity_level_transfer_h

#include <deal.II/base/mg_level_object.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/la_parallel_vector.h>
#include <deal.II/multigrid/mg_base.h>
#include <deal.II/multigrid/mg_transfer_global_coarsening.h>

#include <signorini/elasticity/cell_matrices.h>

#include <functional>
#include <memory>
#include <vector>

namespace signorini
{
  /**
   * The transfer between the levels of ElasticMultigrid, meshes each
   * refining the one below it at most once (coarsening_sequence), done cell
   * by cell: a coarse cell is either a cell of the finer mesh or the parent
   * of its children there, and the finer values are the coarse cell's
   * interpolated by the element's embedding matrices (its hanging nodes and
   * Dirichlet dofs resolved first, the finer level's constrained dofs
   * zero); restriction is the transpose. Each process handles the finer
   * cells it owns; the coarse cells it does not have (the two meshes are
   * partitioned each on its own) are asked of their owners once, at
   * setup.
   *
   * A level of degree 2 above one of degree 1 on the same mesh (the
   * p-step of a Q2 operator's multigrid) is transferred the same way,
   * cell by cell, its embedding the interpolation of Q1 at Q2's nodes.
   *
   * It replaces deal.II's MGTwoLevelTransfer, which finds the coarse cells
   * through a table over every cell the mesh's levels could have: 4 bytes
   * times 8^L for L levels, 537 MB at 9 levels (sphere_indentation at
   * 493,287 dofs) and 4.3 GB at 10, where this one holds about 28 indices
   * per finer cell (its 24 dofs, its embedding, its share of its coarse
   * cell's 24 dofs). deal.II's is kept for meshes that are not nested so.
   */
  template <int dim>
  class LevelTransfer : public dealii::MGTransferBase<
                          dealii::LinearAlgebra::distributed::Vector<double>>
  {
  public:
    using VectorType = dealii::LinearAlgebra::distributed::Vector<double>;

    /** Levels 0 (coarsest) to dofs.size() - 1 with their constraints and
     * how to make a vector of a level. */
    void
    reinit(
      const std::vector<const dealii::DoFHandler<dim> *>           &dofs,
      const std::vector<const dealii::AffineConstraints<double> *> &constraints,
      const std::function<void(const unsigned int, VectorType &)>  &initialize);

    void
    clear();

    void
    prolongate(const unsigned int to_level,
               VectorType        &dst,
               const VectorType  &src) const override;

    void
    restrict_and_add(const unsigned int from_level,
                     VectorType        &dst,
                     const VectorType  &src) const override;

    /** The fine vector to the top level; the others zero. */
    template <class InVector>
    void
    copy_to_mg(const dealii::DoFHandler<dim> &,
               dealii::MGLevelObject<VectorType> &dst,
               const InVector                    &src) const
    {
      for (unsigned int level = dst.min_level(); level <= dst.max_level();
           ++level)
        {
          initialize(level, dst[level]);
          if (level == dst.max_level())
            dst[level].copy_locally_owned_data_from(src);
          else
            dst[level] = 0.;
        }
    }

    /** The top level to the fine vector. */
    template <class OutVector>
    void
    copy_from_mg(const dealii::DoFHandler<dim> &,
                 OutVector                               &dst,
                 const dealii::MGLevelObject<VectorType> &src) const
    {
      dst.copy_locally_owned_data_from(src[src.max_level()]);
    }

  private:
    /** One level and the one below it, cell by cell. */
    struct CellwisePair
    {
      /** The dofs per finer and per coarse cell. */
      unsigned int n_fine   = 0;
      unsigned int n_coarse = 0;
      /** An entry of `raise`: finer dof, coarse dof, weight. */
      struct RaiseEntry
      {
        unsigned int fine;
        unsigned int coarse;
        double       weight;
      };
      /** Where the finer level's degree is higher (the same mesh): the
       * interpolation of a coarse cell's values at the finer cell's nodes,
       * its nonzero entries (192 of Q2's 81 x 24 in 3D); else empty. */
      std::vector<RaiseEntry> raise;
      /** Per owned finer cell: its dofs (local indices, `none` where not
       * owned here) and which embedding (a child number, or `identity`),
       * `| new_patch` where its coarse cell is not the previous finer
       * cell's. */
      std::vector<unsigned int> fine_dofs;
      std::vector<unsigned int> embedding;
      /** Per coarse cell, in the order of their finer cells: its dofs
       * (local indices of coarse_values). Siblings come one after the
       * other, so a parent's dofs are held once, not once per child. */
      std::vector<unsigned int> coarse_dofs;
      /** 1 / the number of owned finer cells at an owned dof; 0 at
       * constrained dofs. */
      std::vector<double>       fine_weights;
      std::vector<unsigned int> fine_constrained;
      /** The coarse level's constraints of its owned dofs (local indices):
       * a dof and its masters. */
      std::vector<
        std::pair<unsigned int, std::vector<std::pair<unsigned int, double>>>>
        coarse_lines;
      /** The coarse level's values at its owned dofs and at the dofs of
       * the coarse cells of the owned finer cells. */
      mutable VectorType coarse_values;
    };

    /** Sets up cellwise[level]; false if a coarse cell is missing or not
     * the finer cell or its parent (on any process). */
    bool
    setup_pair(const unsigned int                       level,
               const dealii::DoFHandler<dim>           &coarse,
               const dealii::DoFHandler<dim>           &fine,
               const dealii::AffineConstraints<double> &coarse_constraints,
               const dealii::AffineConstraints<double> &fine_constraints);

    static constexpr unsigned int identity  = 0x7fffffffu;
    static constexpr unsigned int new_patch = 0x80000000u;
    static constexpr unsigned int none      = static_cast<unsigned int>(-1);

    std::function<void(const unsigned int, VectorType &)> initialize;
    /** Indexed by the finer level. */
    std::vector<CellwisePair> cellwise;
    dealii::MGLevelObject<dealii::MGTwoLevelTransfer<dim, VectorType>>
      distributed;
    /** Whether deal.II's transfer is used. */
    bool by_dealii = false;
    /** The embeddings (child c) and their transposes (child c +
     * children per cell) of the levels of degree 1. */
    CellMatrices embeddings;
    /** The most dofs a cell has (Q2 in 3D). */
    static constexpr unsigned int max_cell_dofs = 81;
  };
} // namespace signorini

#endif
