#include <deal.II/base/polynomial.h>
#include <deal.II/base/quadrature_lib.h>

#include <signorini/elasticity/curved_cells.h>

#include "wide_kernel.h"
#include <algorithm>
#include <cmath>

namespace signorini
{
  namespace curved_kernels
  {
    /** A register of 64 bytes: eight doubles, or sixteen floats. */
    template <typename Number>
    struct WideOf;
    template <>
    struct WideOf<double>
    {
      typedef double type __attribute__((vector_size(64)));
    };
    template <>
    struct WideOf<float>
    {
      typedef float type __attribute__((vector_size(64)));
    };
    template <typename Number>
    using Wide  = typename WideOf<Number>::type;
    using Lanes = Wide<double>;
    static_assert(CurvedCells::lanes * sizeof(double) == 64 &&
                    CurvedCells::single_lanes * sizeof(float) == 64,
                  "a batch fills a register of 64 bytes");

    /** out = M_dir in (or out += with @p add): the 1D matrix M (N x N,
     * [q][i]) along direction @p dir of an N^dim tensor, or its transpose
     * (out_i = sum_q M[q][i] in_q). */
    template <int  dim,
              int  N,
              int  dir,
              bool transpose,
              bool add = false,
              typename Number,
              typename Vector>
    inline __attribute__((always_inline)) void
    contract(const Number *M, const Vector *in, Vector *out)
    {
      constexpr int size   = dim == 2 ? N * N : N * N * N;
      constexpr int stride = dir == 0 ? 1 : dir == 1 ? N : N * N;
      // The matrix in registers: `out` may alias its numbers.
      Number m[N * N];
      for (int e = 0; e < N * N; ++e)
        m[e] = M[e];
      for (int outer = 0; outer < size; outer += N * stride)
        for (int inner = 0; inner < stride; ++inner)
          {
            const int base = outer + inner;
            Vector    line[N];
            for (int i = 0; i < N; ++i)
              line[i] = in[base + i * stride];
            for (int q = 0; q < N; ++q)
              {
                Vector sum = (transpose ? m[q] : m[q * N]) * line[0];
                for (int i = 1; i < N; ++i)
                  sum += (transpose ? m[i * N + q] : m[q * N + i]) * line[i];
                if (add)
                  out[base + q * stride] += sum;
                else
                  out[base + q * stride] = sum;
              }
          }
    }

    /** y = K x of a batch (see CurvedCells): the values interpolated to
     * the Gauss points (S along each direction), their gradients there
     * (the collocation derivative C along each), the stress tested the
     * same way back. */
    template <int dim, int N, typename Number, bool affine = false>
    inline __attribute__((always_inline)) void
    apply_batch(const Number       *S,
                const Number       *C,
                const Wide<Number> *B,
                const Number        mu,
                const Number        lambda,
                const Wide<Number> *x,
                Wide<Number>       *y,
                const Number       *weights = nullptr)
    {
      using Lanes      = Wide<Number>;
      constexpr int nq = dim == 2 ? N * N : N * N * N;
      // The gradients at the points G[c][k][q].
      Lanes G[dim][dim][nq], values[nq], scratch[nq];
      for (int c = 0; c < dim; ++c)
        {
          if constexpr (dim == 2)
            {
              contract<dim, N, 0, false>(S, x + c * nq, scratch);
              contract<dim, N, 1, false>(S, scratch, values);
            }
          else
            {
              contract<dim, N, 0, false>(S, x + c * nq, values);
              contract<dim, N, 1, false>(S, values, scratch);
              contract<dim, N, 2, false>(S, scratch, values);
            }
          contract<dim, N, 0, false>(C, values, G[c][0]);
          contract<dim, N, 1, false>(C, values, G[c][1]);
          if constexpr (dim == 3)
            contract<dim, N, 2, false>(C, values, G[c][dim - 1]);
        }
      // At each point: H = G B, sigma(H), T = sigma B^T, into G.
      for (int q = 0; q < nq; ++q)
        {
          // An affine batch: B_q = sqrt(w_q) B, its weight applied once.
          const Lanes *Bq = affine ? B : B + q * dim * dim;
          Lanes        H[dim][dim];
          for (int c = 0; c < dim; ++c)
            for (int j = 0; j < dim; ++j)
              {
                Lanes sum = G[c][0][q] * Bq[j];
                for (int k = 1; k < dim; ++k)
                  sum += G[c][k][q] * Bq[k * dim + j];
                H[c][j] = sum;
              }
          Lanes trace = H[0][0];
          for (int d = 1; d < dim; ++d)
            trace += H[d][d];
          Lanes sigma[dim][dim];
          for (int c = 0; c < dim; ++c)
            for (int j = 0; j < dim; ++j)
              sigma[c][j] = mu * (H[c][j] + H[j][c]);
          for (int d = 0; d < dim; ++d)
            sigma[d][d] += lambda * trace;
          for (int c = 0; c < dim; ++c)
            for (int k = 0; k < dim; ++k)
              {
                Lanes sum = sigma[c][0] * Bq[k * dim];
                for (int j = 1; j < dim; ++j)
                  sum += sigma[c][j] * Bq[k * dim + j];
                G[c][k][q] = affine ? weights[q] * sum : sum;
              }
        }
      // y_c = S^T (sum_k C_k^T T[c][k]).
      for (int c = 0; c < dim; ++c)
        {
          contract<dim, N, 0, true>(C, G[c][0], values);
          contract<dim, N, 1, true, true>(C, G[c][1], values);
          if constexpr (dim == 2)
            {
              contract<dim, N, 0, true>(S, values, scratch);
              contract<dim, N, 1, true>(S, scratch, y + c * nq);
            }
          else
            {
              contract<dim, N, 2, true, true>(C, G[c][dim - 1], values);
              contract<dim, N, 0, true>(S, values, scratch);
              contract<dim, N, 1, true>(S, scratch, values);
              contract<dim, N, 2, true>(S, values, y + c * nq);
            }
        }
    }

