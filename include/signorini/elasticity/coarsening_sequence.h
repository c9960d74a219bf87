#ifndef signorini_elasticity_coarsening_sequence_h
#define signorini_elasticity_coarsening_sequence_h

#include <deal.II/grid/tria.h>

#include <memory>
#include <vector>

namespace signorini
{
  /**
   * The meshes of global-coarsening multigrid for @p fine, coarsest first,
   * the last one @p fine itself (not owned): each the one after it
   * coarsened once everywhere (a family of children whose cells are all
   * active becomes their parent), as deal.II's
   * MGTransferGlobalCoarseningTools::create_geometric_coarsening_sequence
   * makes them, but built upwards from the coarse mesh: a cell is refined on
   * the mesh of t coarsenings if the fine mesh refines it more than t
   * times below it. deal.II's own copies the fine mesh and coarsens the
   * copy, which took half the multigrid's setup and doubled the mesh's
   * memory at the finest level. On a p4est mesh; any other mesh, or a
   * balance that would refine a cell the fine mesh does not, gets deal.II's
   * sequence.
   */
  template <int dim>
  std::vector<std::shared_ptr<const dealii::Triangulation<dim>>>
  coarsening_sequence(const dealii::Triangulation<dim> &fine);
} // namespace signorini

#endif
