#ifndef signorini_contact_height_obstacle_h
#define signorini_contact_height_obstacle_h

#include <deal.II/base/function.h>

#include <signorini/contact/obstacle.h>

namespace signorini
{
  /**
   * An obstacle below the body whose surface is the graph of a height
   * function, y = psi(x) in 2D and z = psi(x, y) in 3D. The gap of a point
   * is its height above the surface, measured along the vertical, which is
   * the normal: the body approaches the obstacle from above (along -y, -z).
   */
  template <int dim>
  class HeightObstacle : public Obstacle<dim>
  {
  public:
    /** @p height is psi [mm], a function of dim - 1 coordinates, given by
     * the parameter @p entry. */
    HeightObstacle(const dealii::Function<dim - 1> &height,
                   const std::string               &entry = "Obstacle/Height");

    double
    gap(const dealii::Point<dim> &point,
        dealii::Tensor<1, dim>   &normal) const override;

    std::string
    entry() const override;

    /** The graph over the horizontal extent of @p box, enlarged by a tenth
     * on each side: 400 segments in 2D, 80 x 80 quadrilaterals in 3D. */
    SurfaceMesh<dim>
    surface(const dealii::BoundingBox<dim> &box) const override;

  private:
    /** psi at the horizontal coordinates of @p point. */
    double
    height_at(const dealii::Point<dim> &point) const;

    const dealii::Function<dim - 1> &height;
    const std::string                height_entry;
  };
} // namespace signorini

#endif
