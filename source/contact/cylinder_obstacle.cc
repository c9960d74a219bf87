#include <deal.II/base/numbers.h>

#include <signorini/contact/cylinder_obstacle.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace signorini
{
  using namespace dealii;

  template <int dim>
  CylinderObstacle<dim>::CylinderObstacle(const Point<dim>     &center,
                                          const Tensor<1, dim> &axis,
                                          const double          radius,
                                          const bool            body_inside,
                                          const std::string    &entry)
    : center(center)
    , axis(dim == 3 ? axis / axis.norm() : Tensor<1, dim>())
    , radius(radius)
    , body_inside(body_inside)
    , center_entry(entry)
  {
  }

  template <int dim>
  double
  CylinderObstacle<dim>::gap(const Point<dim> &x, Tensor<1, dim> &normal) const
  {
    Tensor<1, dim> r = x - center;
    if (dim == 3)
      r -= (r * axis) * axis;
    const double distance = r.norm();
    normal                = Tensor<1, dim>();
    if (distance > 0)
      normal = r / distance;
    else
      {
        // On the axis every radial direction is as near: one across it.
        normal = unit_vector_across(axis);
      }
    if (body_inside)
      {
        normal = -normal;
        return radius - distance;
      }
    return distance - radius;
  }

  template <int dim>
  std::string
  CylinderObstacle<dim>::entry() const
  {
    return center_entry;
  }

  template <int dim>
  SurfaceMesh<dim>
  CylinderObstacle<dim>::surface(const BoundingBox<dim> &box) const
  {
    SurfaceMesh<dim> mesh;
    const double     pi = numbers::PI;
    if constexpr (dim == 2)
      {
        const unsigned int n = 360;
        for (unsigned int i = 0; i < n; ++i)
          {
            const double angle = 2 * pi * i / n;
            mesh.points.push_back(
              center + radius * Point<dim>(std::cos(angle), std::sin(angle)));
            mesh.cells.push_back({i, (i + 1) % n});
          }
      }
    else
      {
        // The axial extent of the box's corners.
        double low = std::numeric_limits<double>::max(), high = -low;
        for (unsigned int c = 0; c < 8; ++c)
          {
            const double s = (box.vertex(c) - center) * axis;
            low            = std::min(low, s);
            high           = std::max(high, s);
          }
        const double margin = 0.1 * (high - low);
        low -= margin;
        high += margin;
        // Two unit vectors across the axis.
        const Tensor<1, dim> e1 = unit_vector_across(axis);
        const Tensor<1, dim> e2 = cross_product_3d(axis, e1);
        const unsigned int   n  = 96;
        for (const double s : {low, high})
          for (unsigned int i = 0; i < n; ++i)
            {
              const double angle = 2 * pi * i / n;
              mesh.points.push_back(
                center + s * axis +
                radius * (std::cos(angle) * e1 + std::sin(angle) * e2));
            }
        for (unsigned int i = 0; i < n; ++i)
          mesh.cells.push_back({i, (i + 1) % n, n + (i + 1) % n, n + i});
      }
    return mesh;
  }

  template class CylinderObstacle<2>;
  template class CylinderObstacle<3>;
} // namespace signorini