    /** h_j = sum_k G_k B_q[k][j]: a node's scaled physical gradient at a
     * point from its reference gradient @p G there. */
    template <int dim>
    inline __attribute__((always_inline)) void
    point_gradient(const double *G, const Lanes *Bq, Lanes *h)
    {
      for (int j = 0; j < dim; ++j)
        {
          Lanes sum = G[0] * Bq[j];
          for (int k = 1; k < dim; ++k)
            sum += G[k] * Bq[k * dim + j];
          h[j] = sum;
        }
    }

    /** The scaled physical gradients h[A][q][j] of each node A at each
     * point q, G the reference gradients [A][q][k]. */
    template <int dim, int N>
    inline __attribute__((always_inline)) void
    node_gradients(const double *G, const Lanes *B, Lanes *h)
    {
      constexpr int nq = dim == 2 ? N * N : N * N * N;
      for (int A = 0; A < nq; ++A)
        for (int q = 0; q < nq; ++q)
          point_gradient<dim>(G + (A * nq + q) * dim,
                              B + q * dim * dim,
                              h + (A * nq + q) * dim);
    }

    /** The diagonal of a batch's K: entry (c, A) is sum_q mu (|h_A|^2 +
     * h_A[c]^2) + lambda h_A[c]^2, h_A = G_A B_q (in registers). */
    template <int dim, int N>
    inline __attribute__((always_inline)) void
    diagonal_batch(const double *G,
                   const Lanes  *B,
                   const double  mu,
                   const double  lambda,
                   Lanes *,
                   Lanes *diagonal)
    {
      constexpr int nq = dim == 2 ? N * N : N * N * N;
      for (int A = 0; A < nq; ++A)
        {
          Lanes square[dim] = {};
          for (int q = 0; q < nq; ++q)
            {
              Lanes h[dim];
              point_gradient<dim>(G + (A * nq + q) * dim, B + q * dim * dim, h);
              for (int j = 0; j < dim; ++j)
                square[j] += h[j] * h[j];
            }
          Lanes norm = square[0];
          for (int j = 1; j < dim; ++j)
            norm += square[j];
          for (int c = 0; c < dim; ++c)
            diagonal[c * nq + A] = mu * norm + (mu + lambda) * square[c];
        }
    }

