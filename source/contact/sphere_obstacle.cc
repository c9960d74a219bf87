#include <deal.II/base/numbers.h>

#include <signorini/contact/sphere_obstacle.h>

#include <cmath>

namespace signorini
{
  using namespace dealii;

  template <int dim>
  SphereObstacle<dim>::SphereObstacle(const Point<dim>  &center,
                                      const double       radius,
                                      const bool         body_inside,
                                      const std::string &entry)
    : center(center)
    , radius(radius)
    , body_inside(body_inside)
    , center_entry(entry)
  {
  }

  template <int dim>
  double
  SphereObstacle<dim>::gap(const Point<dim> &x, Tensor<1, dim> &normal) const
  {
    const Tensor<1, dim> r        = x - center;
    const double         distance = r.norm();
    normal                        = Tensor<1, dim>();
    if (distance > 0)
      normal = r / distance;
    else
      normal[dim - 1] = 1.; // at the center every direction is as near
    if (body_inside)
      {
        normal = -normal;
        return radius - distance;
      }
    return distance - radius;
  }

  template <int dim>
  std::string
  SphereObstacle<dim>::entry() const
  {
    return center_entry;
  }

  template <int dim>
  SurfaceMesh<dim>
  SphereObstacle<dim>::surface(const BoundingBox<dim> &) const
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
        // Rings of constant polar angle between the poles.
        const unsigned int n_polar = 48, n_around = 96;
        mesh.points.push_back(center + Point<dim>(0, 0, radius));
        for (unsigned int j = 1; j < n_polar; ++j)
          for (unsigned int i = 0; i < n_around; ++i)
            {
              const double theta = pi * j / n_polar,
                           phi   = 2 * pi * i / n_around;
              mesh.points.push_back(
                center + radius * Point<dim>(std::sin(theta) * std::cos(phi),
                                             std::sin(theta) * std::sin(phi),
                                             std::cos(theta)));
            }
        mesh.points.push_back(center + Point<dim>(0, 0, -radius));
        const auto ring = [&](const unsigned int j, const unsigned int i) {
          return 1 + (j - 1) * n_around + i % n_around;
        };
        const unsigned int south = mesh.points.size() - 1;
        for (unsigned int i = 0; i < n_around; ++i)
          {
            mesh.cells.push_back({0, ring(1, i), ring(1, i + 1)});
            for (unsigned int j = 1; j + 1 < n_polar; ++j)
              mesh.cells.push_back({ring(j, i),
                                    ring(j + 1, i),
                                    ring(j + 1, i + 1),
                                    ring(j, i + 1)});
            mesh.cells.push_back(
              {ring(n_polar - 1, i), south, ring(n_polar - 1, i + 1)});
          }
      }
    return mesh;
  }

  template class SphereObstacle<2>;
  template class SphereObstacle<3>;
} // namespace signorini
