#ifndef signorini_contact_punch_obstacle_h
#define signorini_contact_punch_obstacle_h

#include <signorini/contact/obstacle.h>

namespace signorini
{
  /**
   * A rigid flat-ended punch: a cylinder of radius R whose flat end, a
   * disk of center c and outward normal n (pointing from the punch towards
   * the body), presses on the body; in 2D a strip of half-width R (the
   * section of an axisymmetric punch when c lies on the axis r = 0).
   *
   * For a point x, with d = (x - c).n its height over the end's plane and
   * t = x - c - d n its offset within that plane: under the end (|t| <= R)
   * the gap is d and the normal n; beyond the rim and in front of the end
   * (d >= 0) the gap is the distance to the rim and the normal points from
   * the rim to x; beside the punch (d < 0) the gap is |t| - R and the
   * normal t / |t| (its side wall).
   *
   * Moved or not (moved_gap()), a point beyond the rim that lay in front of the
   * end before the punch moved stays clear of it: its gap is its height
   * over the moved end plus 1000 R, along n. The small-strain model moves
   * it along the axis, past the punch, as Boussinesq's solution does, whose
   * contact is the end alone; its inward motion under the indented end (of
   * the order of the indentation) is geometry that model leaves out. (Held
   * by the side wall instead, the surface just beyond the rim carried
   * nodal pressures twice the rim's once the cells there became smaller
   * than that motion, and the axisymmetric punch's force left Boussinesq's
   * by 1.6 % over 4 more cycles.) A point that lay beside the punch (a
   * punch in a hole) keeps its side wall.
   */
  template <int dim>
  class PunchObstacle : public Obstacle<dim>
  {
  public:
    /** @p entry is the parameter entry of @p center. */
    PunchObstacle(const dealii::Point<dim>     &center,
                  const dealii::Tensor<1, dim> &normal,
                  const double                  radius,
                  const std::string            &entry);

    double
    gap(const dealii::Point<dim> &point,
        dealii::Tensor<1, dim>   &normal) const override;

    double
    moved_gap(const dealii::Point<dim>     &point,
              const dealii::Tensor<1, dim> &displacement,
              dealii::Tensor<1, dim>       &normal) const override;

    std::string
    entry() const override;

    /** The flat end and the side wall, back from the end as far as the
     * body's bounding box reaches (at least R). */
    SurfaceMesh<dim>
    surface(const dealii::BoundingBox<dim> &box) const override;

  private:
    const dealii::Point<dim>     center;
    const dealii::Tensor<1, dim> unit_normal;
    const double                 radius;
    const std::string            center_entry;
  };
} // namespace signorini

#endif
