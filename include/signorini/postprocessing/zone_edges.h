#ifndef signorini_postprocessing_zone_edges_h
#define signorini_postprocessing_zone_edges_h

#include <deal.II/base/point.h>
#include <deal.II/lac/trilinos_vector.h>

#include <signorini/contact/contact_surface.h>
#include <signorini/discretisation/discretisation.h>

#include <vector>

namespace signorini
{
  /** Where one obstacle's contact zone and stick zone end between the
   * nodes (points on the contact boundary) [mm]. */
  template <int dim>
  struct ZoneEdges
  {
    /** A point between each node in contact and each open node next to it
     * along the contact boundary. */
    std::vector<dealii::Point<dim>> contact;
    /** A point between each sticking node and each node next to it that
     * does not stick. */
    std::vector<dealii::Point<dim>> stick;
  };

  /**
   * The edges of each obstacle's contact and stick zones between the nodes:
   * along the contact boundary's line of nodes in 2D and axisymmetric
   * models, along the lines of each face's grid of nodes in 3D (its edges,
   * and at degree 2 the lines through its centre). The same on every
   * process.
   *
   * At a smooth edge the pressure falls to zero like the square root of the
   * distance to the edge, and a sticking node's margin to the friction
   * bound does too, while the gap of an open node and the slip of a
   * slipping node grow like its 3/2 power. So the edge of the contact zone
   * is where p^2, extrapolated linearly from the last two nodes in contact
   * (along the boundary; in 3D along the line from the open node through
   * the last node in contact), vanishes; for Hertz's p = p0 sqrt(1 - x^2/a^2)
   * that is exact up to O(h^2/a), where the nodes alone err by up to h.
   * The edge of the stick zone is where |s|^(2/3), the slip of the load
   * step extrapolated from the first two slipping nodes, vanishes (the
   * margin of the nodal shear tractions is too rough near it), or the
   * contact zone's edge where the stick zone reaches it. Each edge lies
   * between its two nodes; where the values do not fall towards it (the
   * pressure at a punch's sharp rim rises) it is at the last node inside.
   *
   * @p pressure: the nodal contact pressure at each node's scalar dof,
   * @p solution: the displacement (both ghosted).
   */
  template <int dim>
  std::vector<ZoneEdges<dim>>
  estimate_zone_edges(const Discretisation<dim> &discretisation,
                      const ContactSurface<dim> &surface,
                      const dealii::TrilinosWrappers::MPI::Vector &pressure,
                      const dealii::TrilinosWrappers::MPI::Vector &solution);
} // namespace signorini

#endif
