#include <signorini/elasticity/cell_matrices.h>

#include "wide_kernel.h"
#include <algorithm>

namespace signorini
{
  namespace
  {
#if defined(__GNUC__) && defined(__x86_64__) && !defined(__clang__)
    // The choice of SIGNORINI_WIDE_KERNEL (wide_kernel.h), by the same rule,
    // told by name.
    __attribute__((target("default"))) const char *
    instruction_set()
    {
      return "default";
    }

    __attribute__((target(SIGNORINI_AVX2))) const char *
    instruction_set()
    {
      return "x86-64-v3";
    }

    __attribute__((target(SIGNORINI_AVX512))) const char *
    instruction_set()
    {
      return "avx512f";
    }
#else
    const char *
    instruction_set()
    {
      return "default";
    }
#endif

    /** y = K x, K stored by columns, a column's n entries @p stride apart
     * (zeros between: a padded column fills whole registers, where 81 rows
     * left the compiler to scalar code): a column times x_j at a time.
     * Always inlined, so that each kernel's copy compiles it for its own
     * instruction set (left to itself, the compiler calls one SSE2 copy at
     * n = 81). */
    template <unsigned int n, unsigned int stride, typename Number>
    inline __attribute__((always_inline)) void
    apply_columns(const Number *__restrict K,
                  const Number *__restrict x,
                  Number *__restrict y)
    {
      Number sum[stride];
      for (unsigned int i = 0; i < stride; ++i)
        sum[i] = K[i] * x[0];
      for (unsigned int j = 1; j < n; ++j)
        for (unsigned int i = 0; i < stride; ++i)
          sum[i] += K[j * stride + i] * x[j];
      for (unsigned int i = 0; i < n; ++i)
        y[i] = sum[i];
    }

    // The kernels of Q1's quadrilateral (n = 8) and hexahedron (n = 24),
    // and of Q2's (18 and 81, padded to 24 and 96), in Number: plain
    // functions, which target_clones copies per instruction set.
#define SIGNORINI_CELL_KERNELS(Number)                                       \
  SIGNORINI_WIDE_KERNEL void apply_quadrilateral(const Number *__restrict K, \
                                                 const Number *__restrict x, \
                                                 Number *__restrict y)       \
  {                                                                          \
    apply_columns<8, 8>(K, x, y);                                            \
  }                                                                          \
  SIGNORINI_WIDE_KERNEL void apply_hexahedron(const Number *__restrict K,    \
                                              const Number *__restrict x,    \
                                              Number *__restrict y)          \
  {                                                                          \
    apply_columns<24, 24>(K, x, y);                                          \
  }                                                                          \
  SIGNORINI_WIDE_KERNEL void apply_quadrilateral_q2(                         \
    const Number *__restrict K,                                              \
    const Number *__restrict x,                                              \
    Number *__restrict y)                                                    \
  {                                                                          \
    apply_columns<18, 24>(K, x, y);                                          \
  }                                                                          \
  SIGNORINI_WIDE_KERNEL void apply_hexahedron_q2(const Number *__restrict K, \
                                                 const Number *__restrict x, \
                                                 Number *__restrict y)       \
  {                                                                          \
    apply_columns<81, 96>(K, x, y);                                          \
  }

    SIGNORINI_CELL_KERNELS(double)
    // Single precision: twice the entries per register, half the bytes.
    SIGNORINI_CELL_KERNELS(float)
#undef SIGNORINI_CELL_KERNELS

    /** The padded length of a column of n entries (see apply_columns()). */
    unsigned int
    padded(const unsigned int n)
    {
      return n == 18 ? 24 : n == 81 ? 96 : n;
    }

    template <typename Number>
    void
    apply_any(const unsigned int n,
              const Number *__restrict K,
              const Number *__restrict x,
              Number *__restrict y)
    {
      for (unsigned int i = 0; i < n; ++i)
        y[i] = 0.;
      for (unsigned int j = 0; j < n; ++j)
        for (unsigned int i = 0; i < n; ++i)
          y[i] += K[j * n + i] * x[j];
    }

    /** y = K x by the kernel of its size. */
    template <typename Number>
    void
    apply_matrix(const unsigned int n,
                 const Number      *K,
                 const Number      *x,
                 Number            *y)
    {
      if (n == 24)
        apply_hexahedron(K, x, y);
      else if (n == 8)
        apply_quadrilateral(K, x, y);
      else if (n == 81)
        apply_hexahedron_q2(K, x, y);
      else if (n == 18)
        apply_quadrilateral_q2(K, x, y);
      else
        apply_any(n, K, x, y);
    }
  } // namespace

  const char *
  cell_kernel_instruction_set()
  {
    return instruction_set();
  }

  void
  CellMatrices::reinit(const unsigned int size)
  {
    clear();
    n      = size;
    stride = padded(n);
  }

  void
  CellMatrices::clear()
  {
    index_of.clear();
    entries.clear();
    entries.shrink_to_fit();
    single_entries.clear();
    single_entries.shrink_to_fit();
  }

  unsigned int
  CellMatrices::find(const Key &key) const
  {
    const auto found = index_of.find(key);
    return found == index_of.end() ? none : found->second;
  }

  unsigned int
  CellMatrices::add(const Key &key, const std::vector<double> &columns)
  {
    if (index_of.size() >= max_matrices)
      return none;
    const unsigned int index = index_of.size();
    index_of.emplace(key, index);
    for (unsigned int j = 0; j < n; ++j)
      {
        entries.insert(entries.end(),
                       columns.begin() + j * n,
                       columns.begin() + (j + 1) * n);
        entries.resize(entries.size() + stride - n, 0.);
      }
    single_entries.insert(single_entries.end(),
                          entries.end() - std::size_t(n) * stride,
                          entries.end());
    return index;
  }

  const double *
  CellMatrices::matrix(const unsigned int index) const
  {
    return entries.data() + std::size_t(index) * n * stride;
  }

  void
  CellMatrices::apply(const unsigned int index,
                      const double      *x,
                      double            *y) const
  {
    apply_matrix(n, matrix(index), x, y);
  }

  void
  CellMatrices::apply(const unsigned int index, const float *x, float *y) const
  {
    apply_matrix(n,
                 single_entries.data() + std::size_t(index) * n * stride,
                 x,
                 y);
  }
} // namespace signorini
