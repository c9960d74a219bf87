// CellStiffness: the Q1 element matrix of a unit square against the
// textbook closed form, and of a unit cube against the integrals of its
// tensor-product shape functions written out by hand; symmetry, the
// rigid-body modes in its kernel, the energy of a uniform strain, the
// scaling K(s x) = s^(dim-2) K(x), and the cache for translated and scaled
// copies of a cell.

#include <deal.II/base/quadrature_lib.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/tria.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/lapack_full_matrix.h>
#include <deal.II/lac/vector.h>

#include <signorini/elasticity/cell_stiffness.h>
#include <signorini/elasticity/material.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <iomanip>
#include <iostream>
#include <string>
#include <vector>

using namespace dealii;
using namespace signorini;

namespace
{
  // E = 2.6, nu = 0.3: mu = 1, lambda = 1.5 (plane strain and 3D).
  constexpr double E  = 2.6;
  constexpr double nu = 0.3;

  double
  max_abs(const FullMatrix<double> &a)
  {
    double m = 0.;
    for (unsigned int i = 0; i < a.m(); ++i)
      for (unsigned int j = 0; j < a.n(); ++j)
        m = std::max(m, std::abs(a(i, j)));
    return m;
  }

  double
  max_difference(const FullMatrix<double> &a, const FullMatrix<double> &b)
  {
    FullMatrix<double> d(a);
    d.add(-1., b);
    return max_abs(d);
  }

  void
  report(const std::string &what, const double difference, const double tol)
  {
    std::cout << "  " << what << ": " << std::scientific << std::setprecision(1)
              << difference << (difference <= tol ? "  (ok)" : "  (FAILED)")
              << std::defaultfloat << std::setprecision(10) << '\n';
  }

  /** The position of dof @p i's support point and its component. */
  template <int dim>
  std::pair<Point<dim>, unsigned int>
  support(const FiniteElement<dim> &fe, const unsigned int i)
  {
    return {fe.get_unit_support_points()[i],
            fe.system_to_component_index(i).first};
  }

  /**
   * The textbook stiffness matrix of a square Q1 element of unit thickness
   * in plane stress (e.g. Sigmund's 99-line topology optimisation code),
   * nodes counter-clockwise from (0,0), dofs (u1, v1, u2, v2, ...):
   * K = E / (1 - nu^2) [k_{p(i,j)}] with the eight numbers k below. Its
   * size does not matter in 2D.
   */
  FullMatrix<double>
  textbook_plane_stress(const double E, const double nu)
  {
    const double       k[8]    = {1. / 2 - nu / 6,
                                  1. / 8 + nu / 8,
                                  -1. / 4 - nu / 12,
                                  -1. / 8 + 3 * nu / 8,
                                  -1. / 4 + nu / 12,
                                  -1. / 8 - nu / 8,
                                  nu / 6,
                                  1. / 8 - 3 * nu / 8};
    const unsigned int p[8][8] = {{1, 2, 3, 4, 5, 6, 7, 8},
                                  {2, 1, 8, 7, 6, 5, 4, 3},
                                  {3, 8, 1, 6, 7, 4, 5, 2},
                                  {4, 7, 6, 1, 8, 3, 2, 5},
                                  {5, 6, 7, 8, 1, 2, 3, 4},
                                  {6, 5, 4, 3, 2, 1, 8, 7},
                                  {7, 4, 5, 2, 3, 8, 1, 6},
                                  {8, 3, 2, 5, 4, 7, 6, 1}};
    FullMatrix<double> K(8, 8);
    for (unsigned int i = 0; i < 8; ++i)
      for (unsigned int j = 0; j < 8; ++j)
        K(i, j) = E / (1 - nu * nu) * k[p[i][j] - 1];
    return K;
  }

