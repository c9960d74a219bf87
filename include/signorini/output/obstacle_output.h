#ifndef signorini_output_obstacle_output_h
#define signorini_output_obstacle_output_h

#include <deal.II/base/bounding_box.h>

#include <signorini/contact/obstacle.h>
#include <signorini/contact/obstacle_set.h>

#include <ostream>
#include <vector>

namespace signorini
{
  /**
   * Writes the surfaces @p meshes as one VTU file (zlib-compressed, each
   * cell with points of its own), with the point field `obstacle` holding
   * each surface's entry of @p numbers.
   */
  template <int dim>
  void
  write_surfaces_vtu(std::ostream                        &out,
                     const std::vector<SurfaceMesh<dim>> &meshes,
                     const std::vector<unsigned int>     &numbers);

  /** Writes @p obstacle's surface around @p box (the body's bounding box)
   * as a VTU file, for ParaView. */
  template <int dim>
  void
  write_obstacle_vtu(std::ostream                   &out,
                     const Obstacle<dim>            &obstacle,
                     const dealii::BoundingBox<dim> &box);

  /** Writes the surfaces of @p obstacles, where they are, in one VTU file
   * (obstacle.vtu), with their numbers as the point field `obstacle`. */
  template <int dim>
  void
  write_obstacles_vtu(std::ostream                   &out,
                      const ObstacleSet<dim>         &obstacles,
                      const dealii::BoundingBox<dim> &box);
} // namespace signorini

#endif
