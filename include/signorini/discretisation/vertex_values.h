#ifndef signorini_discretisation_vertex_values_h
#define signorini_discretisation_vertex_values_h

#include <deal.II/distributed/tria.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/lac/trilinos_vector.h>

#include <vector>

namespace signorini
{
  /**
   * The values of vectors of a Lagrange displacement (one dof per node and
   * component: the vertices, and at degree 2 the mid-nodes) attached to the
   * cells of a distributed mesh for a checkpoint, each node's values once:
   * the first locally owned cell (in the order of the active cells) that
   * has a locally owned node carries it. A cell's record is a bit per node
   * of the cell (a byte at degree 1, four at degree 2 in 3D) naming the
   * nodes it carries, then, for each of them and each vector, its dim
   * values. deal.II's SolutionTransfer stores every dof of every cell
   * instead: about seven times as many bytes on a 3D Q1 mesh.
   *
   * The records travel with their cells when the mesh is loaded on another
   * number of processes; each value is written once, by the process that
   * holds its carrier, and summed into its owner's entry.
   */
  template <int dim>
  class VertexValues
  {
  public:
    using VectorType = dealii::TrilinosWrappers::MPI::Vector;

    /** Registers the records of @p vectors (locally owned entries read) on
     * @p dofs's mesh before it is saved; both must outlive the save. */
    static void
    attach(const dealii::DoFHandler<dim>         &dofs,
           const std::vector<const VectorType *> &vectors);

    /** After the mesh of @p dofs (its dofs distributed) was loaded from a
     * file that attach() wrote, fills @p vectors (locally owned entries,
     * laid out already) from the records (collective). Call it in the
     * place of the attach() call, before any other attached data is read.
     */
    static void
    restore(const dealii::DoFHandler<dim>   &dofs,
            const std::vector<VectorType *> &vectors);
  };
} // namespace signorini

#endif
