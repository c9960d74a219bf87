#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_values.h>

#include <signorini/input/parsed_function.h>
#include <signorini/postprocessing/contact_zone.h>
#include <signorini/postprocessing/zone_edges.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <unordered_map>

namespace signorini
{
  using namespace dealii;

  namespace
  {
    /** The unit directions along a contact zone with the mean unit
     * @p normal, along which its width is measured: the radial one in an
     * axisymmetric model (the contact radius, also on an inclined
     * surface); in 2D the axis least aligned with the normal, made tangent
     * to it; in 3D both axes other than the one most aligned with it. */
    template <int dim>
    std::vector<Tensor<1, dim>>
    contact_zone_directions(const Tensor<1, dim> &normal,
                            const bool            axisymmetric)
    {
      if (axisymmetric)
        {
          Tensor<1, dim> radial;
          radial[0] = 1.;
          return {radial};
        }
      if (dim == 2)
        return {unit_vector_across(normal)};
      // In 3D the two axes other than the one most aligned with the normal,
      // each made tangent to it.
      unsigned int along = 0;
      for (unsigned int d = 1; d < dim; ++d)
        if (std::abs(normal[d]) > std::abs(normal[along]))
          along = d;
      std::vector<Tensor<1, dim>> directions;
      for (unsigned int d = 0; d < dim; ++d)
        if (d != along)
          {
            Tensor<1, dim> tangent;
            tangent[d] = 1.;
            tangent -= (tangent * normal) * normal;
            directions.push_back(tangent / tangent.norm());
          }
      return directions;
    }
  } // namespace

