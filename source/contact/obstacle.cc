#include <signorini/contact/cad_obstacle.h>
#include <signorini/contact/cylinder_obstacle.h>
#include <signorini/contact/distance_obstacle.h>
#include <signorini/contact/height_obstacle.h>
#include <signorini/contact/obstacle.h>
#include <signorini/contact/plane_obstacle.h>
#include <signorini/contact/punch_obstacle.h>
#include <signorini/contact/sphere_obstacle.h>
#include <signorini/output/file_output.h>

#include <stdexcept>

namespace signorini
{
  using namespace dealii;

  template <int dim>
  void
  Obstacle<dim>::write_vtu(std::ostream &out, const BoundingBox<dim> &box) const
  {
    write_surfaces_vtu<dim>(out, {surface(box)}, {1});
  }

  template <int dim>
  void
  write_surfaces_vtu(std::ostream                        &out,
                     const std::vector<SurfaceMesh<dim>> &meshes,
                     const std::vector<unsigned int>     &numbers)
  {
    // VTK's line, triangle and quadrilateral.
    constexpr std::uint8_t line = 3, triangle = 5, quadrilateral = 9;
    VtuPiece               piece;
    piece.fields.push_back({"obstacle", 1, {}});
    auto &number_field = piece.fields.back().values;
    for (unsigned int m = 0; m < meshes.size(); ++m)
      for (const auto &cell : meshes[m].cells)
        {
          // Each cell has points of its own.
          for (const unsigned int v : cell)
            {
              const auto &p = meshes[m].points[v];
              piece.connectivity.push_back(number_field.size());
              for (unsigned int d = 0; d < 3; ++d)
                piece.points.push_back(d < dim ? static_cast<float>(p[d]) :
                                                 0.f);
              number_field.push_back(static_cast<float>(numbers[m]));
            }
          piece.offsets.push_back(piece.connectivity.size());
          switch (cell.size())
            {
              case 2:
                piece.types.push_back(line);
                break;
              case 3:
                piece.types.push_back(triangle);
                break;
              case 4:
                piece.types.push_back(quadrilateral);
                break;
              default:
                throw std::logic_error("a surface cell of " +
                                       std::to_string(cell.size()) + " points");
            }
        }
    // Small and written once: zlib, which every VTK reader reads.
    write_vtu(out, piece, VtuCompression::zlib, 1);
  }

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

  template class Obstacle<2>;
  template class Obstacle<3>;
  template void
  write_surfaces_vtu(std::ostream &,
                     const std::vector<SurfaceMesh<2>> &,
                     const std::vector<unsigned int> &);
  template void
  write_surfaces_vtu(std::ostream &,
                     const std::vector<SurfaceMesh<3>> &,
                     const std::vector<unsigned int> &);
  template std::unique_ptr<Obstacle<2>>
  create_obstacle(const ObstacleDescription<2> &);
  template std::unique_ptr<Obstacle<3>>
  create_obstacle(const ObstacleDescription<3> &);
} // namespace signorini
