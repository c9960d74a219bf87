#ifndef signorini_mesh_adaptation_partition_balance_h
#define signorini_mesh_adaptation_partition_balance_h

#include <deal.II/distributed/tria.h>

#include <vector>

namespace signorini
{
  /**
   * The number of cells each process will own once the refinement and
   * coarsening flags of @p mesh are carried out, gathered on every process
   * (a refined cell counts its children, a coarsened family its parent). To
   * be called after prepare_coarsening_and_refinement().
   */
  template <int dim>
  std::vector<double>
  predicted_cells_per_process(
    const dealii::parallel::distributed::Triangulation<dim> &mesh);

  /**
   * Carries out the refinement and coarsening flags of @p mesh, and moves
   * the partition only where the processes' shares of the new mesh would be
   * too uneven.
   *
   * By default p4est balances every refined mesh anew. The cells that then
   * change processes are built on their new process one level at a time,
   * and deal.II 9.4 walks the whole local mesh for each level: on two
   * processes the 2D Hertz scene took 7 to 8 such passes per refinement
   * instead of 2, and its refinements took longer than on one process.
   * So when no process would own more than (1 + @p imbalance_tolerance)
   * times the mean number of cells, each process keeps its cells: they are
   * weighted by the inverse of their number on their process, which puts
   * the balance of the weights where the partition already lies. Otherwise
   * the new mesh is balanced by the number of cells.
   *
   * Returns whether the mesh was balanced anew.
   */
  template <int dim>
  bool
  execute_refinement(dealii::parallel::distributed::Triangulation<dim> &mesh,
                     double imbalance_tolerance);
} // namespace signorini

#endif
