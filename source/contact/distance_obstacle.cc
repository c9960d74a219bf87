#include <signorini/contact/distance_obstacle.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace signorini
{
  using namespace dealii;

  template <int dim>
  DistanceObstacle<dim>::DistanceObstacle(const Function<dim> &distance,
                                          const std::string   &entry)
    : distance(distance)
    , distance_entry(entry)
  {
  }

  template <int dim>
  double
  DistanceObstacle<dim>::gap(const Point<dim> &x, Tensor<1, dim> &normal) const
  {
    // Central differences with a step near the cube root of the machine
    // precision (relative to the point's size, at least 1 mm's).
    double scale = 1.;
    for (unsigned int d = 0; d < dim; ++d)
      scale = std::max(scale, std::abs(x[d]));
    const double   h = 6e-6 * scale;
    Tensor<1, dim> gradient;
    for (unsigned int d = 0; d < dim; ++d)
      {
        Point<dim> forward = x, backward = x;
        forward[d] += h;
        backward[d] -= h;
        gradient[d] =
          (distance.value(forward) - distance.value(backward)) / (2 * h);
      }
    const double length = gradient.norm();
    normal              = gradient / length;
    return distance.value(x) / length;
  }

  template <int dim>
  std::string
  DistanceObstacle<dim>::entry() const
  {
    return distance_entry;
  }

  namespace
  {
    /** The point where phi, @p a at @p p and @p b at @p q, is zero. */
    template <int dim>
    Point<dim>
    level_set_crossing(const Point<dim> &p,
                       const Point<dim> &q,
                       const double      a,
                       const double      b)
    {
      const double t = a / (a - b);
      return p + t * (q - p);
    }
  } // namespace

  template <int dim>
  SurfaceMesh<dim>
  DistanceObstacle<dim>::surface(const BoundingBox<dim> &box) const
  {
    const unsigned int n = dim == 2 ? 200 : 40;
    Point<dim>         lower;
    Tensor<1, dim>     step;
    for (unsigned int d = 0; d < dim; ++d)
      {
        const double margin = 0.1 * box.side_length(d);
        lower[d]            = box.lower_bound(d) - margin;
        step[d]             = (box.upper_bound(d) + margin - lower[d]) / n;
      }
    // phi at the grid points.
    const unsigned int  n1 = n + 1;
    std::vector<double> phi(dim == 2 ? n1 * n1 : n1 * n1 * n1);
    const auto          grid_point = [&](const unsigned int index) {
      Point<dim>   p = lower;
      unsigned int k = index;
      for (unsigned int d = 0; d < dim; ++d, k /= n1)
        p[d] += (k % n1) * step[d];
      return p;
    };
    for (unsigned int i = 0; i < phi.size(); ++i)
      phi[i] = distance.value(grid_point(i));

    // Each square split into 2 triangles, each cube into 6 tetrahedra
    // around its diagonal; a simplex whose corners change sign holds a
    // piece of the zero set.
    SurfaceMesh<dim>   mesh;
    const unsigned int n_cells = dim == 2 ? n * n : n * n * n;
    for (unsigned int c = 0; c < n_cells; ++c)
      {
        std::array<unsigned int, 1U << dim> corner;
        unsigned int                        base = 0, k = c, stride = 1;
        for (unsigned int d = 0; d < dim; ++d, k /= n, stride *= n1)
          base += (k % n) * stride;
        for (unsigned int v = 0; v < (1U << dim); ++v)
          {
            corner[v] = base;
            for (unsigned int d = 0, s = 1; d < dim; ++d, s *= n1)
              if (v & (1U << d))
                corner[v] += s;
          }
        std::vector<std::array<unsigned int, dim + 1>> simplices;
        if constexpr (dim == 2)
          simplices = {{{corner[0], corner[1], corner[3]}},
                       {{corner[0], corner[3], corner[2]}}};
        else
          // Paths from corner 0 to corner 7 along the three axes.
          for (const auto &path : std::array<std::array<unsigned int, 2>, 6>{
                 {{{1, 3}}, {{1, 5}}, {{2, 3}}, {{2, 6}}, {{4, 5}}, {{4, 6}}}})
            simplices.push_back(
              {{corner[0], corner[path[0]], corner[path[1]], corner[7]}});
        for (const auto &simplex : simplices)
          {
            std::vector<Point<dim>>   crossings;
            std::vector<unsigned int> negative, positive;
            for (const unsigned int v : simplex)
              (phi[v] < 0 ? negative : positive).push_back(v);
            if (negative.empty() || positive.empty())
              continue;
            for (const unsigned int a : negative)
              for (const unsigned int b : positive)
                crossings.push_back(level_set_crossing(
                  grid_point(a), grid_point(b), phi[a], phi[b]));
            const unsigned int first = mesh.points.size();
            mesh.points.insert(mesh.points.end(),
                               crossings.begin(),
                               crossings.end());
            if (crossings.size() == 2)
              mesh.cells.push_back({first, first + 1});
            else if (crossings.size() == 3)
              mesh.cells.push_back({first, first + 1, first + 2});
            else // 2 + 2 corners of a tetrahedron: a quadrilateral
              mesh.cells.push_back({first, first + 1, first + 3, first + 2});
          }
      }
    return mesh;
  }

  template class DistanceObstacle<2>;
  template class DistanceObstacle<3>;
} // namespace signorini
