// SizeField against its documented rule on small simplex meshes: the cell
// size h (mean edge length), the new size h clamp((t / eta)^(1/(1 + d/2)),
// 1/4, 2) with t bisected for growth times the number of cells, the clamps,
// the minimum size, indicators all zero, vertex sizes as the mean of their
// cells', and the inverse-distance weighted mean of the d + 1 nearest vertices
// between them.

#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/tria.h>

#include <signorini/mesh_adaptation/size_field.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <iostream>
#include <string>
#include <vector>

using namespace dealii;
using namespace signorini;

namespace
{
  void
  report(const std::string &what, const double difference, const double tol)
  {
    std::cout << "  " << what << ": " << std::scientific << std::setprecision(1)
              << difference << (difference <= tol ? "  (ok)" : "  (FAILED)")
              << std::defaultfloat << std::setprecision(10) << '\n';
  }

  // The sizes follow the rule to round-off.
  constexpr double size_tolerance = 1e-12;

  /** The mean edge length of a simplex, by hand. */
  template <int dim>
  double
  mean_edge(const typename Triangulation<dim>::active_cell_iterator &cell)
  {
    double       sum = 0.;
    unsigned int n   = 0;
    for (unsigned int i = 0; i <= dim; ++i)
      for (unsigned int j = i + 1; j <= dim; ++j, ++n)
        sum += cell->vertex(i).distance(cell->vertex(j));
    return sum / n;
  }

  /** The vertex sizes for the cell sizes @p cell_size: means over the cells
   * at each vertex. */
  template <int dim>
  std::vector<double>
  vertex_means(const Triangulation<dim>  &mesh,
               const std::vector<double> &cell_size)
  {
    std::vector<double>       sum(mesh.n_vertices(), 0.);
    std::vector<unsigned int> count(mesh.n_vertices(), 0);
    for (const auto &cell : mesh.active_cell_iterators())
      for (const unsigned int v : cell->vertex_indices())
        {
          sum[cell->vertex_index(v)] += cell_size[cell->active_cell_index()];
          ++count[cell->vertex_index(v)];
        }
    for (unsigned int v = 0; v < sum.size(); ++v)
      sum[v] /= count[v];
    return sum;
  }

  template <int dim>
  Point<3>
  to_3d(const Point<dim> &p, const double z = 0.)
  {
    Point<3> q;
    for (unsigned int d = 0; d < dim; ++d)
      q[d] = p[d];
    if (dim == 2)
      q[2] = z;
    return q;
  }

  /** The field at every vertex against @p expected; the largest relative
   * difference. */
  template <int dim>
  double
  vertex_difference(const SizeField<dim>      &field,
                    const Triangulation<dim>  &mesh,
                    const std::vector<double> &expected)
  {
    double difference = 0.;
    for (unsigned int v = 0; v < mesh.n_vertices(); ++v)
      difference = std::max(difference,
                            std::abs(field(to_3d(mesh.get_vertices()[v], 7.)) -
                                     expected[v]) /
                              expected[v]);
    return difference;
  }

  /** The inverse-distance weighted mean of the d + 1 nearest vertices. */
  template <int dim>
  double
  weighted_mean(const Triangulation<dim>  &mesh,
                const std::vector<double> &vertex_size,
                const Point<dim>          &p)
  {
    std::vector<std::pair<double, unsigned int>> by_distance;
    for (unsigned int v = 0; v < mesh.n_vertices(); ++v)
      by_distance.emplace_back(p.distance(mesh.get_vertices()[v]), v);
    std::sort(by_distance.begin(), by_distance.end());
    double weights = 0., sum = 0.;
    for (unsigned int k = 0; k <= dim; ++k)
      {
        const double w = 1. / std::pow(by_distance[k].first, 2);
        weights += w;
        sum += w * vertex_size[by_distance[k].second];
      }
    return sum / weights;
  }

