#include <signorini/contact/height_obstacle.h>

namespace signorini
{
  using namespace dealii;

  template <int dim>
  HeightObstacle<dim>::HeightObstacle(const Function<dim - 1> &height,
                                      const std::string       &entry)
    : height(height)
    , height_entry(entry)
  {
  }

  template <int dim>
  double
  HeightObstacle<dim>::height_at(const Point<dim> &point) const
  {
    Point<dim - 1> horizontal;
    for (unsigned int d = 0; d < dim - 1; ++d)
      horizontal[d] = point[d];
    return height.value(horizontal);
  }

  template <int dim>
  double
  HeightObstacle<dim>::gap(const Point<dim> &point,
                           Tensor<1, dim>   &normal) const
  {
    normal          = Tensor<1, dim>();
    normal[dim - 1] = 1.;
    return point[dim - 1] - height_at(point);
  }

  template <int dim>
  std::string
  HeightObstacle<dim>::entry() const
  {
    return height_entry;
  }

  template <int dim>
  SurfaceMesh<dim>
  HeightObstacle<dim>::surface(const BoundingBox<dim> &box) const
  {
    const unsigned int n = dim == 2 ? 400 : 80;
    Point<dim>         lower, step;
    for (unsigned int d = 0; d < dim - 1; ++d)
      {
        const double margin = 0.1 * box.side_length(d);
        lower[d]            = box.lower_bound(d) - margin;
        step[d]             = (box.upper_bound(d) + margin - lower[d]) / n;
      }
    // A grid of (n + 1)^(dim - 1) points on the graph.
    SurfaceMesh<dim>   mesh;
    const unsigned int n_rows = dim == 2 ? 1 : n + 1;
    for (unsigned int j = 0; j < n_rows; ++j)
      for (unsigned int i = 0; i <= n; ++i)
        {
          Point<dim> p;
          p[0] = lower[0] + i * step[0];
          if (dim == 3)
            p[1] = lower[1] + j * step[1];
          p[dim - 1] = height_at(p);
          mesh.points.push_back(p);
        }
    if (dim == 2)
      for (unsigned int i = 0; i < n; ++i)
        mesh.cells.push_back({i, i + 1});
    else
      for (unsigned int j = 0; j < n; ++j)
        for (unsigned int i = 0; i < n; ++i)
          {
            const unsigned int a = j * (n + 1) + i;
            mesh.cells.push_back({a, a + 1, a + n + 2, a + n + 1});
          }
    return mesh;
  }

  template class HeightObstacle<2>;
  template class HeightObstacle<3>;
} // namespace signorini