  /** The textbook matrix in deal.II's dof order. */
  FullMatrix<double>
  textbook_in_fe_order(const FiniteElement<2> &fe, const FullMatrix<double> &K)
  {
    // Textbook node of a vertex of the unit square.
    const auto node = [](const Point<2> &p) {
      const unsigned int x = std::lround(p[0]), y = std::lround(p[1]);
      return y == 0 ? x : 3 - x;
    };
    FullMatrix<double> M(fe.n_dofs_per_cell(), fe.n_dofs_per_cell());
    for (unsigned int i = 0; i < M.m(); ++i)
      for (unsigned int j = 0; j < M.n(); ++j)
        {
          const auto [pi, ci] = support(fe, i);
          const auto [pj, cj] = support(fe, j);
          M(i, j)             = K(2 * node(pi) + ci, 2 * node(pj) + cj);
        }
    return M;
  }

  /**
   * The stiffness matrix of the unit hypercube, from its definition
   *   K(ic, je) = lambda int d_c N_i d_e N_j
   *             + mu int (d_e N_i d_c N_j + delta_ce grad N_i . grad N_j)
   * with N_i = prod_d f_id(x_d), f = x or 1 - x (slope s = +-1), and the
   * one-dimensional integrals int f_i' f_j' = s_i s_j, int f_i' f_j = s_i/2,
   * int f_i f_j = 1/3 (same end) or 1/6 (other end).
   */
  template <int dim>
  FullMatrix<double>
  unit_cube_by_hand(const FiniteElement<dim> &fe,
                    const double              lambda,
                    const double              mu)
  {
    const auto integral = [](const Point<dim>  &xi,
                             const Point<dim>  &xj,
                             const unsigned int a,
                             const unsigned int b) {
      double product = 1.;
      for (unsigned int d = 0; d < dim; ++d)
        {
          const double si = xi[d] > 0.5 ? 1. : -1.;
          const double sj = xj[d] > 0.5 ? 1. : -1.;
          if (d == a && d == b)
            product *= si * sj;
          else if (d == a)
            product *= si / 2;
          else if (d == b)
            product *= sj / 2;
          else
            product *= xi[d] == xj[d] ? 1. / 3 : 1. / 6;
        }
      return product;
    };
    FullMatrix<double> K(fe.n_dofs_per_cell(), fe.n_dofs_per_cell());
    for (unsigned int i = 0; i < K.m(); ++i)
      for (unsigned int j = 0; j < K.n(); ++j)
        {
          const auto [xi, c] = support(fe, i);
          const auto [xj, e] = support(fe, j);
          double value =
            lambda * integral(xi, xj, c, e) + mu * integral(xi, xj, e, c);
          if (c == e)
            for (unsigned int a = 0; a < dim; ++a)
              value += mu * integral(xi, xj, a, a);
          K(i, j) = value;
        }
    return K;
  }

  /** |K r| for the nodal values r of a motion u of the unit cell. */
  template <int dim>
  double
  residual_of_motion(
    const FullMatrix<double>                                            &K,
    const FiniteElement<dim>                                            &fe,
    const std::function<double(const Point<dim> &, const unsigned int)> &u)
  {
    Vector<double> r(K.m()), Kr(K.m());
    for (unsigned int i = 0; i < K.m(); ++i)
      {
        const auto [x, c] = support(fe, i);
        r(i)              = u(x, c);
      }
    K.vmult(Kr, r);
    return Kr.linfty_norm();
  }

