#include <deal.II/base/mpi.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/lac/vector.h>

#include <signorini/contact/contact_surface.h>
#include <signorini/input/input_error.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <optional>
#include <sstream>

namespace signorini
{
  using namespace dealii;

  template <int dim>
  ContactSurface<dim>::ContactSurface(
    const std::set<types::boundary_id> &contact_ids,
    const Obstacle<dim>                &obstacle)
    : ids(contact_ids)
    , obstacle(obstacle)
    , mpi_communicator(MPI_COMM_SELF)
  {
  }

  template <int dim>
  void
  ContactSurface<dim>::setup(const Discretisation<dim> &discretisation)
  {
    mpi_communicator        = discretisation.mpi_communicator();
    tolerance               = 1e-12 * discretisation.body_size();
    const auto &constraints = discretisation.constraints();
    const auto &owned_dofs  = discretisation.locally_owned_dofs();

    contact_nodes.clear();
    std::vector<std::pair<types::global_dof_index, ContactNode<dim>>> found;
    std::optional<Point<dim>> non_finite;
    for (const auto &cell :
         discretisation.dof_handler().active_cell_iterators())
      if (!cell->is_artificial())
        for (const auto &face : cell->face_iterators())
          if (face->at_boundary() && ids.count(face->boundary_id()))
            for (const unsigned int v : face->vertex_indices())
              {
                ContactNode<dim> node;
                node.position      = face->vertex(v);
                node.gap           = obstacle.gap(node.position, node.normal);
                unsigned int along = 0;
                for (unsigned int d = 0; d < dim; ++d)
                  {
                    node.dofs[d] = face->vertex_dof_index(v, d);
                    if (std::abs(node.normal[d]) >=
                        std::abs(node.normal[along]))
                      along = d;
                  }
                node.scalar_dof = node.dofs[along];
                if (constraints.is_constrained(node.scalar_dof))
                  continue;
                if (!std::isfinite(node.gap))
                  non_finite = node.position;
                node.owned = owned_dofs.is_element(node.scalar_dof);
                found.emplace_back(node.scalar_dof, node);
              }
    if (Utilities::MPI::max(non_finite ? 1U : 0U, mpi_communicator) > 0)
      {
        std::ostringstream where;
        if (non_finite)
          where << " at (" << *non_finite << ")";
        throw InputError(obstacle.entry(),
                         "is not a finite number on the contact boundary" +
                           where.str());
      }
    std::sort(found.begin(), found.end(), [](const auto &a, const auto &b) {
      return a.first < b.first;
    });
    for (unsigned int i = 0; i < found.size(); ++i)
      if (i == 0 || found[i].first != found[i - 1].first)
        contact_nodes.push_back(found[i].second);

    // Lumped contact-boundary mass: the integral of each shape function over
    // the contact boundary (weighted by the measure's weight), condensed
    // onto the free nodes.
    const auto       &fe = discretisation.fe();
    VectorType        mass(owned_dofs, mpi_communicator);
    FEFaceValues<dim> fe_face_values(discretisation.mapping(),
                                     fe,
                                     discretisation.face_quadrature(),
                                     update_values | update_JxW_values |
                                       discretisation.weight_flags());
    Vector<double>    cell_mass(fe.n_dofs_per_cell());
    std::vector<types::global_dof_index> dof_indices(fe.n_dofs_per_cell());
    for (const auto &cell :
         discretisation.dof_handler().active_cell_iterators())
      if (cell->is_locally_owned())
        for (const unsigned int f : cell->face_indices())
          if (cell->face(f)->at_boundary() &&
              ids.count(cell->face(f)->boundary_id()))
            {
              fe_face_values.reinit(cell, f);
              cell_mass = 0;
              for (unsigned int i = 0; i < fe.n_dofs_per_cell(); ++i)
                for (const unsigned int q :
                     fe_face_values.quadrature_point_indices())
                  cell_mass(i) += fe_face_values.shape_value(i, q) *
                                  fe_face_values.JxW(q) *
                                  discretisation.weight(fe_face_values, q);
              cell->get_dof_indices(dof_indices);
              constraints.distribute_local_to_global(cell_mass,
                                                     dof_indices,
                                                     mass);
            }
    mass.compress(VectorOperation::add);
    for (auto &node : contact_nodes)
      if (node.owned)
        node.mass = mass(node.scalar_dof);
  }

  template <int dim>
  std::vector<ContactNode<dim>> &
  ContactSurface<dim>::nodes()
  {
    return contact_nodes;
  }

  template <int dim>
  const std::vector<ContactNode<dim>> &
  ContactSurface<dim>::nodes() const
  {
    return contact_nodes;
  }

  template <int dim>
  const std::set<types::boundary_id> &
  ContactSurface<dim>::contact_ids() const
  {
    return ids;
  }

  template <int dim>
  double
  ContactSurface<dim>::deformed_gap(const ContactNode<dim> &node,
                                    const VectorType       &u) const
  {
    return node.normal_displacement(u) + node.gap;
  }

  template <int dim>
  double
  ContactSurface<dim>::touching_tolerance() const
  {
    return tolerance;
  }

  template <int dim>
  std::pair<unsigned int, std::size_t>
  ContactSurface<dim>::active_set_signature() const
  {
    unsigned int  count = 0;
    std::uint64_t hash  = 0;
    for (const auto &node : contact_nodes)
      if (node.owned && node.active)
        {
          ++count;
          std::uint64_t z = node.scalar_dof + 0x9e3779b97f4a7c15ULL;
          z               = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
          z               = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
          hash += z ^ (z >> 31);
        }
    // Sums of per-process hashes: the same on every process.
    return {Utilities::MPI::sum(count, mpi_communicator),
            static_cast<std::size_t>(Utilities::MPI::sum(
              static_cast<unsigned long>(hash), mpi_communicator))};
  }

  template class ContactSurface<2>;
  template class ContactSurface<3>;
} // namespace signorini