    /** A batch's K by blocks: entry ((c, A), (e, B)) is sum_q mu delta_ce
     * h_A . h_B + mu h_A[e] h_B[c] + lambda h_A[c] h_B[e], from
     * M = sum_q h_A h_B^T; K[(c * nq + A) * n + e * nq + B]. */
    template <int dim, int N>
    inline __attribute__((always_inline)) void
    matrix_batch(const double *G,
                 const Lanes  *B,
                 const double  mu,
                 const double  lambda,
                 Lanes        *h,
                 Lanes        *K)
    {
      constexpr int nq = dim == 2 ? N * N : N * N * N;
      constexpr int n  = dim * nq;
      node_gradients<dim, N>(G, B, h);
      for (int A = 0; A < nq; ++A)
        for (int Bn = A; Bn < nq; ++Bn)
          {
            Lanes M[dim][dim] = {};
            for (int q = 0; q < nq; ++q)
              {
                const Lanes *hA = h + (A * nq + q) * dim;
                const Lanes *hB = h + (Bn * nq + q) * dim;
                for (int i = 0; i < dim; ++i)
                  for (int j = 0; j < dim; ++j)
                    M[i][j] += hA[i] * hB[j];
              }
            Lanes trace = M[0][0];
            for (int d = 1; d < dim; ++d)
              trace += M[d][d];
            for (int c = 0; c < dim; ++c)
              for (int e = 0; e < dim; ++e)
                {
                  Lanes entry = mu * M[e][c] + lambda * M[c][e];
                  if (c == e)
                    entry += mu * trace;
                  K[(c * nq + A) * n + e * nq + Bn] = entry;
                  K[(e * nq + Bn) * n + c * nq + A] = entry;
                }
          }
    }

    // One plain function per case, which target_clones copies per
    // instruction set.
    // (Affine: Q2 cells that are parallelepipeds, one B a cell.)
#define SIGNORINI_CURVED_KERNEL(name, dim, N, Number, affine)                \
  SIGNORINI_WIDE_KERNEL void name(const Number       *S,                     \
                                  const Number       *C,                     \
                                  const Wide<Number> *B,                     \
                                  const Number        mu,                    \
                                  const Number        lambda,                \
                                  const Wide<Number> *x,                     \
                                  Wide<Number>       *y,                     \
                                  const Number       *weights)               \
  {                                                                          \
    apply_batch<dim, N, Number, affine>(S, C, B, mu, lambda, x, y, weights); \
  }
    SIGNORINI_CURVED_KERNEL(apply_quadrilaterals, 2, 2, double, false)
    SIGNORINI_CURVED_KERNEL(apply_quadrilaterals_q2, 2, 3, double, false)
    SIGNORINI_CURVED_KERNEL(apply_hexahedra, 3, 2, double, false)
    SIGNORINI_CURVED_KERNEL(apply_hexahedra_q2, 3, 3, double, false)
    SIGNORINI_CURVED_KERNEL(apply_quadrilaterals_single, 2, 2, float, false)
    SIGNORINI_CURVED_KERNEL(apply_quadrilaterals_q2_single, 2, 3, float, false)
    SIGNORINI_CURVED_KERNEL(apply_hexahedra_single, 3, 2, float, false)
    SIGNORINI_CURVED_KERNEL(apply_hexahedra_q2_single, 3, 3, float, false)
    SIGNORINI_CURVED_KERNEL(apply_parallelograms_q2, 2, 3, double, true)
    SIGNORINI_CURVED_KERNEL(apply_parallelepipeds_q2, 3, 3, double, true)
    SIGNORINI_CURVED_KERNEL(apply_parallelograms_q2_single, 2, 3, float, true)
    SIGNORINI_CURVED_KERNEL(apply_parallelepipeds_q2_single, 3, 3, float, true)
#undef SIGNORINI_CURVED_KERNEL
#define SIGNORINI_CURVED_SETUP(name, batch_function, dim, N) \
  SIGNORINI_WIDE_KERNEL void name(const double *G,           \
                                  const Lanes  *B,           \
                                  const double  mu,          \
                                  const double  lambda,      \
                                  Lanes        *h,           \
                                  Lanes        *out)         \
  {                                                          \
    batch_function<dim, N>(G, B, mu, lambda, h, out);        \
  }
    SIGNORINI_CURVED_SETUP(diagonal_2d_q1, diagonal_batch, 2, 2)
    SIGNORINI_CURVED_SETUP(diagonal_2d_q2, diagonal_batch, 2, 3)
    SIGNORINI_CURVED_SETUP(diagonal_3d_q1, diagonal_batch, 3, 2)
    SIGNORINI_CURVED_SETUP(diagonal_3d_q2, diagonal_batch, 3, 3)
    SIGNORINI_CURVED_SETUP(matrix_2d_q1, matrix_batch, 2, 2)
    SIGNORINI_CURVED_SETUP(matrix_2d_q2, matrix_batch, 2, 3)
    SIGNORINI_CURVED_SETUP(matrix_3d_q1, matrix_batch, 3, 2)
    SIGNORINI_CURVED_SETUP(matrix_3d_q2, matrix_batch, 3, 3)
#undef SIGNORINI_CURVED_SETUP
  } // namespace curved_kernels

