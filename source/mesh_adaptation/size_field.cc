#include <deal.II/numerics/rtree.h>

#include <signorini/mesh_adaptation/size_field.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace signorini
{
  using namespace dealii;

  template <int dim>
  struct SizeField<dim>::Tree
  {
    explicit Tree(const std::vector<Point<dim>> &points)
      : rtree(pack_rtree_of_indices(points))
    {
    }
    decltype(pack_rtree_of_indices(
      std::declval<std::vector<Point<dim>> &>())) rtree;
  };

  template <int dim>
  SizeField<dim>::SizeField(const Triangulation<dim>  &mesh,
                            const std::vector<double> &indicators,
                            const double               growth,
                            const double               min_size)
  {
    // Each cell's size: its mean edge length (every pair of vertices of a
    // simplex is an edge).
    const unsigned int  n_cells = mesh.n_active_cells();
    std::vector<double> h(n_cells);
    for (const auto &cell : mesh.active_cell_iterators())
      {
        double       sum = 0.;
        unsigned int n   = 0;
        for (const unsigned int i : cell->vertex_indices())
          for (unsigned int j = i + 1; j < cell->n_vertices(); ++j, ++n)
            sum += cell->vertex(i).distance(cell->vertex(j));
        h[cell->active_cell_index()] = sum / n;
      }

    // h_new / h = clamp((t / eta)^alpha, 1/4, 2), alpha = 1 / (1 + d/2).
    const double alpha = 1. / (1. + 0.5 * dim);
    const double eta_max =
      *std::max_element(indicators.begin(), indicators.end());
    const auto ratio = [&](const double t, const double eta) {
      if (!(eta_max > 0))
        return std::pow(growth, -1. / dim);
      if (!(eta > 0))
        return 2.;
      return std::clamp(std::pow(t / eta, alpha), 0.25, 2.);
    };
    const auto cells = [&](const double t) {
      double n = 0.;
      for (unsigned int k = 0; k < n_cells; ++k)
        n += std::pow(ratio(t, indicators[k]), -1. * dim);
      return n;
    };
    // cells(t) falls as t grows: bisect log t for growth * n_cells.
    double low  = std::log(eta_max) - 40.;
    double high = std::log(eta_max) + 10.;
    if (eta_max > 0)
      for (unsigned int i = 0; i < 100; ++i)
        {
          const double middle = 0.5 * (low + high);
          (cells(std::exp(middle)) > growth * n_cells ? low : high) = middle;
        }
    const double t = eta_max > 0 ? std::exp(0.5 * (low + high)) : 1.;
    expected_cells = cells(t);

    // The vertices' sizes: the mean over their cells.
    const auto               &all_vertices = mesh.get_vertices();
    std::vector<double>       sums(all_vertices.size(), 0.);
    std::vector<unsigned int> count(all_vertices.size(), 0);
    for (const auto &cell : mesh.active_cell_iterators())
      {
        const unsigned int k = cell->active_cell_index();
        const double size = std::max(min_size, h[k] * ratio(t, indicators[k]));
        for (const unsigned int v : cell->vertex_indices())
          {
            sums[cell->vertex_index(v)] += size;
            ++count[cell->vertex_index(v)];
          }
      }
    smallest = std::numeric_limits<double>::max();
    largest  = 0.;
    for (unsigned int v = 0; v < all_vertices.size(); ++v)
      if (count[v] > 0)
        {
          vertices.push_back(all_vertices[v]);
          vertex_sizes.push_back(sums[v] / count[v]);
          smallest = std::min(smallest, vertex_sizes.back());
          largest  = std::max(largest, vertex_sizes.back());
        }
    tree = std::make_unique<Tree>(vertices);
  }

  template <int dim>
  SizeField<dim>::~SizeField() = default;

  template <int dim>
  double
  SizeField<dim>::operator()(const Point<3> &point) const
  {
    Point<dim> p;
    for (unsigned int d = 0; d < dim; ++d)
      p[d] = point[d];
    std::vector<unsigned int> nearest;
    tree->rtree.query(boost::geometry::index::nearest(p, dim + 1),
                      std::back_inserter(nearest));
    double weights = 0., sum = 0.;
    for (const unsigned int v : nearest)
      {
        const double distance = p.distance(vertices[v]);
        if (distance < 1e-12 * vertex_sizes[v])
          return vertex_sizes[v];
        weights += 1. / (distance * distance);
        sum += vertex_sizes[v] / (distance * distance);
      }
    return sum / weights;
  }

  template class SizeField<2>;
  template class SizeField<3>;
} // namespace signorini
