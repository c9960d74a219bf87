#include <deal.II/base/mpi.h>

#include <signorini/base/text.h>
#include <signorini/contact/contact_surface.h>
#include <signorini/input/input_error.h>

#include <sstream>

namespace signorini
{
  using namespace dealii;

  namespace
  {
    template <int dim>
    std::string
    point_text(const Point<dim> &p)
    {
      std::ostringstream text;
      text << '(' << p << ')';
      return text.str();
    }
  } // namespace

  template <int dim>
  void
  ContactSurface<dim>::check_vertices(
    const std::vector<Vertex>                        &vertices,
    const std::map<types::boundary_id, unsigned int> &acting_vertices,
    const AffineConstraints<double>                  &constraints) const
  {
    const unsigned int        n_obstacles = obstacle_set.size();
    std::optional<InputError> error;
    for (const auto &vertex : vertices)
      for (unsigned int k = 0; k < n_obstacles && !error; ++k)
        {
          // The body inside an obstacle before it moves.
          const double initial = obstacle_set.initial_gap(k, vertex.position);
          if (!obstacle_set.may_start_inside(k) && initial < -tolerance)
            error = InputError(
              obstacle_set[k].entry(),
              "the body starts inside this obstacle: its contact node " +
                point_text(vertex.position) + " lies " + number(-initial) +
                " mm inside (place the obstacle outside the body, and "
                "press it in by its Displacement)");
          // A support that holds a node inside an obstacle.
          const auto &n = vertex.normals[k];
          if (free_part(n, vertex.free) >= fixed_along_normal)
            continue;
          double held_gap  = vertex.gaps[k];
          bool   supported = true;
          for (unsigned int d = 0; d < dim; ++d)
            if (n[d] != 0.)
              {
                const auto *entries =
                  constraints.get_constraint_entries(vertex.dofs[d]);
                if (entries != nullptr && !entries->empty())
                  supported = false; // a hanging node, not a support
                else
                  held_gap +=
                    n[d] * constraints.get_inhomogeneity(vertex.dofs[d]);
              }
          if (!error && supported && held_gap < -tolerance)
            error =
              InputError("Boundary conditions/Dirichlet",
                         "holds the contact node " +
                           point_text(vertex.position) + " " +
                           number(-held_gap) + " mm inside the obstacle " +
                           obstacle_set[k].entry() +
                           ", along whose normal it cannot move");
        }
    throw_first(error, mpi_communicator);

    // Contact boundary ids on which no node can touch an obstacle.
    for (const auto id : ids)
      {
        unsigned int seen = 0;
        for (const auto &vertex : vertices)
          seen += vertex.boundary_ids.count(id);
        seen                  = Utilities::MPI::sum(seen, mpi_communicator);
        const auto         at = acting_vertices.find(id);
        const unsigned int acting =
          Utilities::MPI::sum(at == acting_vertices.end() ? 0U : at->second,
                              mpi_communicator);
        if (seen > 0 && acting == 0)
          throw InputError(
            "Obstacle/Contact boundary ids",
            "no node of boundary id " + std::to_string(id) +
              " can touch an obstacle: Boundary conditions/Dirichlet "
              "fixes each along the obstacles' normals");
      }
  }

  template void
  ContactSurface<2>::check_vertices(
    const std::vector<Vertex> &,
    const std::map<types::boundary_id, unsigned int> &,
    const AffineConstraints<double> &) const;
  template void
  ContactSurface<3>::check_vertices(
    const std::vector<Vertex> &,
    const std::map<types::boundary_id, unsigned int> &,
    const AffineConstraints<double> &) const;
} // namespace signorini
