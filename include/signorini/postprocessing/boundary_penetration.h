#ifndef signorini_postprocessing_boundary_penetration_h
#define signorini_postprocessing_boundary_penetration_h

#include <deal.II/base/types.h>
#include <deal.II/lac/trilinos_vector.h>

#include <signorini/contact/contact_surface.h>
#include <signorini/discretisation/discretisation.h>

namespace signorini
{
  /**
   * Checks that no obstacle passes through the body where nothing holds it
   * off: the deformed vertices of the boundary faces that are not contact
   * boundaries (Obstacle/Contact boundary ids), but for those they share
   * with a contact face, must lie outside every obstacle (to 1e-6 of the
   * body's size, and as deep as the contact nodes of @p surface are inside
   * theirs: a method that lets them penetrate, the penalty's O(eps), lets
   * their neighbours do so too). Throws an InputError on `Obstacle/Contact
   * boundary ids` naming the cycle, the boundary id, the obstacle, the depth
   * and the point of the deepest such vertex (an obstacle moved into a face
   * that may not touch it). Collective.
   */
  template <int dim>
  void
  check_boundary_penetration(
    const Discretisation<dim>                   &discretisation,
    const ContactSurface<dim>                   &surface,
    const dealii::TrilinosWrappers::MPI::Vector &solution,
    const unsigned int                           cycle);
} // namespace signorini

#endif
