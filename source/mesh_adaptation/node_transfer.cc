#include <deal.II/base/bounding_box.h>
#include <deal.II/base/tensor.h>
#include <deal.II/numerics/rtree.h>

#include <signorini/mesh_adaptation/node_transfer.h>

#include <algorithm>
#include <functional>
#include <limits>

namespace signorini
{
  using namespace dealii;

  template <int dim>
  NodeTransfer<dim>::NodeTransfer(
    const Triangulation<dim>              &old_mesh,
    const DoFHandler<dim>                 &dof_handler,
    const std::vector<const VectorType *> &vectors,
    const MPI_Comm                         comm)
    : comm(comm)
    , base(dof_handler.get_fe().base_element(0).clone())
    , vertices(old_mesh.get_vertices())
  {
    const bool quadratic = base->degree > 1;
    // Cell k of the old mesh, the coarse cell k of a distributed copy.
    for (const auto &cell : old_mesh.active_cell_iterators())
      {
        std::array<unsigned int, dim + 1> cell_vertices;
        for (const unsigned int v : cell->vertex_indices())
          cell_vertices[v] = cell->vertex_index(v);
        cells.push_back(cell_vertices);
        if (quadratic)
          {
            std::vector<unsigned int> lines(cell->n_lines());
            for (unsigned int l = 0; l < lines.size(); ++l)
              lines[l] = cell->line(l)->index();
            cell_lines.push_back(lines);
          }
      }
    if (quadratic)
      {
        line_ends.resize(old_mesh.n_raw_lines());
        for (const auto &cell : old_mesh.active_cell_iterators())
          for (unsigned int l = 0; l < cell->n_lines(); ++l)
            line_ends[cell->line(l)->index()] = {
              {cell->line(l)->vertex_index(0), cell->line(l)->vertex_index(1)}};
      }
    const std::size_t n_nodes = vertices.size() + line_ends.size();

    // Each dof is owned by one process: summing gives every value once.
    const auto     &fe    = dof_handler.get_fe();
    const IndexSet &owned = dof_handler.locally_owned_dofs();
    values.assign(vectors.size(), std::vector<double>(dim * n_nodes, 0.));
    const bool distributed = &dof_handler.get_triangulation() != &old_mesh &&
                             Utilities::MPI::n_mpi_processes(comm) > 1;
    std::vector<types::global_dof_index> dofs(fe.n_dofs_per_cell());
    // The node of the old cell nearest to @p point among @p candidates
    // (the distributed copy's cells are the serial ones, but their
    // numbering of vertices and lines is not relied on).
    const auto nearest =
      [](const Point<dim>                              &point,
         const std::vector<unsigned int>               &candidates,
         const std::function<Point<dim>(unsigned int)> &position) {
        unsigned int best     = candidates[0];
        double       distance = std::numeric_limits<double>::max();
        for (const unsigned int c : candidates)
          if (point.distance(position(c)) < distance)
            {
              distance = point.distance(position(c));
              best     = c;
            }
        return best;
      };
    const auto line_middle = [&](const unsigned int l) {
      return Point<dim>(
        0.5 * (vertices[line_ends[l][0]] + vertices[line_ends[l][1]]));
    };
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          const unsigned int c = distributed ? cell->id().get_coarse_cell_id() :
                                               cell->active_cell_index();
          const std::vector<unsigned int> old_vertices(cells[c].begin(),
                                                       cells[c].end());
          cell->get_dof_indices(dofs);
          for (unsigned int b = 0; b < base->n_dofs_per_cell(); ++b)
            {
              const bool   at_vertex = b < cell->n_vertices();
              unsigned int node;
              if (at_vertex)
                node =
                  nearest(cell->vertex(b),
                          old_vertices,
                          [&](const unsigned int v) { return vertices[v]; });
              else
                node = vertices.size() +
                       nearest(cell->line(b - cell->n_vertices())->center(),
                               cell_lines[c],
                               line_middle);
              for (unsigned int d = 0; d < dim; ++d)
                {
                  const auto i = dofs[fe.component_to_system_index(d, b)];
                  if (owned.is_element(i))
                    for (unsigned int k = 0; k < vectors.size(); ++k)
                      values[k][dim * node + d] = (*vectors[k])(i);
                }
            }
        }
    for (auto &vector : values)
      Utilities::MPI::sum(vector, comm, vector);

