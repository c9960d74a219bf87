#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/lac/full_matrix.h>

#include <signorini/contact/contact_surface.h>
#include <signorini/input/input_error.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <map>
#include <optional>
#include <sstream>

namespace signorini
{
  using namespace dealii;

  namespace
  {
    /** A corner's normals must be this independent: the determinant of
     * their components along their nodes' scalar dofs (about the sine of
     * the angle between two unit normals). */
    constexpr double independent_normals = 0.1;

    /** The determinant of the m x m matrix a[i][j] = normals[i][columns[j]]
     * (m <= 3). */
    template <int dim>
    double
    normal_determinant(const std::vector<Tensor<1, dim>> &normals,
                       const std::vector<unsigned int>   &columns)
    {
      FullMatrix<double> a(normals.size(), normals.size());
      for (unsigned int i = 0; i < normals.size(); ++i)
        for (unsigned int j = 0; j < columns.size(); ++j)
          a(i, j) = normals[i][columns[j]];
      return a.determinant();
    }
  } // namespace

  template <int dim>
  std::array<Tensor<1, dim>, dim - 1>
  tangent_frame(const Tensor<1, dim> &n)
  {
    std::array<Tensor<1, dim>, dim - 1> t;
    if constexpr (dim == 2)
      {
        t[0][0] = -n[1];
        t[0][1] = n[0];
      }
    else
      {
        // Along the axis e_k where n is smallest, less its part along n.
        unsigned int k = 0;
        for (unsigned int d = 1; d < dim; ++d)
          if (std::abs(n[d]) < std::abs(n[k]))
            k = d;
        t[0] = -n[k] * n;
        t[0][k] += 1.;
        t[0] /= t[0].norm();
        t[1] = cross_product_3d(n, t[0]);
      }
    return t;
  }

  template std::array<Tensor<1, 2>, 1>
  tangent_frame(const Tensor<1, 2> &);
  template std::array<Tensor<1, 3>, 2>
  tangent_frame(const Tensor<1, 3> &);

  template <int dim>
  ContactSurface<dim>::ContactSurface(
    const std::set<types::boundary_id> &contact_ids,
    const ObstacleSet<dim>             &obstacles,
    const bool                          check_input)
    : ids(contact_ids)
    , obstacle_set(obstacles)
    , check_input(check_input)
    , mpi_communicator(MPI_COMM_SELF)
  {
  }

  template <int dim>
  double
  ContactSurface<dim>::free_part(const Tensor<1, dim>        &normal,
                                 const std::array<bool, dim> &free)
  {
    double sum = 0.;
    for (unsigned int d = 0; d < dim; ++d)
      if (free[d])
        sum += normal[d] * normal[d];
    return std::sqrt(sum);
  }

  template <int dim>
  void
  ContactSurface<dim>::throw_first(const std::optional<InputError> &error,
                                   const MPI_Comm                   comm)
  {
    // The first message of any process (by rank), on all of them.
    const std::string local =
      error ? error->entry + '\n' + error->what() : std::string();
    for (const auto &message : Utilities::MPI::all_gather(comm, local))
      if (!message.empty())
        {
          const auto split = message.find('\n');
          throw InputError(message.substr(0, split), message.substr(split + 1));
        }
  }

