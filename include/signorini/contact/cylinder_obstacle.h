#ifndef signorini_contact_cylinder_obstacle_h
#define signorini_contact_cylinder_obstacle_h

#include <signorini/contact/obstacle.h>

namespace signorini
{
  /**
   * A rigid circular cylinder of radius R around the axis through c along
   * the unit vector a (in 2D a circle around c, the section of a cylinder
   * along z). The radial vector r of x is x - c without its part along a;
   * with the body outside (a roller, a pin), gap |r| - R and normal
   * r/|r|; with the body inside (a shaft in a bore), gap R - |r| and normal
   * -r/|r|.
   */
  template <int dim>
  class CylinderObstacle : public Obstacle<dim>
  {
  public:
    /** @p axis is ignored in 2D; @p entry is the parameter entry of
     * @p center. */
    CylinderObstacle(const dealii::Point<dim>     &center,
                     const dealii::Tensor<1, dim> &axis,
                     const double                  radius,
                     const bool                    body_inside,
                     const std::string            &entry);

    double
    gap(const dealii::Point<dim> &point,
        dealii::Tensor<1, dim>   &normal) const override;

    std::string
    entry() const override;

    /** In 2D the circle (360 segments); in 3D the mantle over the axial
     * extent of @p box enlarged by a tenth on each side (96 cells around). */
    SurfaceMesh<dim>
    surface(const dealii::BoundingBox<dim> &box) const override;

  private:
    const dealii::Point<dim>     center;
    const dealii::Tensor<1, dim> axis;
    const double                 radius;
    const bool                   body_inside;
    const std::string            center_entry;
  };
} // namespace signorini

#endif