  void
  CurvedCells::reinit(const unsigned int dim,
                      const unsigned int degree,
                      const double       mu,
                      const double       lambda,
                      const bool         affine)
  {
    AssertThrow(!affine || degree == 2,
                dealii::ExcMessage("affine batches are of degree 2"));
    this->dim    = dim;
    this->degree = degree;
    this->mu     = mu;
    this->lambda = lambda;
    this->affine = affine;
    n            = 0;
    geometry.clear();
    single_geometry.clear();
    // The 1D basis at the nodes 0, ..., 1 (lexicographic), at the Gauss
    // points of degree + 1.
    const unsigned int            N = degree + 1;
    std::vector<dealii::Point<1>> nodes(N);
    for (unsigned int i = 0; i < N; ++i)
      nodes[i][0] = double(i) / degree;
    const auto basis =
      dealii::Polynomials::generate_complete_Lagrange_basis(nodes);
    const dealii::QGauss<1> gauss(N);
    values.resize(N * N);
    derivatives.resize(N * N);
    std::vector<double> value_and_derivative(2);
    for (unsigned int q = 0; q < N; ++q)
      for (unsigned int i = 0; i < N; ++i)
        {
          basis[i].value(gauss.point(q)[0], value_and_derivative);
          values[q * N + i]      = value_and_derivative[0];
          derivatives[q * N + i] = value_and_derivative[1];
        }
    // The collocation derivative: the derivative of the Lagrange basis on
    // the Gauss points, at the Gauss points.
    const auto gauss_basis =
      dealii::Polynomials::generate_complete_Lagrange_basis(gauss.get_points());
    collocation.resize(N * N);
    for (unsigned int q = 0; q < N; ++q)
      for (unsigned int p = 0; p < N; ++p)
        {
          gauss_basis[p].value(gauss.point(q)[0], value_and_derivative);
          collocation[q * N + p] = value_and_derivative[1];
        }
    // The tensor-product Gauss weights, lexicographic.
    const unsigned int n_q = n_points();
    weights.assign(n_q, 1.);
    for (unsigned int q = 0; q < n_q; ++q)
      for (unsigned int d = 0, p = q; d < dim; ++d, p /= N)
        weights[q] *= gauss.weight(p % N);
    single_weights.assign(weights.begin(), weights.end());
    single_values.assign(values.begin(), values.end());
    single_collocation.assign(collocation.begin(), collocation.end());
    // Node A's reference gradient at point q (digits of A and q, the
    // first fastest): G[(A * n_q + q) * dim + k].
    reference_gradients.resize(n_q * n_q * dim);
    for (unsigned int A = 0; A < n_q; ++A)
      for (unsigned int q = 0; q < n_q; ++q)
        for (unsigned int k = 0; k < dim; ++k)
          {
            double       product = 1.;
            unsigned int a = A, p = q;
            for (unsigned int d = 0; d < dim; ++d, a /= N, p /= N)
              product *= (d == k ? derivatives : values)[(p % N) * N + a % N];
            reference_gradients[(A * n_q + q) * dim + k] = product;
          }
  }

  void
  CurvedCells::clear()
  {
    n      = 0;
    affine = false;
    geometry.clear();
    single_geometry.clear();
  }

  unsigned int
  CurvedCells::add(const std::vector<double> &B)
  {
    const unsigned int per_batch = B.size() * lanes;
    if (n % lanes == 0)
      geometry.resize(geometry.size() + per_batch, 0.);
    double *batch = geometry.data() + (n / lanes) * per_batch;
    for (std::size_t e = 0; e < B.size(); ++e)
      batch[e * lanes + n % lanes] = B[e];
    const unsigned int per_single = B.size() * single_lanes;
    if (n % single_lanes == 0)
      single_geometry.resize(single_geometry.size() + per_single, 0.f);
    float *single = single_geometry.data() + (n / single_lanes) * per_single;
    for (std::size_t e = 0; e < B.size(); ++e)
      single[e * single_lanes + n % single_lanes] = B[e];
    return n++;
  }

  unsigned int
  CurvedCells::n_cells() const
  {
    return n;
  }

  unsigned int
  CurvedCells::cell_entries() const
  {
    return affine ? dim * dim : n_points() * dim * dim;
  }

  unsigned int
  CurvedCells::n_points() const
  {
    unsigned int n_q = 1;
    for (unsigned int d = 0; d < dim; ++d)
      n_q *= degree + 1;
    return n_q;
  }

