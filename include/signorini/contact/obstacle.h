#ifndef signorini_contact_obstacle_h
#define signorini_contact_obstacle_h

#include <deal.II/base/bounding_box.h>
#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

#include <signorini/contact/obstacle_parameters.h>

#include <cmath>
#include <memory>
#include <ostream>
#include <string>
#include <vector>

namespace signorini
{
  /**
   * A surface for ParaView: points and the cells between them, segments
   * (2 points) in 2D, triangles or quadrilaterals (3 or 4 points, in VTK's
   * order) in 3D.
   */
  template <int dim>
  struct SurfaceMesh
  {
    std::vector<dealii::Point<dim>>        points;
    std::vector<std::vector<unsigned int>> cells;
  };

  /**
   * A unit vector across @p direction: the coordinate axis least aligned
   * with it (the first of equals), made orthogonal to it (a tangent of a
   * plane of normal @p direction, a radial direction of an axis).
   */
  template <int dim>
  inline dealii::Tensor<1, dim>
  unit_vector_across(const dealii::Tensor<1, dim> &direction)
  {
    unsigned int axis = 0;
    for (unsigned int d = 1; d < dim; ++d)
      if (std::abs(direction[d]) < std::abs(direction[axis]))
        axis = d;
    dealii::Tensor<1, dim> across;
    across[axis] = 1.;
    across -= (across * direction) * direction;
    return across / across.norm();
  }

  /**
   * A rigid obstacle: for a point of the body, how far it is from the
   * obstacle's surface and in which direction the surface faces it.
   *
   * The normal n is the obstacle's outward unit normal (pointing from the
   * obstacle towards the body). A displacement u of the point changes its
   * gap g to g + n.u; the body may not penetrate, g + n.u >= 0, and the
   * obstacle pushes back along n.
   */
  template <int dim>
  class Obstacle
  {
  public:
    virtual ~Obstacle() = default;

    /** The gap of @p point [mm] (negative inside the obstacle) and, in
     * @p normal, the obstacle's outward unit normal there. */
    virtual double
    gap(const dealii::Point<dim> &point,
        dealii::Tensor<1, dim>   &normal) const = 0;

    /** The gap of @p point to the obstacle moved by @p displacement, and
     * its normal there: the gap of the point moved back, unless the
     * obstacle's small-strain contact depends on where the point lies
     * against the obstacle before it moved (PunchObstacle). */
    virtual double
    moved_gap(const dealii::Point<dim>     &point,
              const dealii::Tensor<1, dim> &displacement,
              dealii::Tensor<1, dim>       &normal) const
    {
      return gap(point - displacement, normal);
    }

    /** The parameter entry that describes the obstacle, for messages
     * ("Obstacle 2/Center"). */
    virtual std::string
    entry() const = 0;

    /** The obstacle's surface around @p box (the body's bounding box), for
     * ParaView. */
    virtual SurfaceMesh<dim>
    surface(const dealii::BoundingBox<dim> &box) const = 0;
  };


} // namespace signorini

#endif
