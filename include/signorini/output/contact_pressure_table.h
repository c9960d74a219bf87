#ifndef signorini_output_contact_pressure_table_h
#define signorini_output_contact_pressure_table_h

#include <deal.II/lac/trilinos_vector.h>

#include <signorini/contact/contact_surface.h>

#include <string>

namespace signorini
{
  /** Writes @p file (contact_pressure-CC.csv): one row per contact node,
   * gathered on process 0 and sorted by position, with the node's
   * coordinates, contact pressure [MPa], deformed gap [mm], obstacle,
   * state and frame; with friction (@p tangential: the obstacle's shear
   * traction at the nodes' dofs, ghosted) its shear traction [MPa] and its
   * slip of the load step [mm] along each tangent. Collective; process 0
   * writes. */
  template <int dim>
  void
  write_contact_pressure_table(
    const std::string                           &file,
    const ContactSurface<dim>                   &surface,
    const dealii::TrilinosWrappers::MPI::Vector &pressure,
    const dealii::TrilinosWrappers::MPI::Vector &solution,
    const MPI_Comm                               mpi_communicator,
    const dealii::TrilinosWrappers::MPI::Vector *tangential = nullptr);
} // namespace signorini

#endif