  /** The rigid-body motions of the unit cell are in the kernel of @p K,
   * and nothing else is. */
  template <int dim>
  void
  check_kernel(const FullMatrix<double> &K, const FiniteElement<dim> &fe)
  {
    const double scale = max_abs(K);
    for (unsigned int d = 0; d < dim; ++d)
      report("|K t| / max|K|, translation along " + std::to_string(d),
             residual_of_motion<dim>(K,
                                     fe,
                                     [d](const Point<dim> &, unsigned int c) {
                                       return c == d ? 1. : 0.;
                                     }) /
               scale,
             1e-13);
    // Rotation in the plane (a, b): u = (-x_b, x_a).
    for (unsigned int a = 0; a < dim; ++a)
      for (unsigned int b = a + 1; b < dim; ++b)
        report(
          "|K r| / max|K|, rotation in plane " + std::to_string(a) +
            std::to_string(b),
          residual_of_motion<dim>(K,
                                  fe,
                                  [a, b](const Point<dim> &x, unsigned int c) {
                                    return c == a ? -x[b] : c == b ? x[a] : 0.;
                                  }) /
            scale,
          1e-13);

    LAPACKFullMatrix<double> lapack(K.m());
    lapack = K;
    Vector<double>     eigenvalues;
    FullMatrix<double> eigenvectors;
    lapack.compute_eigenvalues_symmetric(
      -1e300, 1e300, 0., eigenvalues, eigenvectors);
    unsigned int zero = 0;
    for (const double lambda : eigenvalues)
      if (std::abs(lambda) < 1e-12 * scale)
        ++zero;
    std::cout << "  eigenvalues (ascending):";
    for (const double lambda : eigenvalues)
      std::cout << ' ' << (std::abs(lambda) < 1e-12 * scale ? 0. : lambda);
    std::cout << "\n  zero eigenvalues: " << zero << " (rigid motions "
              << dim * (dim + 1) / 2 << ")\n";
  }

  double
  symmetry_defect(const FullMatrix<double> &K)
  {
    FullMatrix<double> T;
    T.copy_transposed(K);
    return max_difference(K, T) / max_abs(K);
  }

  /** The matrix of a cell computed afresh, not through the cache. */
  template <int dim>
  FullMatrix<double>
  computed(const CellStiffness<dim>                             &stiffness,
           const FiniteElement<dim>                             &fe,
           const typename DoFHandler<dim>::active_cell_iterator &cell)
  {
    FEValues<dim> fe_values(fe,
                            QGauss<dim>(2),
                            update_gradients | update_JxW_values);
    fe_values.reinit(cell);
    FullMatrix<double> K;
    stiffness.compute(fe_values, K);
    return K;
  }