  const double *
  CurvedCells::point_geometry(const unsigned int batch) const
  {
    const unsigned int n_q = n_points(), entries = dim * dim;
    if (!affine)
      return geometry.data() + std::size_t(batch) * n_q * entries * lanes;
    // B_q = sqrt(w_q) B.
    expanded.resize(std::size_t(n_q) * entries * lanes);
    const double *B = geometry.data() + std::size_t(batch) * entries * lanes;
    for (unsigned int q = 0; q < n_q; ++q)
      for (unsigned int e = 0; e < entries * lanes; ++e)
        expanded[q * entries * lanes + e] = std::sqrt(weights[q]) * B[e];
    return expanded.data();
  }

  void
  CurvedCells::diagonals(const unsigned int batch, double *diagonal) const
  {
    from_gradients(batch, false, diagonal);
  }

  void
  CurvedCells::matrices(const unsigned int batch, double *K) const
  {
    from_gradients(batch, true, K);
  }

  void
  CurvedCells::from_gradients(const unsigned int batch,
                              const bool         whole,
                              double            *out) const
  {
    using curved_kernels::Lanes;
    const unsigned int n_q = n_points();
    const auto *B = reinterpret_cast<const Lanes *>(point_geometry(batch));
    Lanes      *h = nullptr;
    if (whole)
      {
        scratch.resize(std::size_t(n_q) * n_q * dim * lanes);
        h = reinterpret_cast<Lanes *>(scratch.data());
      }
    using Function =
      void (*)(const double *, const Lanes *, double, double, Lanes *, Lanes *);
    // [whole][dim - 2][degree - 1]
    const Function functions[2][2][2] = {
      {{curved_kernels::diagonal_2d_q1, curved_kernels::diagonal_2d_q2},
       {curved_kernels::diagonal_3d_q1, curved_kernels::diagonal_3d_q2}},
      {{curved_kernels::matrix_2d_q1, curved_kernels::matrix_2d_q2},
       {curved_kernels::matrix_3d_q1, curved_kernels::matrix_3d_q2}}};
    functions[whole][dim - 2][degree - 1](reference_gradients.data(),
                                          B,
                                          mu,
                                          lambda,
                                          h,
                                          reinterpret_cast<Lanes *>(out));
  }

  void
  CurvedCells::apply(const unsigned int batch, const double *x, double *y) const
  {
    const auto *B =
      reinterpret_cast<const curved_kernels::Lanes *>(geometry.data()) +
      std::size_t(batch) * cell_entries();
    const auto   *in  = reinterpret_cast<const curved_kernels::Lanes *>(x);
    auto         *out = reinterpret_cast<curved_kernels::Lanes *>(y);
    const double *S = values.data(), *C = collocation.data();
    if (affine)
      (dim == 2 ? curved_kernels::apply_parallelograms_q2 :
                  curved_kernels::apply_parallelepipeds_q2)(
        S, C, B, mu, lambda, in, out, weights.data());
    else if (dim == 2)
      (degree == 1 ? curved_kernels::apply_quadrilaterals :
                     curved_kernels::apply_quadrilaterals_q2)(
        S, C, B, mu, lambda, in, out, weights.data());
    else
      (degree == 1 ? curved_kernels::apply_hexahedra :
                     curved_kernels::apply_hexahedra_q2)(
        S, C, B, mu, lambda, in, out, weights.data());
  }

  void
  CurvedCells::apply_single(const unsigned int batch,
                            const float       *x,
                            float             *y) const
  {
    using Lanes   = curved_kernels::Wide<float>;
    const auto *B = reinterpret_cast<const Lanes *>(single_geometry.data()) +
                    std::size_t(batch) * cell_entries();
    const auto  *in  = reinterpret_cast<const Lanes *>(x);
    auto        *out = reinterpret_cast<Lanes *>(y);
    const float *S = single_values.data(), *C = single_collocation.data();
    const float  m = mu, l = lambda;
    if (affine)
      (dim == 2 ? curved_kernels::apply_parallelograms_q2_single :
                  curved_kernels::apply_parallelepipeds_q2_single)(
        S, C, B, m, l, in, out, single_weights.data());
    else if (dim == 2)
      (degree == 1 ? curved_kernels::apply_quadrilaterals_single :
                     curved_kernels::apply_quadrilaterals_q2_single)(
        S, C, B, m, l, in, out, single_weights.data());
    else
      (degree == 1 ? curved_kernels::apply_hexahedra_single :
                     curved_kernels::apply_hexahedra_q2_single)(
        S, C, B, m, l, in, out, single_weights.data());
  }

} // namespace signorini
