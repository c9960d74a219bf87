#ifndef signorini_mesh_adaptation_vertex_transfer_h
#define signorini_mesh_adaptation_vertex_transfer_h

#include <deal.II/base/bounding_box.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/point.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/grid/tria.h>
#include <deal.II/lac/trilinos_vector.h>
#include <deal.II/numerics/rtree.h>

#include <array>
#include <memory>
#include <vector>

namespace signorini
{
  /**
   * P1 fields carried across a remesh, between simplex meshes that share no
   * vertex: each new vertex takes the linear interpolant of the old cell
   * that holds it (for a point of a curved boundary outside the old,
   * polygonal mesh, the linear extension of the nearest old cell). On a
   * mesh refined globally this is exact: the same as deal.II's
   * SolutionTransfer.
   *
   * The old vertex values are gathered on every process, so that the new
   * mesh may be partitioned anew.
   */
  template <int dim>
  class VertexTransfer
  {
  public:
    using VectorType = dealii::TrilinosWrappers::MPI::Vector;

    /** Collects the vertex values of the ghosted @p vectors (P1, dim
     * components) of @p dof_handler, whose mesh is the serial @p old_mesh
     * or a fully distributed copy of it. */
    VertexTransfer(const dealii::Triangulation<dim>      &old_mesh,
                   const dealii::DoFHandler<dim>         &dof_handler,
                   const std::vector<const VectorType *> &vectors,
                   const MPI_Comm                         comm);

    /** The vectors on the locally owned dofs of @p dof_handler, on the new
     * mesh (not ghosted). */
    std::vector<VectorType>
    interpolate(const dealii::DoFHandler<dim> &dof_handler) const;

  private:
    /** The old cell for @p point and its barycentric coordinates. */
    std::pair<unsigned int, std::array<double, dim + 1>>
    locate(const dealii::Point<dim> &point) const;

    const MPI_Comm                                 comm;
    std::vector<dealii::Point<dim>>                vertices;
    std::vector<std::array<unsigned int, dim + 1>> cells;
    /** values[k][dim * vertex + component] of vector k. */
    std::vector<std::vector<double>> values;
    /** The old cells' bounding boxes, and a tree to search them. */
    std::vector<dealii::BoundingBox<dim>> boxes;
    using Tree = dealii::RTree<std::size_t,
                               boost::geometry::index::linear<16>,
                               dealii::IndexableGetterFromIndices<
                                 std::vector<dealii::BoundingBox<dim>>>>;
    std::unique_ptr<Tree> tree;
  };
} // namespace signorini

#endif
