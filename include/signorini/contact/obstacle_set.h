#ifndef signorini_contact_obstacle_set_h
#define signorini_contact_obstacle_set_h

#include <deal.II/base/bounding_box.h>
#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

#include <signorini/contact/obstacle.h>
#include <signorini/contact/obstacle_parameters.h>
#include <signorini/input/time_vector.h>

#include <memory>
#include <ostream>
#include <string>
#include <vector>

namespace signorini
{
  /**
   * The rigid obstacles of a scene, each moved by its displacement and
   * known by its number (N of its subsection `Obstacle N`; 1 for
   * `Obstacle`). As one Obstacle, the gap of a point is its gap to the
   * nearest obstacle (the smallest), with that obstacle's normal.
   */
  template <int dim>
  class ObstacleSet : public Obstacle<dim>
  {
  public:
    /** Adds @p obstacle, moved by @p displacement [mm] (a function of the
     * pseudo-time t, see set_time(); a constant is where it is from the
     * start), as number @p number; @p may_start_inside: the body may start
     * inside it. */
    void
    add(std::unique_ptr<Obstacle<dim>> obstacle,
        const TimeVector<dim>         &displacement     = {},
        const unsigned int             number           = 0,
        const bool                     may_start_inside = true);

    /** Moves each obstacle to its displacement at the pseudo-time @p t of
     * the load history. Throws InputError naming the entry and t if a
     * displacement is not finite there. */
    void
    set_time(const double t);

    /** The displacement [mm] of obstacle @p k where it is now. */
    const dealii::Tensor<1, dim> &
    displacement(const unsigned int k) const;

    unsigned int
    size() const;

    /** The number of obstacle @p k (1 for the first subsection). */
    unsigned int
    number(const unsigned int k) const;

    /** The gap of @p point to obstacle @p k where it is (moved) and its
     * normal there. */
    double
    gap(const unsigned int        k,
        const dealii::Point<dim> &point,
        dealii::Tensor<1, dim>   &normal) const;

    /** The gap of @p point to obstacle @p k before its displacement. */
    double
    initial_gap(const unsigned int k, const dealii::Point<dim> &point) const;

    /** Whether the body may start inside obstacle @p k. */
    bool
    may_start_inside(const unsigned int k) const;

    /** Whether the scene has one obstacle, a height (whose statistics keep
     * their original columns). */
    bool
    single_height() const;

    /** Obstacle @p k, not moved. */
    const Obstacle<dim> &
    operator[](const unsigned int k) const;

    /** The obstacle nearest to @p point (smallest gap; the first of
     * equals). */
    unsigned int
    nearest(const dealii::Point<dim> &point) const;

    /** The obstacle that a boundary point @p point with outward normal
     * @p boundary_normal faces most squarely: the largest -n.n_k (the
     * nearest of equals). The part of the boundary that an obstacle acts
     * on. */
    unsigned int
    facing(const dealii::Point<dim>     &point,
           const dealii::Tensor<1, dim> &boundary_normal) const;

    /** The gap to the nearest obstacle and its normal. */
    double
    gap(const dealii::Point<dim> &point,
        dealii::Tensor<1, dim>   &normal) const override;

    /** The entries of the obstacles, joined by ", ". */
    std::string
    entry() const override;

    /** All obstacles' surfaces, where they are. */
    SurfaceMesh<dim>
    surface(const dealii::BoundingBox<dim> &box) const override;

    /** Obstacle @p k's surface around @p box, moved. */
    SurfaceMesh<dim>
    moved_surface(const unsigned int              k,
                  const dealii::BoundingBox<dim> &box) const;

    /** Each obstacle's number (1 for `Obstacle`, 2 for `Obstacle 2`, ...). */
    const std::vector<unsigned int> &
    obstacle_numbers() const;

  private:
    std::vector<std::unique_ptr<Obstacle<dim>>> obstacles;
    std::vector<TimeVector<dim>>                histories;
    std::vector<dealii::Tensor<1, dim>>         displacements;
    std::vector<unsigned int>                   numbers;
    std::vector<bool>                           may_start_inside_flags;
  };

  /** The obstacles of @p parameters. Throws InputError. */
  template <int dim>
  std::unique_ptr<ObstacleSet<dim>>
  create_obstacles(const ObstacleParameters<dim> &parameters);

  /** The obstacle that @p description describes (one kind). Throws
   * InputError, e.g. for a geometry file that cannot be read. */
  template <int dim>
  std::unique_ptr<Obstacle<dim>>
  create_obstacle(const ObstacleDescription<dim> &description);
} // namespace signorini

#endif
