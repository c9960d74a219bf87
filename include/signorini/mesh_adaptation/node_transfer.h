#ifndef signorini_mesh_adaptation_node_transfer_h
#define signorini_mesh_adaptation_node_transfer_h

#include <deal.II/base/bounding_box.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/point.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe.h>
#include <deal.II/grid/tria.h>
#include <deal.II/lac/trilinos_vector.h>
#include <deal.II/numerics/rtree.h>

#include <array>
#include <memory>
#include <vector>

namespace signorini
{
  /**
   * P1 and P2 fields carried across a remesh, between simplex meshes that
   * share no node: each new node (vertex, and at degree 2 the middle of an
   * edge) takes the value of the old cell that holds it, its P1 or P2
   * interpolant (for a point of a curved boundary outside the old mesh,
   * the polynomial's extension from the nearest old cell). On a mesh
   * refined globally this is exact: the same as deal.II's
   * SolutionTransfer. The old cells are located as straight simplices of
   * their vertices, and a new mid-node is taken at the middle of its
   * straight edge.
   *
   * The old cells' node values are gathered on every process, so that the
   * new mesh may be partitioned anew.
   */
  template <int dim>
  class NodeTransfer
  {
  public:
    using VectorType = dealii::TrilinosWrappers::MPI::Vector;

    /** Collects the node values of the ghosted @p vectors (P1 or P2, dim
     * components) of @p dof_handler, whose mesh is the serial @p old_mesh
     * or a fully distributed copy of it. */
    NodeTransfer(const dealii::Triangulation<dim>      &old_mesh,
                 const dealii::DoFHandler<dim>         &dof_handler,
                 const std::vector<const VectorType *> &vectors,
                 const MPI_Comm                         comm);

    /** The vectors on the locally owned dofs of @p dof_handler, on the new
     * mesh (not ghosted; its element is the old one's). */
    std::vector<VectorType>
    interpolate(const dealii::DoFHandler<dim> &dof_handler) const;

  private:
    /** The old cell for @p point and its barycentric coordinates. */
    std::pair<unsigned int, std::array<double, dim + 1>>
    locate(const dealii::Point<dim> &point) const;

    const MPI_Comm comm;
    /** The scalar element of the nodes (P1 or P2). */
    std::unique_ptr<const dealii::FiniteElement<dim>> base;
    std::vector<dealii::Point<dim>>                   vertices;
    std::vector<std::array<unsigned int, dim + 1>>    cells;
    /** At degree 2: each old cell's edges (the serial mesh's line indices,
     * in the cell's order), and each line's ends. */
    std::vector<std::vector<unsigned int>>   cell_lines;
    std::vector<std::array<unsigned int, 2>> line_ends;
    /** values[k][dim * node + component] of vector k, the old mesh's
     * vertices first, then (degree 2) its lines. */
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
