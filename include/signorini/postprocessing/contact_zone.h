#ifndef signorini_postprocessing_contact_zone_h
#define signorini_postprocessing_contact_zone_h

#include <deal.II/base/tensor.h>
#include <deal.II/lac/trilinos_vector.h>

#include <signorini/base/statistics_row.h>
#include <signorini/contact/contact_surface.h>
#include <signorini/discretisation/discretisation.h>
#include <signorini/postprocessing/reference.h>

#include <vector>

namespace signorini
{
  /** What the contact with one obstacle measures. */
  template <int dim>
  struct ObstacleContact
  {
    /** Largest nodal contact pressure [MPa]. */
    double max_pressure = 0.;
    /** Extent of the contact zone [mm], of its active nodes and, in 2D and
     * axisymmetric models, of its edges between the nodes (see
     * estimate_zone_edges): in 2D
     * along the coordinate axis least aligned with the active nodes' mean
     * normal, made tangent to it (x for a floor, y for a wall x = const);
     * in an axisymmetric model along r (the contact radius where the zone
     * covers the axis, also on an inclined surface such as a cone in its
     * seat); in 3D the smaller of the extents along the two axes other
     * than the one most aligned with the normal (a round zone's diameter,
     * a line contact's width; its length is contact_area / width). */
    double contact_width = 0.;
    /** With friction, the extent of the stick zone [mm], of its sticking
     * nodes and edges, along the directions of contact_width. */
    double stick_width = 0.;
    /** Measure of the contact zone [mm in 2D, mm^2 in 3D and
     * axisymmetric]: the integral
     * over the contact boundary of the interpolated indicator of the
     * active nodes (faces between active nodes count whole, faces at the
     * zone's edge by the share of their active vertices). */
    double contact_area = 0.;
    /** The nodal forces of the obstacle on the body, sum of p_i m_i n_i
     * [N]. */
    dealii::Tensor<1, dim> force;
  };

  /** What a cycle's contact zone measures. */
  template <int dim>
  struct ContactZone
  {
    /** Largest nodal contact pressure [MPa]. */
    double max_pressure = 0.;
    /** The largest contact_width of the obstacles [mm]. */
    double contact_width = 0.;
    /** The largest stick_width of the obstacles [mm]. */
    double stick_width = 0.;
    /** The sum of the obstacles' contact_area [mm in 2D, mm^2 in 3D and in
     * an axisymmetric model, where it is the area of revolution]. */
    double contact_area = 0.;
    /** Whether the measures are of a revolved (axisymmetric) model: the
     * contact width is then the radial extent (the contact radius where
     * the zone covers the axis) and the contact area an area. */
    bool revolved = false;
    /** Integral of the contact pressure over the contact boundary [N]. */
    double integrated_pressure = 0.;
    /** Integral of the interpolated nodal pressure times normal: the force
     * of the obstacles on the body [N], the sum of the nodal forces. */
    dealii::Tensor<1, dim> pressure_resultant;
    /** Relative L2 error of the pressure against Reference/Contact pressure
     * (NaN if none). */
    double pressure_error = 0.;
    /** Each obstacle's contact, in the order of the ObstacleSet. */
    std::vector<ObstacleContact<dim>> obstacles;
    /** The obstacles' nodal forces on components that a support fixes,
     * sum of p_i m_i n_i there [N]: K u - f holds them in the support
     * reaction; and whether there are any. */
    dealii::Tensor<1, dim> supported_force;
    bool                   supported = false;
  };

  /**
   * The contact zone of the nodal contact @p pressure (at each contact
   * node's scalar dof, ghosted) and the displacement @p solution (ghosted):
   * its largest value, the extent of the zone (and with friction of its
   * stick zone), the measure of the active nodes, and the integral of the
   * pressure field that interpolates the nodal values of each obstacle (a
   * hanging node takes the pressure its masters give it, a supported one none),
   * with a Gauss rule of high order, since a closed-form pressure has a
   * square-root edge. Integrals are weighted by Discretisation::weight (over
   * the whole revolution of an axisymmetric model). With friction, @p
   * tangential (the obstacle's tangential traction at the contact nodes' dofs,
   * ghosted) adds its nodal forces to each obstacle's force and to the
   * resultant.
   */
  template <int dim>
  ContactZone<dim>
  evaluate_contact_zone(
    const Discretisation<dim>                   &discretisation,
    const ContactSurface<dim>                   &surface,
    const dealii::TrilinosWrappers::MPI::Vector &pressure,
    const dealii::TrilinosWrappers::MPI::Vector &solution,
    const Reference<dim>                        &reference,
    const dealii::TrilinosWrappers::MPI::Vector *tangential = nullptr);

  /**
   * Adds the statistics columns of the contact in general form, except for
   * a scene with one height obstacle (whose columns stay as they were):
   * `contact_area`, and with several obstacles, for obstacle N (its
   * subsection `Obstacle N`, 1 for `Obstacle`) `contact_forceN_x, _y[, _z]`,
   * `max_pressureN`, `contact_widthN` and `contact_areaN`. Prints them on
   * @p out.
   */
  template <int dim>
  void
  add_contact_columns(StatisticsRow          &row,
                      const ContactZone<dim> &zone,
                      const ObstacleSet<dim> &obstacles,
                      std::ostream           &out);
} // namespace signorini

#endif