  template <int dim>
  void
  ContactSurface<dim>::setup(const Discretisation<dim> &discretisation)
  {
    mpi_communicator               = discretisation.mpi_communicator();
    tolerance                      = 1e-12 * discretisation.body_size();
    const auto        &constraints = discretisation.constraints();
    const auto        &owned_dofs  = discretisation.locally_owned_dofs();
    const unsigned int n_obstacles = obstacle_set.size();

    // The nodes of the contact boundary, each once, with their gaps: the
    // vertices, and at degree 2 the mid-nodes of edges and faces (where the
    // mapping puts them: on a curved boundary's manifold).
    std::vector<Vertex>                                vertices;
    std::map<types::global_dof_index, unsigned int>    vertex_index;
    std::optional<std::pair<Point<dim>, unsigned int>> non_finite;
    const auto                                         add_node =
      [&](const std::array<types::global_dof_index, dim> &dofs,
          const Point<dim>                               &position,
          const types::boundary_id                        id) {
        const auto [at, added] = vertex_index.emplace(dofs[0], vertices.size());
        if (added)
          {
            Vertex vertex;
            vertex.position = position;
            vertex.dofs     = dofs;
            for (unsigned int d = 0; d < dim; ++d)
              vertex.free[d] = !constraints.is_constrained(dofs[d]);
            vertex.gaps.resize(n_obstacles);
            vertex.normals.resize(n_obstacles);
            for (unsigned int k = 0; k < n_obstacles; ++k)
              vertex.gaps[k] =
                obstacle_set.gap(k, vertex.position, vertex.normals[k]);
            vertices.push_back(vertex);
          }
        auto &vertex = vertices[at->second];
        vertex.boundary_ids.insert(id);
        // A gap that is not a number where a node can act on it.
        for (unsigned int k = 0; k < n_obstacles; ++k)
          if (!std::isfinite(vertex.gaps[k]) &&
              !(free_part(vertex.normals[k], vertex.free) < fixed_along_normal))
            non_finite = {vertex.position, k};
      };
    const auto                              &fe   = discretisation.fe();
    const auto                              &base = fe.base_element(0);
    FEValues<dim>                            at_nodes(discretisation.mapping(),
                           fe,
                           Quadrature<dim>(base.get_unit_support_points()),
                           update_quadrature_points);
    std::vector<types::global_dof_index>     cell_dofs(fe.n_dofs_per_cell());
    std::vector<types::global_dof_index>     face_dofs;
    std::array<types::global_dof_index, dim> dofs;
    for (const auto &cell :
         discretisation.dof_handler().active_cell_iterators())
      if (!cell->is_artificial())
        {
          bool mapped = false;
          for (const unsigned int f : cell->face_indices())
            {
              const auto face = cell->face(f);
              if (!face->at_boundary() || !ids.count(face->boundary_id()))
                continue;
              if (fe.degree == 1)
                {
                  for (const unsigned int v : face->vertex_indices())
                    {
                      for (unsigned int d = 0; d < dim; ++d)
                        dofs[d] = face->vertex_dof_index(v, d);
                      add_node(dofs, face->vertex(v), face->boundary_id());
                    }
                  continue;
                }
              // Degree 2: the cell's nodes on the face (the face's own
              // dofs: simplex elements do not say which of theirs have
              // support on a face).
              if (!mapped)
                {
                  cell->get_dof_indices(cell_dofs);
                  at_nodes.reinit(cell);
                  mapped = true;
                }
              face_dofs.resize(fe.n_dofs_per_face(f));
              face->get_dof_indices(face_dofs);
              std::sort(face_dofs.begin(), face_dofs.end());
              for (unsigned int b = 0; b < base.n_dofs_per_cell(); ++b)
                if (std::binary_search(
                      face_dofs.begin(),
                      face_dofs.end(),
                      cell_dofs[fe.component_to_system_index(0, b)]))
                  {
                    for (unsigned int d = 0; d < dim; ++d)
                      dofs[d] = cell_dofs[fe.component_to_system_index(d, b)];
                    add_node(dofs,
                             b < cell->n_vertices() ?
                               cell->vertex(b) :
                               at_nodes.quadrature_point(b),
                             face->boundary_id());
                  }
            }
        }
    if (Utilities::MPI::max(non_finite ? 1U : 0U, mpi_communicator) > 0)
      {
        std::optional<InputError> error;
        if (non_finite)
          {
            std::ostringstream where;
            where << non_finite->first;
            // A normal that is not a number has no direction: a zero
            // gradient (a constant signed distance) rather than a gap
            // expression that overflows.
            Tensor<1, dim> normal;
            obstacle_set.gap(non_finite->second, non_finite->first, normal);
            bool directed = true;
            for (unsigned int d = 0; d < dim; ++d)
              directed = directed && std::isfinite(normal[d]);
            error = InputError(
              obstacle_set[non_finite->second].entry(),
              directed ?
                "is not a finite number on the contact boundary at (" +
                  where.str() + ")" :
                "has no normal on the contact boundary at (" + where.str() +
                  "), so the gap there is undefined: its gradient is zero "
                  "(a signed distance changes by 1 mm per mm, its gradient "
                  "has length 1)");
          }
        throw_first(error, mpi_communicator);
      }

    // Each vertex faces its nearest obstacle that it can move towards, and
    // those of the others whose normals are independent of the ones it
    // faces already on its free components: one node each.
    std::vector<ContactNode<dim>>              primary, secondary;
    std::map<types::boundary_id, unsigned int> acting_vertices;
    for (const auto &vertex : vertices)
      {
        std::vector<unsigned int> order(n_obstacles);
        for (unsigned int k = 0; k < n_obstacles; ++k)
          order[k] = k;
        std::stable_sort(order.begin(),
                         order.end(),
                         [&](const unsigned int a, const unsigned int b) {
                           return vertex.gaps[a] < vertex.gaps[b];
                         });
        std::vector<Tensor<1, dim>> normals;
        std::vector<unsigned int>   columns;
        for (const unsigned int k : order)
          {
            if (columns.size() == dim)
              break;
            const Tensor<1, dim> &n     = vertex.normals[k];
            unsigned int          along = numbers::invalid_unsigned_int;
            if (columns.empty())
              {
                if (free_part(n, vertex.free) < fixed_along_normal)
                  continue;
                // The free component along which the normal is largest.
                for (unsigned int d = 0; d < dim; ++d)
                  if (vertex.free[d] &&
                      (along == numbers::invalid_unsigned_int ||
                       std::abs(n[d]) >= std::abs(n[along])))
                    along = d;
              }
            else
              {
                double best = independent_normals;
                auto   rows = normals;
                rows.push_back(n);
                for (unsigned int d = 0; d < dim; ++d)
                  if (vertex.free[d] &&
                      std::find(columns.begin(), columns.end(), d) ==
                        columns.end())
                    {
                      auto candidate = columns;
                      candidate.push_back(d);
                      const double det =
                        std::abs(normal_determinant<dim>(rows, candidate));
                      if (det >= best)
                        {
                          best  = det;
                          along = d;
                        }
                    }
                if (along == numbers::invalid_unsigned_int)
                  continue;
              }
            ContactNode<dim> node;
            node.dofs       = vertex.dofs;
            node.free       = vertex.free;
            node.scalar_dof = vertex.dofs[along];
            node.position   = vertex.position;
            node.normal     = n;
            node.tangents   = tangent_frame(n);
            node.gap        = vertex.gaps[k];
            node.obstacle   = k;
            node.owned      = owned_dofs.is_element(node.scalar_dof);
            node.primary    = columns.empty();
            (node.primary ? primary : secondary).push_back(node);
            normals.push_back(n);
            columns.push_back(along);
          }
        for (const auto id : vertex.boundary_ids)
          acting_vertices[id] += columns.empty() ? 0 : 1;
      }

    if (check_input)
      check_vertices(vertices, acting_vertices, constraints);

    // Sorted by scalar dof, the vertices' primary nodes first.
    const auto by_scalar_dof = [](const ContactNode<dim> &a,
                                  const ContactNode<dim> &b) {
      return a.scalar_dof < b.scalar_dof;
    };
    std::sort(primary.begin(), primary.end(), by_scalar_dof);
    std::sort(secondary.begin(), secondary.end(), by_scalar_dof);
    contact_nodes = std::move(primary);
    contact_nodes.insert(contact_nodes.end(),
                         secondary.begin(),
                         secondary.end());
    corner_nodes.clear();
    if (!secondary.empty())
      {
        std::map<types::global_dof_index, std::vector<unsigned int>> at_vertex;
        for (unsigned int i = 0; i < contact_nodes.size(); ++i)
          at_vertex[contact_nodes[i].dofs[0]].push_back(i);
        for (const auto &[dof, indices] : at_vertex)
          if (indices.size() > 1)
            {
              for (const unsigned int i : indices)
                contact_nodes[i].corner = corner_nodes.size();
              corner_nodes.push_back(indices);
            }
      }

    compute_masses(discretisation);
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
  const std::vector<std::vector<unsigned int>> &
  ContactSurface<dim>::corners() const
  {
    return corner_nodes;
  }

  template <int dim>
  const ObstacleSet<dim> &
  ContactSurface<dim>::obstacles() const
  {
    return obstacle_set;
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
  std::vector<double>
  ContactSurface<dim>::normal_forces(const VectorType &residual) const
  {
    std::vector<double> lambda(contact_nodes.size(), 0.);
    for (unsigned int i = 0; i < contact_nodes.size(); ++i)
      {
        const auto &node = contact_nodes[i];
        if (!node.owned)
          continue;
        if (node.corner == numbers::invalid_unsigned_int)
          {
            // residual = lambda n on the free components.
            double force = 0., length = 0.;
            for (unsigned int d = 0; d < dim; ++d)
              if (node.free[d])
                {
                  force += node.normal[d] * residual(node.dofs[d]);
                  length += node.normal[d] * node.normal[d];
                }
            lambda[i] = force / length;
          }
        else if (node.primary)
          {
            // residual = sum_j lambda_j n_j on the free components, in the
            // least-squares sense: (N N^T) lambda = N residual.
            const auto        &corner = corner_nodes[node.corner];
            const unsigned int m      = corner.size();
            FullMatrix<double> normal_matrix(m, m);
            Vector<double>     right(m), solution(m);
            for (unsigned int a = 0; a < m; ++a)
              {
                const auto &na = contact_nodes[corner[a]].normal;
                for (unsigned int d = 0; d < dim; ++d)
                  if (node.free[d])
                    {
                      right(a) += na[d] * residual(node.dofs[d]);
                      for (unsigned int b = 0; b < m; ++b)
                        normal_matrix(a, b) +=
                          na[d] * contact_nodes[corner[b]].normal[d];
                    }
              }
            normal_matrix.gauss_jordan();
            normal_matrix.vmult(solution, right);
            for (unsigned int a = 0; a < m; ++a)
              lambda[corner[a]] = solution(a);
          }
      }
    return lambda;
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
      if (node.owned && node.in_contact())
        {
          ++count;
          // The state beyond `closed` enters the hash (friction's).
          const std::uint64_t state =
            static_cast<std::uint64_t>(node.state) -
            static_cast<std::uint64_t>(NodeState::closed);
          std::uint64_t z =
            node.scalar_dof + 0x9e3779b97f4a7c15ULL + (state << 40);
          z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
          z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
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
