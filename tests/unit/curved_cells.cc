// CurvedCells against FEValues: on curved cells (a ball's and a disk's,
// whose cells follow the sphere by a mapping of the element's degree) the
// operator of each cell applied eight at a time by sum factorisation equals
// the cell's stiffness matrix K (2 mu eps:eps + lambda div div, assembled by
// FEValues at the same Gauss points) times x, to a relative 1e-13 of
// sum |K_ij x_j|, for Q1 and Q2 in 2D and 3D, with a last batch of fewer
// than eight cells (in single precision sixteen at a time, to 1e-6); and
// the matrices and diagonals it computes from the gradients at the points
// (for the smoother's diagonal) equal K's to a relative 1e-13; the same for
// Q2 parallelograms and parallelepipeds given by one Jacobian each
// (affine batches, a box's cells).
// (tests/processor/ runs this on the kernels' other copies.)

#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/fe_tools.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping_q.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/tria.h>

#include <signorini/elasticity/curved_cells.h>

#include "checks.h"
#include <algorithm>
#include <cmath>
#include <iostream>
#include <string>
#include <vector>

using namespace dealii;
using namespace signorini;

namespace
{
  template <int dim>
  void
  check(const unsigned int degree, const bool affine = false)
  {
    const double       mu = 0.8, lambda = 1.7;
    Triangulation<dim> mesh;
    if (affine)
      {
        // Parallelograms or parallelepipeds of two sizes, sheared.
        GridGenerator::hyper_cube(mesh);
        mesh.refine_global(1);
        mesh.begin_active()->set_refine_flag();
        mesh.execute_coarsening_and_refinement();
        GridTools::transform(
          [](const Point<dim> &p) {
            Point<dim> q = p;
            q[0] += 0.3 * p[1] + 0.1;
            q[dim - 1] *= 1.7;
            return q;
          },
          mesh);
      }
    else
      {
        GridGenerator::hyper_ball(mesh);
        mesh.refine_global(1);
      }
    const MappingQ<dim> mapping(degree);
    const FESystem<dim> fe(FE_Q<dim>(degree), dim);
    const QGauss<dim>   gauss(degree + 1);
    const unsigned int  n = fe.n_dofs_per_cell(), nodes = n / dim;
    const auto          lexicographic =
      FETools::lexicographic_to_hierarchic_numbering<dim>(degree);
    FEValues<dim> fe_values(mapping,
                            fe,
                            gauss,
                            update_gradients | update_JxW_values |
                              update_inverse_jacobians);
    CurvedCells   curved;
    curved.reinit(dim, degree, mu, lambda, affine);
    std::vector<std::vector<double>> matrices, xs;
    for (const auto &cell : mesh.active_cell_iterators())
      {
        fe_values.reinit(cell);
        // The cell's B_q and its K in the kernel's order: component c of
        // node i (lexicographic) is entry c * nodes + i.
        std::vector<double> B(gauss.size() * dim * dim);
        for (unsigned int q = 0; q < gauss.size(); ++q)
          for (unsigned int k = 0; k < dim; ++k)
            for (unsigned int j = 0; j < dim; ++j)
              B[(q * dim + k) * dim + j] = std::sqrt(fe_values.JxW(q)) *
                                           fe_values.inverse_jacobian(q)[k][j];
        // An affine cell: one B = sqrt(det J) J^{-1}, det J = JxW / w.
        if (affine)
          {
            B.resize(dim * dim);
            for (unsigned int k = 0; k < dim; ++k)
              for (unsigned int j = 0; j < dim; ++j)
                B[k * dim + j] = std::sqrt(fe_values.JxW(0) / gauss.weight(0)) *
                                 fe_values.inverse_jacobian(0)[k][j];
          }
        curved.add(B);
        std::vector<unsigned int> local(n);
        for (unsigned int c = 0; c < dim; ++c)
          for (unsigned int i = 0; i < nodes; ++i)
            local[c * nodes + i] =
              fe.component_to_system_index(c, lexicographic[i]);
        std::vector<double>              K(n * n, 0.);
        const FEValuesExtractors::Vector u(0);
        for (unsigned int q = 0; q < gauss.size(); ++q)
          for (unsigned int a = 0; a < n; ++a)
            for (unsigned int b = 0; b < n; ++b)
              {
                const auto ea = fe_values[u].symmetric_gradient(local[a], q);
                const auto eb = fe_values[u].symmetric_gradient(local[b], q);
                K[a * n + b] +=
                  (2. * mu * (ea * eb) + lambda * trace(ea) * trace(eb)) *
                  fe_values.JxW(q);
              }
        matrices.push_back(K);
        std::vector<double> x(n);
        for (unsigned int a = 0; a < n; ++a)
          x[a] = std::sin(1.7 * a + 0.3 * xs.size()) * (1. + a % 3);
        xs.push_back(x);
      }
    // The largest |K x - kernel| / sum |K_ij x_j| with `wide` cells a
    // batch, in Number.
    const auto worst_of = [&](const unsigned int wide,
                              auto               number,
                              const auto        &apply) {
      using Number = decltype(number);
      AlignedVector<Number> bx(n * wide), by(n * wide);
      double                worst = 0.;
      for (unsigned int batch = 0; batch * wide < xs.size(); ++batch)
        {
          const unsigned int first = batch * wide,
                             count =
                               std::min<std::size_t>(wide, xs.size() - first);
          bx.fill(Number());
          for (unsigned int l = 0; l < count; ++l)
            for (unsigned int a = 0; a < n; ++a)
              bx[a * wide + l] = xs[first + l][a];
          apply(batch, bx.data(), by.data());
          for (unsigned int l = 0; l < count; ++l)
            for (unsigned int a = 0; a < n; ++a)
              {
                const auto &K = matrices[first + l];
                double      y = 0., scale = 0.;
                for (unsigned int b = 0; b < n; ++b)
                  {
                    y += K[a * n + b] * xs[first + l][b];
                    scale += std::abs(K[a * n + b] * xs[first + l][b]);
                  }
                worst = std::max(worst, std::abs(by[a * wide + l] - y) / scale);
              }
        }
      return worst;
    };
    const unsigned int lanes = CurvedCells::lanes;
    const double       worst =
      worst_of(lanes, 0., [&](const auto batch, const auto x, const auto y) {
        curved.apply(batch, x, y);
      });
    // In single precision, sixteen cells at a time.
    const double worst_single =
      worst_of(CurvedCells::single_lanes,
               0.f,
               [&](const auto batch, const auto x, const auto y) {
                 curved.apply_single(batch, x, y);
               });
    // The matrices and diagonals from the points' gradients.
    AlignedVector<double> bK(n * n * lanes), bd(n * lanes);
    double                worst_matrix = 0., worst_diagonal = 0.;
    for (unsigned int batch = 0; batch * lanes < xs.size(); ++batch)
      {
        curved.matrices(batch, bK.data());
        curved.diagonals(batch, bd.data());
        for (unsigned int l = 0; l < lanes && batch * lanes + l < xs.size();
             ++l)
          {
            const auto &K     = matrices[batch * lanes + l];
            double      scale = 0.;
            for (const double entry : K)
              scale = std::max(scale, std::abs(entry));
            for (unsigned int a = 0; a < n; ++a)
              {
                for (unsigned int b = 0; b < n; ++b)
                  worst_matrix = std::max(worst_matrix,
                                          std::abs(bK[(a * n + b) * lanes + l] -
                                                   K[a * n + b]) /
                                            scale);
                worst_diagonal =
                  std::max(worst_diagonal,
                           std::abs(bd[a * lanes + l] - K[a * n + a]) /
                             K[a * n + a]);
              }
          }
      }
    std::cout << dim << "D, degree " << degree << (affine ? ", affine" : "")
              << ", " << xs.size() << " cells ("
              << (xs.size() + lanes - 1) / lanes << " batches):\n";
    checks::report("  max |K x - kernel| / sum |K_ij x_j|", worst, 1e-13);
    // (Its digits differ between processors: the verdict is compared.)
    checks::expect("  single precision: max |K x - kernel| / sum |K_ij x_j| "
                   "below 1e-6",
                   worst_single <= 1e-6);
    checks::report("  max |K_ij - matrices()| / max |K_ij|",
                   worst_matrix,
                   1e-13);
    checks::report("  max |K_ii - diagonals()| / K_ii", worst_diagonal, 1e-13);
  }
} // namespace

int
main()
{
  check<2>(1);
  check<2>(2);
  check<3>(1);
  check<3>(2);
  check<2>(2, true);
  check<3>(2, true);
}
