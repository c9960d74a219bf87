#ifndef signorini_elasticity_curved_cells_h
#define signorini_elasticity_curved_cells_h

#include <deal.II/base/aligned_vector.h>

#include <cstddef>
#include <vector>

namespace signorini
{
  /**
   * The elastic operator of the cells that have no shape matrix (curved
   * cells, which are no image of a reference shape under an affine map),
   * evaluated by sum factorisation at their Gauss points, eight cells at a
   * time, one in each lane of a vector of eight doubles (an AVX-512
   * register; two of AVX2, four of SSE2). Debian's deal.II evaluates cells
   * one at a time (its VectorizedArray holds one double), so this class
   * does what its FEEvaluation would with eight lanes, for Q1 and Q2 in 2D
   * and 3D.
   *
   * A cell is stored by its geometry alone: at each Gauss point q the
   * matrix B_q = sqrt(JxW_q) J_q^{-1}, (B_q)_kj = sqrt(JxW_q) d xi_k/d x_j.
   * The gradient of u at q is G_q B_q / sqrt(JxW_q) with G_q its reference
   * gradient, so the cell's K u is sum_q [(sigma(G_q B_q) B_q^T) tested by
   * the reference gradients], JxW included once.
   *
   * The gradients at the points come from the values there (the 1D basis
   * along each direction) and the collocation derivative on the Gauss
   * points: 6 one-dimensional contractions per component each way where
   * a derivative or value along each direction of each gradient takes 9
   * (Q2 in 3D, 8,856 cells applied in turn on an AVX-512 Xeon: 320 -> 200
   * ns per cell; in single precision, sixteen at a time, 91 ns).
   *
   * The smoother's diagonal (diagonals()) and, where constraints couple a
   * cell's dofs, its whole matrix (matrices()) come from the gradients of
   * the nodes' shape functions at the points, not from the operator
   * applied to unit vectors (81 applications a batch for Q2 in 3D).
   *
   * Cells are added in the order in which they are applied; cell r is lane
   * r % lanes of batch r / lanes.
   */
  class CurvedCells
  {
  public:
    static constexpr unsigned int lanes = 8;
    /** The cells of a batch in single precision (apply_single()). */
    static constexpr unsigned int single_lanes = 16;

    /** No cells; the element's @p degree (1 or 2) in @p dim dimensions, the
     * Lamé constants @p mu and @p lambda. With @p affine (degree 2 only)
     * every cell is a parallelogram or parallelepiped, given by one B =
     * sqrt(det J) J^{-1} (B_q = sqrt(w_q) B, w_q the Gauss weight): 9
     * numbers a cell instead of 243, and Q2 cells of a box at about half
     * the cost of their 81 x 81 matrix. */
    void
    reinit(const unsigned int dim,
           const unsigned int degree,
           const double       mu,
           const double       lambda,
           const bool         affine = false);

    /** Forgets the cells, their geometry and the affine mode. */
    void
    clear();

    /** Adds the next cell by its B_q, entry (q * dim + k) * dim + j (in
     * affine batches its one B, entry k * dim + j); returns its number. */
    unsigned int
    add(const std::vector<double> &B);

    unsigned int
    n_cells() const;

    /** y = K x for the cells of @p batch, x and y by dof, then lane
     * (x[i * lanes + l]), both aligned to 64 bytes (AlignedVector's); a
     * lane without a cell has no entries that matter. */
    void
    apply(const unsigned int batch, const double *x, double *y) const;

    /** apply() in single precision, sixteen cells at a time: cell r is
     * lane r % single_lanes of @p batch r / single_lanes (about 1e-7
     * relative, for the multigrid's smoothing; twice the cells per
     * instruction and half the bytes of the geometry). */
    void
    apply_single(const unsigned int batch, const float *x, float *y) const;

    /** The diagonals of the cells of @p batch, by dof, then lane
     * (diagonal[i * lanes + l]), aligned to 64 bytes: from the gradients
     * at the points, without applying the operator to unit vectors. */
    void
    diagonals(const unsigned int batch, double *diagonal) const;

    /** The stiffness matrices of the cells of @p batch, entry (i, j) of
     * lane l at K[(i * n + j) * lanes + l] (n dofs per cell), aligned to
     * 64 bytes; symmetric. */
    void
    matrices(const unsigned int batch, double *K) const;

  private:
    /** The Gauss points per cell. */
    unsigned int
    n_points() const;

    /** diagonals(), or with @p whole matrices(). */
    void
    from_gradients(const unsigned int batch,
                   const bool         whole,
                   double            *out) const;

    /** The geometry's numbers per cell and lane. */
    unsigned int
    cell_entries() const;

    /** The B_q of @p batch, [q][k][j][lane] (expanded for an affine
     * batch). */
    const double *
    point_geometry(const unsigned int batch) const;

    bool affine = false;
    /** The Gauss weights, lexicographic (affine batches). */
    std::vector<double> weights;
    std::vector<float>  single_weights;
    /** An affine batch's B_q (point_geometry()). */
    mutable dealii::AlignedVector<double> expanded;

    unsigned int dim    = 0;
    unsigned int degree = 0;
    double       mu     = 0.;
    double       lambda = 0.;
    unsigned int n      = 0;
    /** The 1D Lagrange basis at its nodes (0, 1/2, 1 at degree 2) and its
     * derivative, at the Gauss points: [q][i]. */
    std::vector<double> values, derivatives;
    /** The derivative of the Lagrange basis on the Gauss points, at the
     * Gauss points: [q][p]. */
    std::vector<double> collocation;
    /** Each node's reference gradient at each point:
     * [node][q][k], nodes and points lexicographic. */
    std::vector<double> reference_gradients;
    /** B of each batch: [batch][q][k][j][lane], aligned to 64 bytes. */
    dealii::AlignedVector<double> geometry;
    /** The same in single precision, [batch][q][k][j][single lane]. */
    dealii::AlignedVector<float> single_geometry;
    /** values and collocation in single precision. */
    std::vector<float> single_values, single_collocation;
    /** The nodes' gradients at the points, for matrices(). */
    mutable dealii::AlignedVector<double> scratch;
  };
} // namespace signorini

#endif