  template <int dim>
  void
  print_summary(const SizeField<dim> &field)
  {
    std::cout << "  smallest " << field.smallest << ", largest "
              << field.largest << ", expected cells " << field.expected_cells
              << '\n';
  }

  void
  uniform_2d()
  {
    std::cout << "2D, 2 x 2 squares in 8 right triangles (legs 1/2), "
                 "eta = 1 everywhere, growth 2:\n";
    Triangulation<2> mesh;
    GridGenerator::subdivided_hyper_cube_with_simplices(mesh, 2);
    const std::vector<double> eta(mesh.n_active_cells(), 1.);
    const SizeField<2>        field(mesh, eta, 2., 0.);
    print_summary(field);
    // h = (1/2 + 1/2 + sqrt(1/2)) / 3; twice the cells: h / sqrt(2).
    const double h        = (1. + std::sqrt(0.5)) / 3.;
    const double expected = h / std::sqrt(2.);
    std::cout << "  h / sqrt(2) = " << expected << '\n';
    report("|expected cells - 16|", std::abs(field.expected_cells - 16.), 1e-9);
    report("max |size - h / sqrt(2)| / size, vertices",
           vertex_difference(field,
                             mesh,
                             std::vector<double>(mesh.n_vertices(), expected)),
           size_tolerance);
    double between = 0.;
    for (const Point<3> p : {Point<3>(0.3, 0.7, 5.),
                             Point<3>(0.01, 0.99, 0.),
                             Point<3>(1.2, -0.1, 0.),
                             Point<3>(-3., 0.5, 0.)})
      between = std::max(between, std::abs(field(p) - expected) / expected);
    report("max |size - h / sqrt(2)| / size, between and outside",
           between,
           size_tolerance);
    report("|smallest - h / sqrt(2)| / size",
           std::abs(field.smallest - expected) / expected,
           size_tolerance);
    report("|largest - h / sqrt(2)| / size",
           std::abs(field.largest - expected) / expected,
           size_tolerance);

    std::cout << "the same, minimum size 0.5:\n";
    const SizeField<2> coarse(mesh, eta, 2., 0.5);
    print_summary(coarse);
    report("max |size - 0.5|, vertices",
           vertex_difference(coarse,
                             mesh,
                             std::vector<double>(mesh.n_vertices(), 0.5)),
           0.);

    std::cout << "the same, indicators all zero, growth 4:\n";
    const SizeField<2> zero(mesh,
                            std::vector<double>(mesh.n_active_cells(), 0.),
                            4.,
                            0.);
    print_summary(zero);
    report("|expected cells - 32|", std::abs(zero.expected_cells - 32.), 1e-9);
    report("max |size - h / 2| / size, vertices",
           vertex_difference(zero,
                             mesh,
                             std::vector<double>(mesh.n_vertices(), h / 2)),
           size_tolerance);

    std::cout << "the same, eta = 1, growth 20 (h / sqrt(20) < h / 4):\n";
    const SizeField<2> fine(mesh, eta, 20., 0.);
    print_summary(fine);
    report("|expected cells - 8 * 16| (the clamp at 1/4)",
           std::abs(fine.expected_cells - 128.),
           1e-9);
    report("max |size - h / 4| / size, vertices",
           vertex_difference(fine,
                             mesh,
                             std::vector<double>(mesh.n_vertices(), h / 4)),
           size_tolerance);

    std::cout << "the same, eta = 1, growth 0.1 (h sqrt(10) > 2 h):\n";
    const SizeField<2> coarser(mesh, eta, 0.1, 0.);
    print_summary(coarser);
    report("|expected cells - 8 / 4| (the clamp at 2)",
           std::abs(coarser.expected_cells - 2.),
           1e-9);
    report("max |size - 2 h| / size, vertices",
           vertex_difference(coarser,
                             mesh,
                             std::vector<double>(mesh.n_vertices(), 2 * h)),
           size_tolerance);
  }

