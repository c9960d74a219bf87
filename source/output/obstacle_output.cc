#include <signorini/output/file_output.h>
#include <signorini/output/obstacle_output.h>

#include <cstdint>
#include <stdexcept>

namespace signorini
{
  using namespace dealii;

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
  void
  write_obstacle_vtu(std::ostream           &out,
                     const Obstacle<dim>    &obstacle,
                     const BoundingBox<dim> &box)
  {
    write_surfaces_vtu<dim>(out, {obstacle.surface(box)}, {1});
  }

  template <int dim>
  void
  write_obstacles_vtu(std::ostream           &out,
                      const ObstacleSet<dim> &obstacles,
                      const BoundingBox<dim> &box)
  {
    std::vector<SurfaceMesh<dim>> meshes;
    for (unsigned int k = 0; k < obstacles.size(); ++k)
      meshes.push_back(obstacles.moved_surface(k, box));
    write_surfaces_vtu(out, meshes, obstacles.obstacle_numbers());
  }

  template void
  write_surfaces_vtu(std::ostream &,
                     const std::vector<SurfaceMesh<2>> &,
                     const std::vector<unsigned int> &);
  template void
  write_surfaces_vtu(std::ostream &,
                     const std::vector<SurfaceMesh<3>> &,
                     const std::vector<unsigned int> &);
  template void
  write_obstacle_vtu(std::ostream &,
                     const Obstacle<2> &,
                     const BoundingBox<2> &);
  template void
  write_obstacle_vtu(std::ostream &,
                     const Obstacle<3> &,
                     const BoundingBox<3> &);
  template void
  write_obstacles_vtu(std::ostream &,
                      const ObstacleSet<2> &,
                      const BoundingBox<2> &);
  template void
  write_obstacles_vtu(std::ostream &,
                      const ObstacleSet<3> &,
                      const BoundingBox<3> &);
} // namespace signorini
