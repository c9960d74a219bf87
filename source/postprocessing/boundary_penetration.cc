#include <deal.II/base/mpi.h>

#include <signorini/base/text.h>
#include <signorini/input/input_error.h>
#include <signorini/postprocessing/boundary_penetration.h>

#include <algorithm>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace signorini
{
  using namespace dealii;

  template <int dim>
  void
  check_boundary_penetration(const Discretisation<dim> &discretisation,
                             const ContactSurface<dim> &surface,
                             const TrilinosWrappers::MPI::Vector &solution,
                             const unsigned int                   cycle)
  {
    const auto &obstacles   = surface.obstacles();
    const auto &contact_ids = surface.contact_ids();
    const auto  u           = discretisation.relevant_copy(solution);
    // The vertices of contact faces: obstacles may press on them.
    std::set<unsigned int> on_contact_faces;
    for (const auto &cell :
         discretisation.dof_handler().active_cell_iterators())
      if (!cell->is_artificial())
        for (const auto &face : cell->face_iterators())
          if (face->at_boundary() && contact_ids.count(face->boundary_id()))
            for (const unsigned int v : face->vertex_indices())
              on_contact_faces.insert(face->vertex_index(v));

    // As deep as the contact nodes penetrate (the penalty's O(eps)).
    double allowed = 0.;
    for (const auto &node : surface.nodes())
      if (node.owned)
        allowed = std::max(allowed, -surface.deformed_gap(node, solution));
    const double tolerance =
      1e-6 * discretisation.body_size() +
      Utilities::MPI::max(allowed, discretisation.mpi_communicator());
    double      deepest = tolerance;
    std::string where;
    for (const auto &cell :
         discretisation.dof_handler().active_cell_iterators())
      if (cell->is_locally_owned())
        for (const auto &face : cell->face_iterators())
          if (face->at_boundary() && !contact_ids.count(face->boundary_id()))
            for (const unsigned int v : face->vertex_indices())
              {
                if (on_contact_faces.count(face->vertex_index(v)))
                  continue;
                Point<dim> x = face->vertex(v);
                for (unsigned int d = 0; d < dim; ++d)
                  x[d] += u(face->vertex_dof_index(v, d));
                for (unsigned int k = 0; k < obstacles.size(); ++k)
                  {
                    Tensor<1, dim> normal;
                    const double   depth = -obstacles.gap(k, x, normal);
                    if (depth > deepest)
                      {
                        deepest = depth;
                        std::ostringstream text;
                        text << "boundary id " << face->boundary_id()
                             << ", which is not a contact boundary, lies "
                             << number(depth) << " mm inside the obstacle "
                             << obstacles[k].entry() << " at ("
                             << face->vertex(v) << ")";
                        where = text.str();
                      }
                  }
              }
    // The deepest of all processes (the first by rank at a tie).
    const auto all =
      Utilities::MPI::all_gather(discretisation.mpi_communicator(),
                                 std::make_pair(deepest, where));
    std::pair<double, std::string> worst = {tolerance, ""};
    for (const auto &found : all)
      if (found.first > worst.first)
        worst = found;
    if (!worst.second.empty())
      throw InputError("Obstacle/Contact boundary ids",
                       "after cycle " + std::to_string(cycle) + " the " +
                         worst.second +
                         ": nothing holds the body off an obstacle there, so "
                         "it would pass through; add that id to the contact "
                         "boundary ids, or move the obstacle");
  }

  template void
  check_boundary_penetration(const Discretisation<2> &,
                             const ContactSurface<2> &,
                             const TrilinosWrappers::MPI::Vector &,
                             const unsigned int);
  template void
  check_boundary_penetration(const Discretisation<3> &,
                             const ContactSurface<3> &,
                             const TrilinosWrappers::MPI::Vector &,
                             const unsigned int);
} // namespace signorini