  void
  test_square()
  {
    std::cout << "2D unit square, Q1, E = " << E << ", nu = " << nu << '\n';
    const FESystem<2> fe(FE_Q<2>(1), 2);

    for (const bool plane_stress : {false, true})
      {
        Material material;
        material.young_modulus = E;
        material.poisson_ratio = nu;
        material.plane_state   = plane_stress ?
                                   Material::PlaneState::plane_stress :
                                   Material::PlaneState::plane_strain;
        CellStiffness<2> stiffness(material);

        Triangulation<2> tria;
        GridGenerator::hyper_cube(tria, 0., 1.);
        DoFHandler<2> dofs(tria);
        dofs.distribute_dofs(fe);
        FEValues<2>        fe_values(fe,
                              QGauss<2>(2),
                              update_gradients | update_JxW_values);
        const auto         cell = dofs.begin_active();
        FullMatrix<double> K    = stiffness.matrix(cell, fe_values);

        // Plane strain (E, nu) is plane stress (E / (1 - nu^2),
        // nu / (1 - nu)).
        const double             E_  = plane_stress ? E : E / (1 - nu * nu);
        const double             nu_ = plane_stress ? nu : nu / (1 - nu);
        const FullMatrix<double> textbook =
          textbook_in_fe_order(fe, textbook_plane_stress(E_, nu_));
        std::cout << (plane_stress ? " plane stress\n" : " plane strain\n");
        std::cout << "  K(0,0) = " << K(0, 0) << ", K(0,1) = " << K(0, 1)
                  << ", K(0,2) = " << K(0, 2) << ", K(0,7) = " << K(0, 7)
                  << '\n';
        report("max |K - textbook| / max|K|",
               max_difference(K, textbook) / max_abs(K),
               1e-14);
        const double mu     = E / (2 * (1 + nu));
        double       lambda = E * nu / ((1 + nu) * (1 - 2 * nu));
        if (plane_stress)
          lambda = 2 * lambda * mu / (lambda + 2 * mu);
        report("max |K - tensor-product integrals| / max|K|",
               max_difference(K, unit_cube_by_hand<2>(fe, lambda, mu)) /
                 max_abs(K),
               1e-14);
        report("max |K - K^T| / max|K|", symmetry_defect(K), 0.);
        if (plane_stress)
          continue;
        check_kernel<2>(K, fe);

        // The same square moved by (3, -5): the cache has it.
        Triangulation<2> moved;
        GridGenerator::hyper_rectangle(moved, Point<2>(3, -5), Point<2>(4, -4));
        DoFHandler<2> moved_dofs(moved);
        moved_dofs.distribute_dofs(fe);
        const auto moved_cell = moved_dofs.begin_active();
        const auto hit        = stiffness.cached(moved_cell);
        std::cout << "  translated square cached: " << (hit ? "yes" : "no")
                  << '\n';
        if (hit)
          report("max |K(translated, cached) - K| / max|K|",
                 max_difference(*hit, K) / max_abs(K),
                 0.);
        report("max |K(translated, computed) - K| / max|K|",
               max_difference(computed(stiffness, fe, moved_cell), K) /
                 max_abs(K),
               1e-14);

        // Scaled by 2.5 (and moved): in 2D the matrix does not change.
        Triangulation<2> scaled;
        GridGenerator::hyper_rectangle(scaled,
                                       Point<2>(-1, 2),
                                       Point<2>(1.5, 4.5));
        DoFHandler<2> scaled_dofs(scaled);
        scaled_dofs.distribute_dofs(fe);
        const auto scaled_cell = scaled_dofs.begin_active();
        std::cout << "  square scaled by 2.5 cached: "
                  << (stiffness.cached(scaled_cell) ? "yes" : "no") << '\n';
        report("max |K(scaled 2.5, computed) - K| / max|K|",
               max_difference(computed(stiffness, fe, scaled_cell), K) /
                 max_abs(K),
               1e-14);

        // A 1 x 2 rectangle is another shape: not cached until computed.
        Triangulation<2> rectangle;
        GridGenerator::hyper_rectangle(rectangle,
                                       Point<2>(0, 0),
                                       Point<2>(1, 2));
        DoFHandler<2> rectangle_dofs(rectangle);
        rectangle_dofs.distribute_dofs(fe);
        const auto rectangle_cell = rectangle_dofs.begin_active();
        std::cout << "  1 x 2 rectangle cached before: "
                  << (stiffness.cached(rectangle_cell) ? "yes" : "no");
        const FullMatrix<double> R =
          stiffness.matrix(rectangle_cell, fe_values);
        std::cout << ", after: "
                  << (stiffness.cached(rectangle_cell) ? "yes" : "no")
                  << ", R(0,0) = " << R(0, 0) << '\n';
        report("max |R - computed| / max|R|",
               max_difference(R, computed(stiffness, fe, rectangle_cell)) /
                 max_abs(R),
               1e-14);
        stiffness.clear();
        std::cout << "  after clear(): square cached: "
                  << (stiffness.cached(cell) ? "yes" : "no") << '\n';
      }
  }