  template <int dim>
  ContactZone<dim>
  evaluate_contact_zone(const Discretisation<dim>           &discretisation,
                        const ContactSurface<dim>           &surface,
                        const TrilinosWrappers::MPI::Vector &pressure,
                        const TrilinosWrappers::MPI::Vector &solution,
                        const Reference<dim>                &reference,
                        const TrilinosWrappers::MPI::Vector *tangential)
  {
    const MPI_Comm     comm        = discretisation.mpi_communicator();
    const auto        &obstacles   = surface.obstacles();
    const unsigned int n_obstacles = obstacles.size();
    const auto        &nodes       = surface.nodes();
    ContactZone<dim>   zone;
    zone.obstacles.resize(n_obstacles);
    zone.revolved = discretisation.axisymmetric();

    // Peak pressure, nodal forces and the mean normal of the active nodes.
    const double                none = -std::numeric_limits<double>::max();
    double                      max_pressure = none;
    std::vector<double>         peak(n_obstacles, none);
    std::vector<Tensor<1, dim>> mean_normal(n_obstacles);
    std::vector<unsigned int>   n_active(n_obstacles, 0);
    Tensor<1, dim>              friction_force;
    for (const auto &node : nodes)
      if (node.owned)
        {
          const double p      = pressure(node.scalar_dof);
          max_pressure        = std::max(max_pressure, p);
          auto &contact       = zone.obstacles[node.obstacle];
          peak[node.obstacle] = std::max(peak[node.obstacle], p);
          contact.force += p * node.mass * node.normal;
          // With friction, the obstacle's tangential nodal force too.
          if (tangential)
            for (unsigned int d = 0; d < dim; ++d)
              {
                const double q = (*tangential)(node.dofs[d]) * node.mass;
                contact.force[d] += q;
                friction_force[d] += q;
              }
          for (unsigned int d = 0; d < dim; ++d)
            if (!node.free[d] && node.normal[d] != 0.)
              {
                zone.supported_force[d] += p * node.mass * node.normal[d];
                zone.supported = true;
              }
          if (node.in_contact())
            {
              mean_normal[node.obstacle] += node.normal;
              ++n_active[node.obstacle];
            }
        }
    zone.supported = Utilities::MPI::max(zone.supported ? 1U : 0U, comm) > 0;
    if (zone.supported)
      zone.supported_force = Utilities::MPI::sum(zone.supported_force, comm);
    max_pressure      = Utilities::MPI::max(max_pressure, comm);
    zone.max_pressure = max_pressure == none ? 0. : max_pressure;
    const auto edges =
      estimate_zone_edges(discretisation, surface, pressure, solution);
    for (unsigned int k = 0; k < n_obstacles; ++k)
      {
        auto &contact        = zone.obstacles[k];
        peak[k]              = Utilities::MPI::max(peak[k], comm);
        contact.max_pressure = peak[k] == none ? 0. : peak[k];
        contact.force        = Utilities::MPI::sum(contact.force, comm);
        // The radial forces of a whole revolution cancel: its resultant is
        // axial.
        if (discretisation.axisymmetric())
          contact.force[0] = 0.;
        mean_normal[k] = Utilities::MPI::sum(mean_normal[k], comm);
        if (Utilities::MPI::sum(n_active[k], comm) == 0)
          continue;
        const double length = mean_normal[k].norm();
        const auto   across =
          contact_zone_directions(length > 0 ? mean_normal[k] / length :
                                               mean_normal[k],
                                  discretisation.axisymmetric());
        // The extent along each direction of the nodes in contact (or
        // sticking) and of the zone's edges between the nodes; the width
        // is the smallest (the same on any number of processes: a near tie
        // of two axes in the mean normal no longer picks one).
        const auto extent = [&](const auto                    &inside,
                                const std::vector<Point<dim>> &edge_points) {
          double width = std::numeric_limits<double>::max();
          for (const auto &tangent : across)
            {
              double     low = std::numeric_limits<double>::max(), high = -low;
              const auto add = [&](const Point<dim> &x) {
                low  = std::min(low, tangent * x);
                high = std::max(high, tangent * x);
              };
              for (const auto &node : nodes)
                if (node.owned && node.obstacle == k && inside(node))
                  add(node.position);
              for (const auto &x : edge_points)
                add(x);
              low   = Utilities::MPI::min(low, comm);
              high  = Utilities::MPI::max(high, comm);
              width = std::min(width, high >= low ? high - low : 0.);
            }
          return width;
        };
        contact.contact_width =
          extent([](const ContactNode<dim> &node) { return node.in_contact(); },
                 edges[k].contact);
        zone.contact_width =
          std::max(zone.contact_width, contact.contact_width);
        if (tangential)
          {
            contact.stick_width = extent(
              [](const ContactNode<dim> &node) {
                return node.state == NodeState::stick;
              },
              edges[k].stick);
            zone.stick_width = std::max(zone.stick_width, contact.stick_width);
          }
      }

    // The nodal pressures sit at one dof per node, the others hold zero:
    // summed over all components, the shape functions interpolate them.
    // Each obstacle's pressure and active indicator are those of its own
    // nodes: all around a vertex that faces one obstacle, and at a corner
    // where the boundary faces each (as the nodes' masses are counted).
    std::unordered_map<types::global_dof_index, unsigned int> node_at;
    for (unsigned int i = 0; i < nodes.size(); ++i)
      node_at[nodes[i].scalar_dof] = i;
    const Function<dim>      *exact = reference.contact_pressure.get();
    const Quadrature<dim - 1> rule  = discretisation.fine_face_quadrature();
    const auto               &fe    = discretisation.fe();
    const auto               &constraints = discretisation.constraints();
    FEFaceValues<dim>         fe_face_values(
      discretisation.mapping(),
      fe,
      rule,
      update_values | update_quadrature_points | update_JxW_values |
        (n_obstacles > 1 ? update_normal_vectors : update_default));
    const unsigned int                   n = fe.n_dofs_per_cell();
    std::vector<types::global_dof_index> dof_indices(n);
    // [corner part][obstacle][dof of the cell]
    std::array<std::vector<std::vector<double>>, 2>         nodal, indicator;
    std::array<std::vector<std::vector<Tensor<1, dim>>>, 2> nodal_force;
    for (unsigned int c = 0; c < 2; ++c)
      {
        nodal[c].assign(n_obstacles, std::vector<double>(n));
        indicator[c].assign(n_obstacles, std::vector<double>(n));
        nodal_force[c].assign(n_obstacles, std::vector<Tensor<1, dim>>(n));
      }
    // The part gathered: the nodes of corners, or the others.
    bool       corner_part = false;
    const auto in_part     = [&](const unsigned int node) {
      return (nodes[node].corner != numbers::invalid_unsigned_int) ==
             corner_part;
    };
    // One obstacle, no corners: the pressure vector as it is.
    const auto single = [&]() { return n_obstacles == 1 && !corner_part; };
    // Obstacle k's pressure (or active indicator) at dof i.
    const auto own_value = [&](const types::global_dof_index i,
                               const unsigned int            k,
                               const bool                    active) {
      const auto at = node_at.find(i);
      if (at == node_at.end() || nodes[at->second].obstacle != k ||
          !in_part(at->second))
        return 0.;
      if (active)
        return nodes[at->second].in_contact() ? 1. : 0.;
      return static_cast<double>(pressure(i));
    };
    const auto nodal_value = [&](const types::global_dof_index i,
                                 const unsigned int            k,
                                 const bool                    active) {
      if (!constraints.is_constrained(i))
        return single() && !active ? static_cast<double>(pressure(i)) :
                                     own_value(i, k, active);
      double value = 0.;
      if (const auto *entries = constraints.get_constraint_entries(i))
        for (const auto &[master, weight] : *entries)
          value += weight * (single() && !active ?
                               static_cast<double>(pressure(master)) :
                               own_value(master, k, active));
      return value;
    };

    // Obstacle k's pressure times its normal at dof i: interpolated, the
    // force density whose integral is the nodal forces' sum.
    const auto own_normal = [&](const types::global_dof_index i,
                                const unsigned int            k) {
      const auto at = node_at.find(i);
      if (at == node_at.end() || nodes[at->second].obstacle != k ||
          !in_part(at->second))
        return Tensor<1, dim>();
      return nodes[at->second].normal;
    };
    const auto nodal_force_density = [&](const types::global_dof_index i,
                                         const unsigned int            k) {
      const auto own_pressure = [&](const types::global_dof_index j) {
        return single() ? static_cast<double>(pressure(j)) :
                          own_value(j, k, false);
      };
      if (!constraints.is_constrained(i))
        return own_pressure(i) * own_normal(i, k);
      Tensor<1, dim> value;
      if (const auto *entries = constraints.get_constraint_entries(i))
        for (const auto &[master, weight] : *entries)
          value += weight * (own_pressure(master) * own_normal(master, k));
      return value;
    };

    double              integral = 0., error_squared = 0., norm_squared = 0.;
    Tensor<1, dim>      resultant;
    std::vector<double> area(n_obstacles, 0.);
    surface.for_each_owned_face(
      discretisation, [&](const auto &cell, const unsigned int f) {
        fe_face_values.reinit(cell, f);
        cell->get_dof_indices(dof_indices);
        for (unsigned int c = 0; c < 2; ++c)
          {
            corner_part = c == 1;
            for (unsigned int k = 0; k < n_obstacles; ++k)
              for (unsigned int i = 0; i < n; ++i)
                {
                  nodal[c][k][i]       = nodal_value(dof_indices[i], k, false);
                  indicator[c][k][i]   = nodal_value(dof_indices[i], k, true);
                  nodal_force[c][k][i] = nodal_force_density(dof_indices[i], k);
                }
          }
        for (const unsigned int q : fe_face_values.quadrature_point_indices())
          {
            const auto  &x   = fe_face_values.quadrature_point(q);
            const double JxW = fe_face_values.JxW(q) * discretisation.weight(x);
            // At a corner, the point belongs to the obstacle it faces.
            const unsigned int facing =
              n_obstacles == 1 ?
                0 :
                obstacles.facing(x, fe_face_values.normal_vector(q));
            double         p_h = 0.;
            Tensor<1, dim> force_h;
            for (unsigned int k = 0; k < n_obstacles; ++k)
              {
                double active_h = 0.;
                for (unsigned int c = 0; c < (k == facing ? 2 : 1); ++c)
                  for (unsigned int i = 0; i < n; ++i)
                    {
                      const double phi = fe_face_values.shape_value(i, q);
                      p_h += nodal[c][k][i] * phi;
                      active_h += indicator[c][k][i] * phi;
                      force_h += nodal_force[c][k][i] * phi;
                    }
                area[k] += active_h * JxW;
              }
            integral += p_h * JxW;
            resultant += force_h * JxW;
            if (exact)
              {
                const double p = exact->value(x);
                error_squared += (p_h - p) * (p_h - p) * JxW;
                norm_squared += p * p * JxW;
              }
          }
      });
    zone.integrated_pressure = Utilities::MPI::sum(integral, comm);
    zone.pressure_resultant  = Utilities::MPI::sum(resultant, comm);
    if (tangential)
      zone.pressure_resultant += Utilities::MPI::sum(friction_force, comm);
    for (unsigned int k = 0; k < n_obstacles; ++k)
      {
        zone.obstacles[k].contact_area = Utilities::MPI::sum(area[k], comm);
        zone.contact_area += zone.obstacles[k].contact_area;
      }
    zone.pressure_error = std::numeric_limits<double>::quiet_NaN();
    if (exact)
      {
        check_finite(*exact, comm);
        error_squared       = Utilities::MPI::sum(error_squared, comm);
        norm_squared        = Utilities::MPI::sum(norm_squared, comm);
        zone.pressure_error = norm_squared > 0 ?
                                std::sqrt(error_squared / norm_squared) :
                                std::sqrt(error_squared);
      }
    return zone;
  }

