#include <deal.II/base/mpi.h>
#include <deal.II/distributed/tria.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/multigrid/mg_transfer_global_coarsening.h>

#include <signorini/elasticity/coarsening_sequence.h>

#include <algorithm>
#include <map>

namespace signorini
{
  using namespace dealii;

  namespace
  {
    using CellKey = CellId::binary_type;

    /** How many times the fine mesh refines each of its refined cells
     * below it (the depth of its deepest active descendant), over all
     * processes. */
    template <int dim>
    std::map<CellKey, unsigned int>
    refinement_heights(const parallel::distributed::Triangulation<dim> &fine)
    {
      // -1: not known here (only artificial cells below).
      std::vector<std::vector<int>> height(fine.n_levels());
      for (unsigned int level = fine.n_levels(); level-- > 0;)
        {
          height[level].assign(fine.n_raw_cells(level), -1);
          for (const auto &cell : fine.cell_iterators_on_level(level))
            if (cell->is_active())
              height[level][cell->index()] = cell->is_artificial() ? -1 : 0;
            else
              {
                int below = -1;
                for (const auto &child : cell->child_iterators())
                  below = std::max(below, height[level + 1][child->index()]);
                height[level][cell->index()] = below < 0 ? -1 : below + 1;
              }
        }
      std::vector<std::pair<CellKey, unsigned int>> known;
      for (unsigned int level = 0; level < fine.n_levels(); ++level)
        for (const auto &cell : fine.cell_iterators_on_level(level))
          if (cell->has_children() && height[level][cell->index()] > 0)
            known.emplace_back(cell->id().template to_binary<dim>(),
                               height[level][cell->index()]);
      std::map<CellKey, unsigned int> heights;
      const auto                      add = [&](const auto &pairs) {
        for (const auto &[key, h] : pairs)
          {
            auto &entry = heights[key];
            entry       = std::max(entry, h);
          }
      };
      if (Utilities::MPI::n_mpi_processes(fine.get_communicator()) == 1)
        add(known);
      else
        for (const auto &pairs :
             Utilities::MPI::all_gather(fine.get_communicator(), known))
          add(pairs);
      return heights;
    }
  } // namespace

  template <int dim>
  std::vector<std::shared_ptr<const Triangulation<dim>>>
  coarsening_sequence(const Triangulation<dim> &fine)
  {
    const auto *distributed =
      dynamic_cast<const parallel::distributed::Triangulation<dim> *>(&fine);
    if (distributed == nullptr || fine.n_global_levels() == 1)
      return MGTransferGlobalCoarseningTools::
        create_geometric_coarsening_sequence(fine);

    const MPI_Comm comm    = fine.get_communicator();
    const auto     heights = refinement_heights(*distributed);
    const auto     height  = [&](const CellId &id) -> int {
      const auto found = heights.find(id.template to_binary<dim>());
      return found == heights.end() ? 0 : int(found->second);
    };
    const unsigned int top = fine.n_global_levels() - 1;

    std::vector<std::shared_ptr<const Triangulation<dim>>> meshes(top + 1);
    meshes[top].reset(&fine, [](auto *) {});

    auto coarse = std::make_shared<parallel::distributed::Triangulation<dim>>(
      comm, fine.get_mesh_smoothing());
    {
      const auto [vertices, cells, subcells] =
        GridTools::get_coarse_mesh_description(fine);
      for (const auto id : fine.get_manifold_ids())
        if (id != numbers::flat_manifold_id)
          coarse->set_manifold(id, fine.get_manifold(id));
      coarse->create_triangulation(vertices, cells, subcells);
    }
    meshes[0] = coarse;

    // The mesh of t coarsenings from the one of t + 1: its active cells
    // that the fine mesh refines more than t times below them, refined.
    bool nested = true;
    for (unsigned int k = 1; k < top && nested; ++k)
      {
        const int t = top - k;
        auto mesh = std::make_shared<parallel::distributed::Triangulation<dim>>(
          comm, fine.get_mesh_smoothing());
        mesh->copy_triangulation(*meshes[k - 1]);
        for (const auto &cell : mesh->active_cell_iterators())
          if (cell->is_locally_owned() && height(cell->id()) > t)
            cell->set_refine_flag();
        mesh->execute_coarsening_and_refinement();
        // p4est's balance may have refined more; a cell the fine mesh does
        // not have would break the transfer.
        for (const auto &cell : mesh->active_cell_iterators())
          if (cell->is_locally_owned() && cell->level() > 0 &&
              height(cell->parent()->id()) == 0)
            nested = false;
        nested    = Utilities::MPI::min(nested ? 1 : 0, comm) == 1;
        meshes[k] = mesh;
      }
    if (!nested)
      return MGTransferGlobalCoarseningTools::
        create_geometric_coarsening_sequence(fine);
    return meshes;
  }

  template std::vector<std::shared_ptr<const Triangulation<2>>>
  coarsening_sequence(const Triangulation<2> &);
  template std::vector<std::shared_ptr<const Triangulation<3>>>
  coarsening_sequence(const Triangulation<3> &);
} // namespace signorini
