#ifndef signorini_discretisation_vertex_values_h
#define signorini_discretisation_vertex_values_h

#include <deal.II/distributed/tria.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/lac/trilinos_vector.h>

#include <vector>

namespace signorini
{
  /**
   * The values of vectors of a Q1 displacement (one dof per vertex and
   * component) attached to the cells of a distributed mesh for a checkpoint,
   * each vertex's values once: the first locally owned cell (in the order of
   * the active cells) that has a locally owned vertex carries it. A cell's
   * record is a byte naming the vertices it carries, then, for each of them
   * and each vector, its dim values. deal.II's SolutionTransfer stores every
   * dof of every cell instead: 2^dim times dim values per cell and vector,
   * about seven times as many bytes on a 3D mesh.
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
