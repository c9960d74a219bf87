#ifndef signorini_elasticity_cell_matrices_h
#define signorini_elasticity_cell_matrices_h

#include <array>
#include <cstddef>
#include <map>
#include <vector>

namespace signorini
{
  /**
   * The dense stiffness matrices of the distinct cell shapes of a mesh, for
   * the cells whose mapping is affine (a box or a parallelepiped): one
   * matrix for all cells of one shape, found by the cell's inverse Jacobian.
   * On a Kelly-refined box mesh that is one matrix per refinement level,
   * and applying one (n x n, n = 24 for a hexahedron) is a few dozen fused
   * multiply-adds on the wide registers the processor has (AVX-512, AVX2
   * with FMA, or SSE2, chosen by its features when the program starts:
   * cell_kernel_instruction_set()), where evaluating the cell at
   * its quadrature points is a few thousand scalar operations.
   */
  class CellMatrices
  {
  public:
    /** The key of a shape: the inverse Jacobian's entries (row by row). */
    using Key = std::vector<double>;

    static constexpr unsigned int none = static_cast<unsigned int>(-1);

    /** Empty, for matrices of size @p n (Q1: 8 in 2D, 24 in 3D; Q2: 18,
     * 81). */
    void
    reinit(const unsigned int n);

    void
    clear();

    /** The matrix of @p key, or `none`. */
    unsigned int
    find(const Key &key) const;

    /** Stores @p columns (n columns of n entries) as the matrix of @p key,
     * unless there are already `max_matrices`; returns its index or `none`. */
    unsigned int
    add(const Key &key, const std::vector<double> &columns);

    /** The matrix @p index, by columns (n columns of stride() entries,
     * the first n of each the column's). */
    const double *
    matrix(const unsigned int index) const;

    /** The length of a stored column: n, padded with zeros to whole
     * registers for Q2 (24 for n = 18, 96 for n = 81). */
    unsigned int
    column_stride() const
    {
      return stride;
    }

    /** y = K_index x (x and y of size n, not overlapping). */
    void
    apply(const unsigned int index, const double *x, double *y) const;

    /** y = K_index x in single precision (the matrix rounded to float):
     * twice the entries in a register, for a preconditioner. */
    void
    apply(const unsigned int index, const float *x, float *y) const;

    /** More distinct shapes than this (a distorted mesh) are evaluated at
     * quadrature points instead. */
    static constexpr unsigned int max_matrices = 512;

  private:
    unsigned int                n      = 0;
    unsigned int                stride = 0;
    std::map<Key, unsigned int> index_of;
    std::vector<double>         entries;
    /** The same entries rounded to float. */
    std::vector<float> single_entries;
  };

  /** The copy of the cell kernels this processor runs: "avx512f",
   * "x86-64-v3" (AVX2 and FMA) or "default" (SSE2), chosen by the
   * processor's features when the program starts. */
  const char *
  cell_kernel_instruction_set();
} // namespace signorini

#endif
