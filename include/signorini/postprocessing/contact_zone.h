#ifndef signorini_postprocessing_contact_zone_h
#define signorini_postprocessing_contact_zone_h

#include <deal.II/base/tensor.h>
#include <deal.II/lac/trilinos_vector.h>

#include <signorini/contact/contact_surface.h>
#include <signorini/contact/obstacle.h>
#include <signorini/discretisation/discretisation.h>
#include <signorini/postprocessing/reference.h>

namespace signorini
{
  /** What a cycle's contact zone measures. */
  template <int dim>
  struct ContactZone
  {
    /** Largest nodal contact pressure [MPa]. */
    double max_pressure = 0.;
    /** Extent along x of the active nodes [mm]. */
    double contact_width = 0.;
    /** Integral of the contact pressure over the contact boundary [N]. */
    double integrated_pressure = 0.;
    /** Integral of the contact pressure times the obstacle's normal: the
     * force of the obstacle on the body [N]. */
    dealii::Tensor<1, dim> pressure_resultant;
    /** Relative L2 error of the pressure against Reference/Contact pressure
     * (NaN if none). */
    double pressure_error = 0.;
  };

  /**
   * The contact zone of the nodal contact @p pressure (at each contact
   * node's scalar dof, ghosted): its largest value, the extent of the active
   * nodes, and the integral of the pressure field that interpolates the
   * nodal values (a hanging node takes the pressure its masters give it, a
   * supported one none), with a Gauss rule of high order, since a closed-form
   * pressure has a square-root edge. Integrals are weighted by
   * Discretisation::weight (over the whole revolution of an axisymmetric
   * model).
   */
  template <int dim>
  ContactZone<dim>
  evaluate_contact_zone(const Discretisation<dim> &discretisation,
                        const ContactSurface<dim> &surface,
                        const Obstacle<dim>       &obstacle,
                        const dealii::TrilinosWrappers::MPI::Vector &pressure,
                        const Reference<dim>                        &reference);
} // namespace signorini

#endif
