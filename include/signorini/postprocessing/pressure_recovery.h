#ifndef signorini_postprocessing_pressure_recovery_h
#define signorini_postprocessing_pressure_recovery_h

#include <deal.II/lac/trilinos_vector.h>

#include <signorini/contact/contact_surface.h>
#include <signorini/discretisation/discretisation.h>

namespace signorini
{
  /**
   * The contact pressure as a field of the displacement's trace space,
   * recovered from the nodal contact forces: at degree 2 the nodal pressure
   * F_i / m_i with the lumped (Gauss-Lobatto) masses m_i, which the contact
   * algorithm uses, is off by O(h^2 p'') with opposite signs at vertices and
   * mid-nodes (for a smooth p in 1D: -p''h^2/20 at a vertex, +p''h^2/40 at
   * a mid-node, h the face's length; 0.3 % of Hertz's p0 at h = a/4). The
   * field p_h = sum p_j phi_j whose consistent nodal forces are the nodal
   * forces, M p = F with M_ij the integral of phi_i phi_j over the contact
   * boundary (hanging nodes condensed; weighted by 2 pi r in an
   * axisymmetric model), reproduces a quadratic pressure exactly, and its
   * integral is the contact force as the lumped one's is. Near the edge of
   * the contact zone, where the pressure falls like a square root, it
   * overshoots by a few percent over one face.
   *
   * The nodes of one obstacle that are no corner's take part; the others
   * keep their nodal values. Degree 1 returns @p pressure as it is (its
   * lumped pressure is what the tests and charts of Q1 were made with). The
   * boundary's mass matrix is gathered on every process and factorised
   * there (a contact surface has far fewer nodes than the body).
   *
   * @p pressure: the nodal contact pressure at the nodes' scalar dofs
   * (ghosted); returns the recovered pressure in the same layout (ghosted).
   * Collective.
   */
  template <int dim>
  dealii::TrilinosWrappers::MPI::Vector
  recover_pressure(const Discretisation<dim>                   &discretisation,
                   const ContactSurface<dim>                   &surface,
                   const dealii::TrilinosWrappers::MPI::Vector &pressure);
} // namespace signorini

#endif
