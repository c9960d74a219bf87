#include <deal.II/base/numbers.h>

#include <signorini/contact/punch_obstacle.h>

#include <algorithm>
#include <array>
#include <cmath>

namespace signorini
{
  using namespace dealii;

  namespace
  {
    /** How far clear of the punch a point beyond its rim stays, in radii
     * (see moved_gap()): no small displacement closes it. */
    constexpr double far = 1e3;
  } // namespace

  template <int dim>
  PunchObstacle<dim>::PunchObstacle(const Point<dim>     &center,
                                    const Tensor<1, dim> &normal,
                                    const double          radius,
                                    const std::string    &entry)
    : center(center)
    , unit_normal(normal / normal.norm())
    , radius(radius)
    , center_entry(entry)
  {
  }

  template <int dim>
  double
  PunchObstacle<dim>::gap(const Point<dim> &x, Tensor<1, dim> &normal) const
  {
    const Tensor<1, dim> r      = x - center;
    const double         height = r * unit_normal;
    const Tensor<1, dim> offset = r - height * unit_normal;
    const double         rho    = offset.norm();
    if (rho <= radius)
      {
        normal = unit_normal;
        return height;
      }
    const Tensor<1, dim> outward = offset / rho;
    if (height < 0)
      {
        normal = outward;
        return rho - radius;
      }
    const Tensor<1, dim> from_rim = r - radius * outward;
    const double         distance = from_rim.norm();
    normal                        = from_rim / distance;
    return distance;
  }

  template <int dim>
  double
  PunchObstacle<dim>::moved_gap(const Point<dim>     &point,
                                const Tensor<1, dim> &displacement,
                                Tensor<1, dim>       &normal) const
  {
    const Point<dim>     moved_back = point - displacement;
    const Tensor<1, dim> r          = point - center;
    const Tensor<1, dim> offset     = r - (r * unit_normal) * unit_normal;
    // Beyond the rim, in front of the end as it was: clear of the punch.
    if (offset.norm() > radius && r * unit_normal >= 0)
      {
        normal = unit_normal;
        return (moved_back - center) * unit_normal + far * radius;
      }
    return gap(moved_back, normal);
  }

  template <int dim>
  std::string
  PunchObstacle<dim>::entry() const
  {
    return center_entry;
  }

  template <int dim>
  SurfaceMesh<dim>
  PunchObstacle<dim>::surface(const BoundingBox<dim> &box) const
  {
    // How far back from its end the punch is drawn: over the box.
    double length = radius;
    for (unsigned int c = 0; c < (1U << dim); ++c)
      length = std::max(length, -((box.vertex(c) - center) * unit_normal));
    const Tensor<1, dim> back = -length * unit_normal;
    SurfaceMesh<dim>     mesh;
    if constexpr (dim == 2)
      {
        Tensor<1, dim> t;
        t[0]                   = -unit_normal[1];
        t[1]                   = unit_normal[0];
        const Point<dim> left  = center - radius * t,
                         right = center + radius * t;
        mesh.points            = {left + back, left, right, right + back};
        mesh.cells             = {{0, 1}, {1, 2}, {2, 3}};
      }
    else
      {
        // Tangents of the end.
        const Tensor<1, dim> a = unit_vector_across(unit_normal);
        const Tensor<1, dim> b = cross_product_3d(unit_normal, a);
        // The end: a fan of triangles around its center; the side wall:
        // quadrilaterals between the rim and the rim moved back.
        const unsigned int n = 96;
        mesh.points.push_back(center);
        for (unsigned int i = 0; i < n; ++i)
          {
            const double     angle = 2 * numbers::PI * i / n;
            const Point<dim> rim =
              center + radius * (std::cos(angle) * a + std::sin(angle) * b);
            mesh.points.push_back(rim);
            mesh.points.push_back(rim + back);
          }
        for (unsigned int i = 0; i < n; ++i)
          {
            const unsigned int here = 1 + 2 * i, next = 1 + 2 * ((i + 1) % n);
            mesh.cells.push_back({0, next, here});
            mesh.cells.push_back({here, next, next + 1, here + 1});
          }
      }
    return mesh;
  }

  template class PunchObstacle<2>;
  template class PunchObstacle<3>;
} // namespace signorini