  /** One square in two triangles with indicators @p eta and @p growth; the
   * ratios h_new / h the rule gives, by hand. */
  void
  two_triangles(const std::vector<double> &eta,
                const double               growth,
                const std::vector<double> &ratio)
  {
    std::cout << "2D, two triangles, eta = {" << eta[0] << ", " << eta[1]
              << "}, growth " << growth << ", ratios by hand {" << ratio[0]
              << ", " << ratio[1] << "}:\n";
    Triangulation<2> mesh;
    GridGenerator::subdivided_hyper_cube_with_simplices(mesh, 1);
    const SizeField<2> field(mesh, eta, growth, 0.);
    print_summary(field);
    double cells = 0.;
    for (const double r : ratio)
      cells += 1. / (r * r);
    std::cout << "  cells by hand " << cells << '\n';
    report("|expected cells - by hand|",
           std::abs(field.expected_cells - cells),
           1e-9);
    std::vector<double> cell_size(2);
    for (const auto &cell : mesh.active_cell_iterators())
      cell_size[cell->active_cell_index()] =
        mean_edge<2>(cell) * ratio[cell->active_cell_index()];
    const auto vertex_size = vertex_means(mesh, cell_size);
    std::cout << "  vertex sizes by hand:";
    for (const double s : vertex_size)
      std::cout << ' ' << s;
    std::cout << '\n';
    report("max |size - by hand| / size, vertices",
           vertex_difference(field, mesh, vertex_size),
           size_tolerance);
    double between = 0.;
    for (const Point<2> p :
         {Point<2>(0.25, 0.1), Point<2>(0.8, 0.6), Point<2>(1.3, -0.2)})
      {
        const double expected = weighted_mean(mesh, vertex_size, p);
        between =
          std::max(between, std::abs(field(to_3d(p)) - expected) / expected);
      }
    report("max |size - weighted mean of 3 nearest| / size, between",
           between,
           size_tolerance);
  }

  void
  uniform_3d()
  {
    std::cout << "3D, a cube in 5 tetrahedra, eta = 1 everywhere, growth 8:\n";
    Triangulation<3> mesh;
    GridGenerator::subdivided_hyper_cube_with_simplices(mesh, 1);
    const std::vector<double> eta(mesh.n_active_cells(), 1.);
    const SizeField<3>        field(mesh, eta, 8., 0.);
    print_summary(field);
    report("|expected cells - 40|", std::abs(field.expected_cells - 40.), 1e-9);
    std::vector<double> cell_size(mesh.n_active_cells());
    for (const auto &cell : mesh.active_cell_iterators())
      cell_size[cell->active_cell_index()] = mean_edge<3>(cell) / 2;
    const auto vertex_size = vertex_means(mesh, cell_size);
    std::cout << "  vertex sizes by hand:";
    for (const double s : vertex_size)
      std::cout << ' ' << s;
    std::cout << '\n';
    report("max |size - by hand| / size, vertices",
           vertex_difference(field, mesh, vertex_size),
           size_tolerance);
    const Point<3> p(0.3, 0.2, 0.1);
    report("|size - weighted mean of 4 nearest| / size, at (0.3, 0.2, 0.1)",
           std::abs(field(p) - weighted_mean(mesh, vertex_size, p)) / field(p),
           size_tolerance);
  }
} // namespace

int
main()
{
  std::cout << std::setprecision(10);
  uniform_2d();
  // d = 2: (t / eta)^(1/2) and sum (eta / t) = growth N, t = sum eta / (g N).
  two_triangles({1., 4.}, 1., {std::sqrt(2.5), std::sqrt(2.5 / 4.)});
  two_triangles({1., 4.}, 1.5, {std::sqrt(5. / 3.), std::sqrt(5. / 12.)});
  // eta = 0 gives the largest ratio, 2; the other cell 1/4 + 1/r^2 = 2.
  two_triangles({0., 1.}, 1., {2., 1. / std::sqrt(1.75)});
  uniform_3d();
}
