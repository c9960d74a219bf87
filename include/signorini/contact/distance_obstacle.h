#ifndef signorini_contact_distance_obstacle_h
#define signorini_contact_distance_obstacle_h

#include <deal.II/base/function.h>

#include <signorini/contact/obstacle.h>

namespace signorini
{
  /**
   * A rigid obstacle given by a signed-distance (level-set) function phi of
   * x, y[, z]: positive on the body's side, negative inside the obstacle,
   * zero on its surface. The gap of x is phi / |grad phi| (phi itself for a
   * true distance, and a first-order distance for any smooth level set near
   * its zero set), the normal grad phi / |grad phi|; the gradient by central
   * differences.
   */
  template <int dim>
  class DistanceObstacle : public Obstacle<dim>
  {
  public:
    /** @p distance is phi [mm], given by the parameter @p entry. */
    DistanceObstacle(const dealii::Function<dim> &distance,
                     const std::string           &entry);

    double
    gap(const dealii::Point<dim> &point,
        dealii::Tensor<1, dim>   &normal) const override;

    std::string
    entry() const override;

    /** The zero set of phi over @p box enlarged by a tenth on each side: a
     * grid of 200 x 200 squares (2D) or 40 x 40 x 40 cubes (3D), split into
     * triangles (tetrahedra), phi interpolated linearly along their edges. */
    SurfaceMesh<dim>
    surface(const dealii::BoundingBox<dim> &box) const override;

  private:
    const dealii::Function<dim> &distance;
    const std::string            distance_entry;
  };
} // namespace signorini

#endif
