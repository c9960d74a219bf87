#include <deal.II/fe/fe_values.h>
#include <deal.II/lac/vector.h>

#include <signorini/contact/contact_surface.h>

#include <optional>

namespace signorini
{
  using namespace dealii;

  template <int dim>
  void
  ContactSurface<dim>::compute_masses(const Discretisation<dim> &discretisation)
  {
    const auto        &constraints = discretisation.constraints();
    const auto        &owned_dofs  = discretisation.locally_owned_dofs();
    const unsigned int n_obstacles = obstacle_set.size();
    // Lumped contact-boundary mass: the integral of each shape function over
    // the contact boundary, condensed onto the free nodes; with several
    // obstacles, a node's over the part of the boundary that faces its
    // obstacle (the quadrature points whose normal faces it most
    // squarely).
    const auto             &fe = discretisation.fe();
    const unsigned int      n  = fe.n_dofs_per_cell();
    std::vector<VectorType> mass(n_obstacles,
                                 VectorType(owned_dofs, mpi_communicator));
    FEFaceValues<dim>       fe_face_values(
      discretisation.mapping(),
      fe,
      discretisation.contact_face_quadrature(),
      update_values | update_JxW_values | discretisation.weight_flags() |
        (n_obstacles > 1 ? update_quadrature_points | update_normal_vectors :
                                 update_default));
    // An axisymmetric model of degree 2: the node on the axis has no mass
    // as an integral of phi_i 2 pi r (its shape function's integral
    // vanishes exactly), so it would have no pressure. Each Gauss-Lobatto
    // point stands for its share of the face instead (the points whose
    // weights add up to it, in order), the annulus that share sweeps: its
    // weight 2 pi r at the share's middle. Along a straight face that is
    // the annulus's area, for the axis node pi (L/6)^2, positive.
    const Quadrature<dim - 1> &rule = discretisation.contact_face_quadrature();
    std::optional<FEFaceValues<dim>> share_middles;
    if (fe.degree > 1 && discretisation.axisymmetric())
      {
        std::vector<Point<dim - 1>> middles(rule.size());
        double                      before = 0.;
        for (unsigned int q = 0; q < rule.size(); ++q)
          {
            middles[q][0] = before + 0.5 * rule.weight(q);
            before += rule.weight(q);
          }
        share_middles.emplace(discretisation.mapping(),
                              fe,
                              Quadrature<dim - 1>(middles),
                              discretisation.weight_flags());
      }
    const auto weight = [&](const unsigned int q) {
      return share_middles ? discretisation.weight(*share_middles, q) :
                             discretisation.weight(fe_face_values, q);
    };
    std::vector<Vector<double>> cell_mass(n_obstacles, Vector<double>(n));
    std::vector<types::global_dof_index> dof_indices(n);
    for_each_owned_face(
      discretisation, [&](const auto &cell, const unsigned int f) {
        fe_face_values.reinit(cell, f);
        if (share_middles)
          share_middles->reinit(cell, f);
        if (n_obstacles == 1)
          {
            cell_mass[0] = 0;
            for (unsigned int i = 0; i < n; ++i)
              for (const unsigned int q :
                   fe_face_values.quadrature_point_indices())
                cell_mass[0](i) += fe_face_values.shape_value(i, q) *
                                   fe_face_values.JxW(q) * weight(q);
          }
        else
          {
            for (auto &m : cell_mass)
              m = 0;
            for (const unsigned int q :
                 fe_face_values.quadrature_point_indices())
              {
                const unsigned int k =
                  obstacle_set.facing(fe_face_values.quadrature_point(q),
                                      fe_face_values.normal_vector(q));
                for (unsigned int i = 0; i < n; ++i)
                  cell_mass[k](i) += fe_face_values.shape_value(i, q) *
                                     fe_face_values.JxW(q) * weight(q);
              }
          }
        cell->get_dof_indices(dof_indices);
        for (unsigned int k = 0; k < n_obstacles; ++k)
          constraints.distribute_local_to_global(cell_mass[k],
                                                 dof_indices,
                                                 mass[k]);
      });
    for (auto &m : mass)
      m.compress(VectorOperation::add);
    // A vertex that faces one obstacle carries the whole boundary around it,
    // whichever obstacle its quadrature points face most squarely (a floor
    // and a plane crossing it at a small angle: the vertex nearest the
    // floor had none of it, so no pressure, and the active set cycled). A
    // corner's nodes share it by facing; one that faces none of it takes
    // an equal share, so that its pressure has the sign of its force.
    for (auto &node : contact_nodes)
      if (node.owned)
        {
          double total = 0.;
          for (const auto &m : mass)
            total += m(node.scalar_dof);
          if (node.corner == numbers::invalid_unsigned_int)
            node.mass = total;
          else
            {
              node.mass = mass[node.obstacle](node.scalar_dof);
              if (node.mass <= 0.)
                node.mass = total / corner_nodes[node.corner].size();
            }
        }
  }

  template void
  ContactSurface<2>::compute_masses(const Discretisation<2> &);
  template void
  ContactSurface<3>::compute_masses(const Discretisation<3> &);
} // namespace signorini
