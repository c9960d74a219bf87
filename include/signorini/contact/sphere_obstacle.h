#ifndef signorini_contact_sphere_obstacle_h
#define signorini_contact_sphere_obstacle_h

#include <signorini/contact/obstacle.h>

namespace signorini
{
  /**
   * A rigid sphere (a circle in 2D) of center c and radius R, with the body
   * outside it (a ball pressed onto a ball, an indenter), gap |x - c| - R
   * and normal (x - c)/|x - c|, or inside it (a ball in a spherical cup),
   * gap R - |x - c| and normal (c - x)/|x - c|.
   */
  template <int dim>
  class SphereObstacle : public Obstacle<dim>
  {
  public:
    /** @p entry is the parameter entry of @p center. */
    SphereObstacle(const dealii::Point<dim> &center,
                   const double              radius,
                   const bool                body_inside,
                   const std::string        &entry);

    double
    gap(const dealii::Point<dim> &point,
        dealii::Tensor<1, dim>   &normal) const override;

    std::string
    entry() const override;

    /** The whole sphere: 360 segments in 2D, 48 x 96 cells in 3D. */
    SurfaceMesh<dim>
    surface(const dealii::BoundingBox<dim> &box) const override;

  private:
    const dealii::Point<dim> center;
    const double             radius;
    const bool               body_inside;
    const std::string        center_entry;
  };
} // namespace signorini

#endif
