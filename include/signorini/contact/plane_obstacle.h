#ifndef signorini_contact_plane_obstacle_h
#define signorini_contact_plane_obstacle_h

#include <signorini/contact/obstacle.h>

namespace signorini
{
  /**
   * A rigid half-space: the plane through a point with an outward unit
   * normal n (pointing towards the body). The gap of x is (x - point).n,
   * the normal n everywhere: a floor, a wall, a plate pressing from above,
   * an inclined wall.
   */
  template <int dim>
  class PlaneObstacle : public Obstacle<dim>
  {
  public:
    /** @p normal need not be a unit vector, but not zero; @p entry is the
     * parameter entry of @p point. */
    PlaneObstacle(const dealii::Point<dim>     &point,
                  const dealii::Tensor<1, dim> &normal,
                  const std::string            &entry);

    double
    gap(const dealii::Point<dim> &point,
        dealii::Tensor<1, dim>   &normal) const override;

    std::string
    entry() const override;

    /** The part of the plane over @p box (its corners projected onto the
     * plane), enlarged by a tenth on each side: a segment in 2D, a
     * rectangle in 3D. */
    SurfaceMesh<dim>
    surface(const dealii::BoundingBox<dim> &box) const override;

  private:
    const dealii::Point<dim>     point;
    const dealii::Tensor<1, dim> unit_normal;
    const std::string            point_entry;
  };
} // namespace signorini

#endif
