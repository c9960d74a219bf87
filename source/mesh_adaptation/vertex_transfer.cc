#include <deal.II/base/bounding_box.h>
#include <deal.II/base/tensor.h>
#include <deal.II/numerics/rtree.h>

#include <signorini/mesh_adaptation/vertex_transfer.h>

#include <algorithm>
#include <limits>

namespace signorini
{
  using namespace dealii;

  template <int dim>
  VertexTransfer<dim>::VertexTransfer(
    const Triangulation<dim>              &old_mesh,
    const DoFHandler<dim>                 &dof_handler,
    const std::vector<const VectorType *> &vectors,
    const MPI_Comm                         comm)
    : comm(comm)
    , vertices(old_mesh.get_vertices())
  {
    // Cell k of the old mesh, the coarse cell k of a distributed copy.
    for (const auto &cell : old_mesh.active_cell_iterators())
      {
        std::array<unsigned int, dim + 1> cell_vertices;
        for (const unsigned int v : cell->vertex_indices())
          cell_vertices[v] = cell->vertex_index(v);
        cells.push_back(cell_vertices);
      }

    // Each dof is owned by one process: summing gives every value once.
    const IndexSet &owned = dof_handler.locally_owned_dofs();
    values.assign(vectors.size(),
                  std::vector<double>(dim * vertices.size(), 0.));
    const bool distributed = &dof_handler.get_triangulation() != &old_mesh &&
                             Utilities::MPI::n_mpi_processes(comm) > 1;
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          const auto &old_cell =
            cells[distributed ? cell->id().get_coarse_cell_id() :
                                cell->active_cell_index()];
          for (const unsigned int v : cell->vertex_indices())
            {
              // The same vertex of the old mesh: the nearest one.
              unsigned int vertex   = old_cell[0];
              double       distance = std::numeric_limits<double>::max();
              for (const unsigned int w : old_cell)
                if (cell->vertex(v).distance(vertices[w]) < distance)
                  {
                    distance = cell->vertex(v).distance(vertices[w]);
                    vertex   = w;
                  }
              for (unsigned int d = 0; d < dim; ++d)
                {
                  const auto i = cell->vertex_dof_index(v, d);
                  if (owned.is_element(i))
                    for (unsigned int k = 0; k < vectors.size(); ++k)
                      values[k][dim * vertex + d] = (*vectors[k])(i);
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
  VertexTransfer<dim>::locate(const Point<dim> &point) const
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
  std::vector<typename VertexTransfer<dim>::VectorType>
  VertexTransfer<dim>::interpolate(const DoFHandler<dim> &dof_handler) const
  {
    const IndexSet         &owned = dof_handler.locally_owned_dofs();
    std::vector<VectorType> result(values.size(), VectorType(owned, comm));
    std::vector<bool> done(dof_handler.get_triangulation().n_vertices(), false);
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        for (const unsigned int v : cell->vertex_indices())
          {
            if (done[cell->vertex_index(v)])
              continue;
            done[cell->vertex_index(v)] = true;
            const auto [k, lambda]      = locate(cell->vertex(v));
            for (unsigned int d = 0; d < dim; ++d)
              {
                const auto i = cell->vertex_dof_index(v, d);
                if (!owned.is_element(i))
                  continue;
                for (unsigned int n = 0; n < values.size(); ++n)
                  {
                    double value = 0.;
                    for (unsigned int j = 0; j <= dim; ++j)
                      value += lambda[j] * values[n][dim * cells[k][j] + d];
                    result[n](i) = value;
                  }
              }
          }
    for (auto &vector : result)
      vector.compress(VectorOperation::insert);
    return result;
  }

  template class VertexTransfer<2>;
  template class VertexTransfer<3>;
} // namespace signorini