  template <int dim>
  void
  add_contact_columns(StatisticsRow          &row,
                      const ContactZone<dim> &zone,
                      const ObstacleSet<dim> &obstacles,
                      std::ostream           &out)
  {
    if (obstacles.single_height())
      return;
    row.add("contact_area", zone.contact_area);
    const char *axes = "xyz";
    const char *area =
      dim == 2 && !zone.revolved ? "contact length " : "contact area ";
    out << "   " << area << zone.contact_area << std::endl;
    if (obstacles.size() > 1)
      for (unsigned int k = 0; k < obstacles.size(); ++k)
        {
          const std::string n       = std::to_string(obstacles.number(k));
          const auto       &contact = zone.obstacles[k];
          for (unsigned int d = 0; d < dim; ++d)
            row.add("contact_force" + n + "_" + axes[d], contact.force[d]);
          row.add("max_pressure" + n, contact.max_pressure);
          row.add("contact_width" + n, contact.contact_width);
          row.add("contact_area" + n, contact.contact_area);
          out << "   obstacle " << n << ": force (" << contact.force
              << "), max pressure " << contact.max_pressure
              << ", contact width " << contact.contact_width << ", " << area
              << contact.contact_area << std::endl;
        }
  }

  template ContactZone<2>
  evaluate_contact_zone(const Discretisation<2> &,
                        const ContactSurface<2> &,
                        const TrilinosWrappers::MPI::Vector &,
                        const TrilinosWrappers::MPI::Vector &,
                        const Reference<2> &,
                        const TrilinosWrappers::MPI::Vector *);
  template ContactZone<3>
  evaluate_contact_zone(const Discretisation<3> &,
                        const ContactSurface<3> &,
                        const TrilinosWrappers::MPI::Vector &,
                        const TrilinosWrappers::MPI::Vector &,
                        const Reference<3> &,
                        const TrilinosWrappers::MPI::Vector *);
  template void
  add_contact_columns(StatisticsRow &,
                      const ContactZone<2> &,
                      const ObstacleSet<2> &,
                      std::ostream &);
  template void
  add_contact_columns(StatisticsRow &,
                      const ContactZone<3> &,
                      const ObstacleSet<3> &,
                      std::ostream &);
} // namespace signorini
