#include <signorini/contact/cad_obstacle.h>
#include <signorini/contact/cylinder_obstacle.h>
#include <signorini/contact/distance_obstacle.h>
#include <signorini/contact/height_obstacle.h>
#include <signorini/contact/obstacle_set.h>
#include <signorini/contact/plane_obstacle.h>
#include <signorini/contact/punch_obstacle.h>
#include <signorini/contact/sphere_obstacle.h>

#include <stdexcept>

namespace signorini
{
  using namespace dealii;

  template <int dim>
  std::unique_ptr<Obstacle<dim>>
  create_obstacle(const ObstacleDescription<dim> &d)
  {
    using Type = typename ObstacleDescription<dim>::Type;
    switch (d.type)
      {
        case Type::height:
          return std::make_unique<HeightObstacle<dim>>(*d.height,
                                                       d.entry("Height"));
        case Type::plane:
          return std::make_unique<PlaneObstacle<dim>>(d.point,
                                                      d.normal,
                                                      d.entry("Point"));
        case Type::sphere:
          return std::make_unique<SphereObstacle<dim>>(d.center,
                                                       d.radius,
                                                       d.body_inside,
                                                       d.entry("Center"));
        case Type::cylinder:
          return std::make_unique<CylinderObstacle<dim>>(
            d.center, d.axis, d.radius, d.body_inside, d.entry("Center"));
        case Type::punch:
          return std::make_unique<PunchObstacle<dim>>(d.center,
                                                      d.normal,
                                                      d.radius,
                                                      d.entry("Center"));
        case Type::signed_distance:
          return std::make_unique<DistanceObstacle<dim>>(
            *d.distance, d.entry("Signed distance"));
        case Type::geometry_file:
          return std::make_unique<CadObstacle<dim>>(d.geometry_file,
                                                    d.body_inside,
                                                    d.entry("Geometry file"));
        case Type::none:
          break;
      }
    throw std::logic_error("an obstacle of no kind");
  }

  template std::unique_ptr<Obstacle<2>>
  create_obstacle(const ObstacleDescription<2> &);
  template std::unique_ptr<Obstacle<3>>
  create_obstacle(const ObstacleDescription<3> &);
} // namespace signorini