    for (const auto &c : cells)
      {
        std::vector<Point<dim>> corners;
        for (const unsigned int v : c)
          corners.push_back(vertices[v]);
        boxes.emplace_back(corners);
      }
    tree = std::make_unique<Tree>(pack_rtree_of_indices(boxes));
  }

  template <int dim>
  std::pair<unsigned int, std::array<double, dim + 1>>
  NodeTransfer<dim>::locate(const Point<dim> &point) const
  {
    // Barycentric coordinates in each candidate; the best holds the point
    // (its smallest coordinate is >= 0) or is the least outside.
    const auto barycentric = [&](const unsigned int k) {
      const auto    &c = cells[k];
      Tensor<2, dim> jacobian;
      for (unsigned int j = 0; j < dim; ++j)
        for (unsigned int d = 0; d < dim; ++d)
          jacobian[d][j] = vertices[c[j + 1]][d] - vertices[c[0]][d];
      const Tensor<1, dim> xi = invert(jacobian) * (point - vertices[c[0]]);
      std::array<double, dim + 1> lambda;
      lambda[0] = 1.;
      for (unsigned int j = 0; j < dim; ++j)
        {
          lambda[j + 1] = xi[j];
          lambda[0] -= xi[j];
        }
      return lambda;
    };
    namespace bgi = boost::geometry::index;
    std::vector<std::size_t> candidates;
    tree->query(bgi::intersects(point), std::back_inserter(candidates));
    if (candidates.empty())
      tree->query(bgi::nearest(point, 4), std::back_inserter(candidates));
    unsigned int                best = candidates[0];
    std::array<double, dim + 1> best_lambda;
    double                      best_min = -std::numeric_limits<double>::max();
    for (const auto k : candidates)
      {
        const auto   lambda = barycentric(k);
        const double least  = *std::min_element(lambda.begin(), lambda.end());
        if (least > best_min)
          {
            best_min    = least;
            best        = k;
            best_lambda = lambda;
          }
      }
    return {best, best_lambda};
  }

  template <int dim>
  std::vector<typename NodeTransfer<dim>::VectorType>
  NodeTransfer<dim>::interpolate(const DoFHandler<dim> &dof_handler) const
  {
    const auto             &fe    = dof_handler.get_fe();
    const IndexSet         &owned = dof_handler.locally_owned_dofs();
    std::vector<VectorType> result(values.size(), VectorType(owned, comm));
    std::vector<bool>       done(owned.n_elements(), false);
    std::vector<types::global_dof_index> dofs(fe.n_dofs_per_cell());
    const unsigned int                   n_nodes = base->n_dofs_per_cell();
    // The old cell's nodes (vertices, then lines) as entries of values.
    const auto old_node = [&](const unsigned int k, const unsigned int b) {
      return b <= dim ? cells[k][b] :
                        vertices.size() + cell_lines[k][b - (dim + 1)];
    };
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          cell->get_dof_indices(dofs);
          for (unsigned int b = 0; b < n_nodes; ++b)
            {
              const auto first = dofs[fe.component_to_system_index(0, b)];
              if (!owned.is_element(first) ||
                  done[owned.index_within_set(first)])
                continue;
              done[owned.index_within_set(first)] = true;
              const Point<dim> point =
                b < cell->n_vertices() ?
                  cell->vertex(b) :
                  cell->line(b - cell->n_vertices())->center();
              const auto [k, lambda] = locate(point);
              Point<dim> unit;
              for (unsigned int j = 0; j < dim; ++j)
                unit[j] = lambda[j + 1];
              for (unsigned int d = 0; d < dim; ++d)
                {
                  const auto i = dofs[fe.component_to_system_index(d, b)];
                  for (unsigned int n = 0; n < values.size(); ++n)
                    {
                      double value = 0.;
                      for (unsigned int j = 0; j < n_nodes; ++j)
                        value += base->shape_value(j, unit) *
                                 values[n][dim * old_node(k, j) + d];
                      result[n](i) = value;
                    }
                }
            }
        }
    for (auto &vector : result)
      vector.compress(VectorOperation::insert);
    return result;
  }

  template class NodeTransfer<2>;
  template class NodeTransfer<3>;
} // namespace signorini
