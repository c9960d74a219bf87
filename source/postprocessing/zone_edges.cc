#include <deal.II/base/mpi.h>

#include <signorini/postprocessing/zone_edges.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <utility>

namespace signorini
{
  using namespace dealii;

  namespace
  {
    /** A contact node as every process sees it. */
    template <int dim>
    struct Sample
    {
      Point<dim>   position;
      double       pressure = 0.;
      double       slip     = 0.;
      NodeState    state    = NodeState::open;
      unsigned int obstacle = 0;
      /** The nodes next to it along the contact boundary (same obstacle). */
      std::vector<unsigned int> neighbours;
    };

    /** The point between @p inside and @p outside (next to it) where a
     * quantity that falls like the square root of the distance to the
     * edge vanishes, extrapolated from @p inner (the node before @p inside)
     * and @p inside with values @p v_inner > @p v_inside >= 0. */
    template <int dim>
    Point<dim>
    square_root_edge(const Point<dim> &inner,
                     const double      v_inner,
                     const Point<dim> &inside,
                     const double      v_inside,
                     const Point<dim> &outside)
    {
      if (!(v_inner > v_inside && v_inside >= 0.))
        return inside;
      const double distance = v_inside * v_inside * inner.distance(inside) /
                              (v_inner * v_inner - v_inside * v_inside);
      const double theta = std::min(1., distance / inside.distance(outside));
      return inside + theta * (outside - inside);
    }
  } // namespace

