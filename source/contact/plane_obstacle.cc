#include <signorini/contact/plane_obstacle.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace signorini
{
  using namespace dealii;

  template <int dim>
  PlaneObstacle<dim>::PlaneObstacle(const Point<dim>     &point,
                                    const Tensor<1, dim> &normal,
                                    const std::string    &entry)
    : point(point)
    , unit_normal(normal / normal.norm())
    , point_entry(entry)
  {
  }

  template <int dim>
  double
  PlaneObstacle<dim>::gap(const Point<dim> &x, Tensor<1, dim> &normal) const
  {
    normal = unit_normal;
    return (x - point) * unit_normal;
  }

  template <int dim>
  std::string
  PlaneObstacle<dim>::entry() const
  {
    return point_entry;
  }

  template <int dim>
  SurfaceMesh<dim>
  PlaneObstacle<dim>::surface(const BoundingBox<dim> &box) const
  {
    // Tangents: in 2D the normal turned by 90 degrees; in 3D a unit vector
    // across the normal, and the normal times that.
    std::array<Tensor<1, dim>, dim - 1> tangents;
    if constexpr (dim == 2)
      {
        tangents[0][0] = -unit_normal[1];
        tangents[0][1] = unit_normal[0];
      }
    else
      {
        tangents[0] = unit_vector_across(unit_normal);
        tangents[1] = cross_product_3d(unit_normal, tangents[0]);
      }
    // The box's corners in the tangents' coordinates.
    std::array<double, dim - 1> low, high;
    low.fill(std::numeric_limits<double>::max());
    high.fill(-std::numeric_limits<double>::max());
    for (unsigned int c = 0; c < (1U << dim); ++c)
      {
        const Point<dim> corner = box.vertex(c);
        for (unsigned int t = 0; t < dim - 1; ++t)
          {
            const double s = (corner - point) * tangents[t];
            low[t]         = std::min(low[t], s);
            high[t]        = std::max(high[t], s);
          }
      }
    const auto  &extent   = box.get_boundary_points();
    const double diagonal = extent.first.distance(extent.second);
    for (unsigned int t = 0; t < dim - 1; ++t)
      {
        const double margin =
          std::max(0.1 * (high[t] - low[t]), 0.05 * diagonal);
        low[t] -= margin;
        high[t] += margin;
      }
    SurfaceMesh<dim> mesh;
    if (dim == 2)
      {
        mesh.points = {point + low[0] * tangents[0],
                       point + high[0] * tangents[0]};
        mesh.cells  = {{0, 1}};
      }
    else
      {
        for (const double b : {low[dim - 2], high[dim - 2]})
          for (const double a : {low[0], high[0]})
            mesh.points.push_back(point + a * tangents[0] +
                                  b * tangents[dim - 2]);
        mesh.cells = {{0, 1, 3, 2}};
      }
    return mesh;
  }

  template class PlaneObstacle<2>;
  template class PlaneObstacle<3>;
} // namespace signorini