  void
  test_cube()
  {
    std::cout << "3D unit cube, Q1, E = " << E << ", nu = " << nu << '\n';
    const FESystem<3> fe(FE_Q<3>(1), 3);
    Material          material;
    material.young_modulus = E;
    material.poisson_ratio = nu;
    CellStiffness<3> stiffness(material);
    const double     mu     = E / (2 * (1 + nu));
    const double     lambda = E * nu / ((1 + nu) * (1 - 2 * nu));

    Triangulation<3> tria;
    GridGenerator::hyper_cube(tria, 0., 1.);
    DoFHandler<3> dofs(tria);
    dofs.distribute_dofs(fe);
    FEValues<3>        fe_values(fe,
                          QGauss<3>(2),
                          update_gradients | update_JxW_values);
    const auto         cell = dofs.begin_active();
    FullMatrix<double> K    = stiffness.matrix(cell, fe_values);

    report("max |K - tensor-product integrals| / max|K|",
           max_difference(K, unit_cube_by_hand<3>(fe, lambda, mu)) / max_abs(K),
           1e-14);
    // Every diagonal entry is (lambda + 2 mu) / 9 + 2 mu / 9.
    const double trace_by_hand = 24 * (lambda + 4 * mu) / 9;
    std::cout << "  trace " << K.trace() << ", by hand " << trace_by_hand
              << '\n';
    report("|trace - 8 (lambda + 4 mu) / 3| / trace",
           std::abs(K.trace() - trace_by_hand) / trace_by_hand,
           1e-14);
    report("max |K - K^T| / max|K|", symmetry_defect(K), 0.);
    check_kernel<3>(K, fe);

    // u = eps x: the energy 1/2 U.K.U is 1/2 eps:C:eps times the volume 1.
    const double   eps[3][3] = {{1e-3, 2e-4, -3e-4},
                                {2e-4, -5e-4, 1e-4},
                                {-3e-4, 1e-4, 2e-3}};
    Vector<double> U(K.m()), KU(K.m());
    for (unsigned int i = 0; i < K.m(); ++i)
      {
        const auto [x, c] = support(fe, i);
        for (unsigned int d = 0; d < 3; ++d)
          U(i) += eps[c][d] * x[d];
      }
    K.vmult(KU, U);
    const double energy = 0.5 * (U * KU);
    double       trace = 0., contraction = 0.;
    for (unsigned int a = 0; a < 3; ++a)
      {
        trace += eps[a][a];
        for (unsigned int b = 0; b < 3; ++b)
          contraction += eps[a][b] * eps[a][b];
      }
    const double closed = 0.5 * (lambda * trace * trace + 2 * mu * contraction);
    std::cout << "  uniform strain energy " << energy << ", 1/2 eps:C:eps "
              << closed << '\n';
    report("|energy - 1/2 eps:C:eps| / energy",
           std::abs(energy - closed) / closed,
           1e-13);

    // The cube scaled by 0.5 and moved: half the matrix, from the cache.
    Triangulation<3> scaled;
    GridGenerator::hyper_rectangle(scaled,
                                   Point<3>(2, 1, -1),
                                   Point<3>(2.5, 1.5, -0.5));
    DoFHandler<3> scaled_dofs(scaled);
    scaled_dofs.distribute_dofs(fe);
    const auto         scaled_cell = scaled_dofs.begin_active();
    FullMatrix<double> half(K);
    half *= 0.5;
    const auto hit = stiffness.cached(scaled_cell);
    std::cout << "  cube scaled by 0.5 cached: " << (hit ? "yes" : "no")
              << '\n';
    if (hit)
      report("max |K(scaled, cached) - K / 2| / max|K / 2|",
             max_difference(*hit, half) / max_abs(half),
             1e-15);
    report("max |K(scaled, computed) - K / 2| / max|K / 2|",
           max_difference(computed(stiffness, fe, scaled_cell), half) /
             max_abs(half),
           1e-14);
    FEValues<3> unused(fe, QGauss<3>(2), update_gradients | update_JxW_values);
    report("max |K(scaled, matrix()) - K / 2| / max|K / 2|",
           max_difference(stiffness.matrix(scaled_cell, unused), half) /
             max_abs(half),
           1e-15);

    // Scaled by 3: three times the matrix.
    Triangulation<3> large;
    GridGenerator::hyper_cube(large, -3., 0.);
    DoFHandler<3> large_dofs(large);
    large_dofs.distribute_dofs(fe);
    FullMatrix<double> triple(K);
    triple *= 3.;
    report("max |K(scaled 3, computed) - 3 K| / max|3 K|",
           max_difference(computed(stiffness, fe, large_dofs.begin_active()),
                          triple) /
             max_abs(triple),
           1e-14);
    report("max |K(scaled 3, matrix()) - 3 K| / max|3 K|",
           max_difference(stiffness.matrix(large_dofs.begin_active(), unused),
                          triple) /
             max_abs(triple),
           1e-15);
  }
} // namespace

int
main()
{
  std::cout << std::setprecision(10);
  test_square();
  test_cube();
}