  template <int dim>
  std::vector<ZoneEdges<dim>>
  estimate_zone_edges(const Discretisation<dim>           &discretisation,
                      const ContactSurface<dim>           &surface,
                      const TrilinosWrappers::MPI::Vector &pressure,
                      const TrilinosWrappers::MPI::Vector &solution)
  {
    std::vector<ZoneEdges<dim>> edges(surface.obstacles().size());
    const MPI_Comm              comm = discretisation.mpi_communicator();

    // The owned nodes, (dof of x, obstacle, position, pressure, slip,
    // state) each, and the faces of the contact boundary, (dof of x at one
    // end, at the other) each, gathered on every process.
    std::vector<double> owned_nodes, owned_faces;
    for (const auto &node : surface.nodes())
      if (node.owned)
        {
          owned_nodes.push_back(node.dofs[0]);
          owned_nodes.push_back(node.obstacle);
          for (unsigned int d = 0; d < dim; ++d)
            owned_nodes.push_back(node.position[d]);
          owned_nodes.push_back(pressure(node.scalar_dof));
          owned_nodes.push_back(node.slip(solution).norm());
          owned_nodes.push_back(static_cast<double>(node.state));
        }
    // Pairs of nodes next to each other along the contact boundary: in 2D
    // a face's ends (at degree 2 each end with its mid-node); in 3D the
    // lines of a face's grid of nodes (its edges, at degree 2 through their
    // mid-nodes; on a quadrilateral also from the edges' mid-nodes through
    // the centre).
    const auto &fe   = discretisation.fe();
    const auto  pair = [&](const types::global_dof_index a,
                          const types::global_dof_index b) {
      owned_faces.push_back(a);
      owned_faces.push_back(b);
    };
    std::vector<types::global_dof_index> face_dofs(fe.n_dofs_per_face());
    surface.for_each_owned_face(
      discretisation, [&](const auto &cell, const unsigned int f) {
        const auto face   = cell->face(f);
        const auto vertex = [&](const unsigned int v) {
          return face->vertex_dof_index(v, 0);
        };
        if (dim == 2 && fe.degree == 1)
          pair(vertex(0), vertex(1));
        else if (dim == 2)
          {
            face->get_dof_indices(face_dofs);
            types::global_dof_index middle = 0;
            for (unsigned int i = 0; i < face_dofs.size(); ++i)
              if (fe.face_system_to_component_index(i) ==
                  std::make_pair(0U, 2U))
                middle = face_dofs[i];
            pair(vertex(0), middle);
            pair(middle, vertex(1));
          }
        else if (face->n_vertices() == 3 && fe.degree == 1)
          {
            pair(vertex(0), vertex(1));
            pair(vertex(1), vertex(2));
            pair(vertex(2), vertex(0));
          }
        else if (face->n_vertices() == 3)
          // A triangle's edges through their mid-nodes.
          for (unsigned int l = 0; l < 3; ++l)
            {
              const auto line   = face->line(l);
              const auto middle = line->dof_index(0);
              pair(line->vertex_dof_index(0, 0), middle);
              pair(middle, line->vertex_dof_index(1, 0));
            }
        else if (fe.degree == 1)
          {
            pair(vertex(0), vertex(1));
            pair(vertex(2), vertex(3));
            pair(vertex(0), vertex(2));
            pair(vertex(1), vertex(3));
          }
        else
          {
            // A quadrilateral's lines 0, 1 run from vertex 0 to 2
            // and 1 to 3, lines 2, 3 from 0 to 1 and 2 to 3.
            std::array<types::global_dof_index, 4> middle;
            for (unsigned int l = 0; l < 4; ++l)
              middle[l] = face->line(l)->dof_index(0);
            const types::global_dof_index centre = face->dof_index(0);
            const unsigned int ends[4][2] = {{0, 2}, {1, 3}, {0, 1}, {2, 3}};
            for (unsigned int l = 0; l < 4; ++l)
              {
                pair(vertex(ends[l][0]), middle[l]);
                pair(middle[l], vertex(ends[l][1]));
              }
            pair(middle[0], centre);
            pair(centre, middle[1]);
            pair(middle[2], centre);
            pair(centre, middle[3]);
          }
      });

    std::vector<Sample<dim>> samples;
    std::map<std::pair<types::global_dof_index, unsigned int>, unsigned int>
                       sample_at;
    const unsigned int width = dim + 5;
    for (const auto &part : Utilities::MPI::all_gather(comm, owned_nodes))
      for (std::size_t i = 0; i + width <= part.size(); i += width)
        {
          Sample<dim> sample;
          sample.obstacle = static_cast<unsigned int>(part[i + 1]);
          for (unsigned int d = 0; d < dim; ++d)
            sample.position[d] = part[i + 2 + d];
          sample.pressure = part[i + dim + 2];
          sample.slip     = part[i + dim + 3];
          sample.state    = static_cast<NodeState>(part[i + dim + 4]);
          sample_at[{static_cast<types::global_dof_index>(part[i]),
                     sample.obstacle}] = samples.size();
          samples.push_back(sample);
        }
    const unsigned int n_obstacles = edges.size();
    for (const auto &part : Utilities::MPI::all_gather(comm, owned_faces))
      for (std::size_t i = 0; i + 2 <= part.size(); i += 2)
        for (unsigned int k = 0; k < n_obstacles; ++k)
          {
            const auto a = sample_at.find(
              {static_cast<types::global_dof_index>(part[i]), k});
            const auto b = sample_at.find(
              {static_cast<types::global_dof_index>(part[i + 1]), k});
            if (a == sample_at.end() || b == sample_at.end())
              continue;
            samples[a->second].neighbours.push_back(b->second);
            samples[b->second].neighbours.push_back(a->second);
          }

    // The contact zone's edge between node i (in contact) and its open
    // neighbour n, from the pressure of i and of its other neighbour in
    // contact.
    // In 3D a node has neighbours in several directions: the node before
    // i is the one on the line from n through i (the neighbour most nearly
    // opposite n; none if no neighbour lies within 45 degrees of it).
    const auto before =
      [&](const unsigned int i, const unsigned int n, const auto &accepted) {
        unsigned int   chosen = numbers::invalid_unsigned_int;
        double         best   = std::sqrt(0.5);
        Tensor<1, dim> ahead  = samples[n].position - samples[i].position;
        ahead /= ahead.norm();
        for (const unsigned int j : samples[i].neighbours)
          if (j != n && accepted(j))
            {
              if (dim == 2)
                return j;
              Tensor<1, dim> back   = samples[i].position - samples[j].position;
              const double   cosine = back * ahead / back.norm();
              if (cosine > best)
                {
                  best   = cosine;
                  chosen = j;
                }
            }
        return chosen;
      };
    const auto contact_edge = [&](const unsigned int i, const unsigned int n) {
      const unsigned int j = before(i, n, [&](const unsigned int k) {
        return samples[k].state != NodeState::open;
      });
      if (j != numbers::invalid_unsigned_int)
        return square_root_edge(samples[j].position,
                                samples[j].pressure,
                                samples[i].position,
                                samples[i].pressure,
                                samples[n].position);
      return samples[i].position;
    };
    // The stick zone's edge between node i (sticking) and its slipping
    // neighbour n, from the slip of n and of its other slipping neighbour:
    // |s|^(2/3) falls linearly to the edge.
    const auto stick_edge = [&](const unsigned int i, const unsigned int n) {
      const auto &inside = samples[i].position, &outside = samples[n].position;
      const unsigned int m = before(n, i, [&](const unsigned int k) {
        return samples[k].state == NodeState::slip;
      });
      if (m == numbers::invalid_unsigned_int)
        return inside;
      const double w_n = std::cbrt(std::pow(samples[n].slip, 2));
      const double w_m = std::cbrt(std::pow(samples[m].slip, 2));
      if (!(w_m > w_n))
        return inside;
      const double distance =
        w_n * samples[m].position.distance(outside) / (w_m - w_n);
      const double theta = std::min(1., distance / outside.distance(inside));
      return Point<dim>(outside + theta * (inside - outside));
    };
    for (unsigned int i = 0; i < samples.size(); ++i)
      if (samples[i].state != NodeState::open)
        for (const unsigned int n : samples[i].neighbours)
          {
            auto           &zone = edges[samples[i].obstacle];
            const NodeState next = samples[n].state;
            if (next == NodeState::open)
              zone.contact.push_back(contact_edge(i, n));
            if (samples[i].state != NodeState::stick ||
                next == NodeState::stick)
              continue;
            if (next == NodeState::open)
              zone.stick.push_back(contact_edge(i, n));
            else if (next == NodeState::slip)
              zone.stick.push_back(stick_edge(i, n));
            else
              zone.stick.push_back(samples[i].position);
          }
    return edges;
  }

  template std::vector<ZoneEdges<2>>
  estimate_zone_edges(const Discretisation<2> &,
                      const ContactSurface<2> &,
                      const TrilinosWrappers::MPI::Vector &,
                      const TrilinosWrappers::MPI::Vector &);
  template std::vector<ZoneEdges<3>>
  estimate_zone_edges(const Discretisation<3> &,
                      const ContactSurface<3> &,
                      const TrilinosWrappers::MPI::Vector &,
                      const TrilinosWrappers::MPI::Vector &);
} // namespace signorini
