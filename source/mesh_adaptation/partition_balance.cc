#include <deal.II/base/mpi.h>

#include <signorini/mesh_adaptation/partition_balance.h>

#include <algorithm>
#include <boost/signals2/connection.hpp>
#include <cmath>
#include <limits>
#include <numeric>

namespace signorini
{
  using namespace dealii;

  template <int dim>
  std::vector<double>
  predicted_cells_per_process(
    const parallel::distributed::Triangulation<dim> &mesh)
  {
    const double children = GeometryInfo<dim>::max_children_per_cell;
    double       cells    = 0.;
    for (const auto &cell : mesh.active_cell_iterators())
      if (cell->is_locally_owned())
        cells += cell->refine_flag_set()  ? children :
                 cell->coarsen_flag_set() ? 1. / children :
                                            1.;
    return Utilities::MPI::all_gather(mesh.get_communicator(), cells);
  }

  template <int dim>
  bool
  execute_refinement(parallel::distributed::Triangulation<dim> &mesh,
                     const double imbalance_tolerance)
  {
    const auto   cells = predicted_cells_per_process(mesh);
    const double total = std::accumulate(cells.begin(), cells.end(), 0.);
    const double most  = *std::max_element(cells.begin(), cells.end());
    const double mean  = total / cells.size();
    if (cells.size() == 1 || most > (1. + imbalance_tolerance) * mean)
      {
        mesh.execute_coarsening_and_refinement();
        return cells.size() > 1;
      }

    // Every process's cells weigh W / (its number of cells), W the largest
    // unsigned int: the cumulative weights along p4est's curve then reach
    // the same total on every process, so the balanced partition is the
    // present one, up to the weights' rounding (n^2 / W cells for n cells
    // per process: none below 6e4 cells, about 230 at a million). The sum
    // stays below W per process, well inside p4est's 64-bit sums.
    const double mine =
      cells[Utilities::MPI::this_mpi_process(mesh.get_communicator())];
    const double       most_weight = std::numeric_limits<unsigned int>::max();
    const unsigned int weight      = static_cast<unsigned int>(
      std::max(1., std::floor(most_weight / std::max(mine, 1.))));
    const boost::signals2::scoped_connection connection =
      mesh.signals.weight.connect(
        [weight](const auto &, const auto) { return weight; });
    mesh.execute_coarsening_and_refinement();
    return false;
  }

  template std::vector<double>
  predicted_cells_per_process(const parallel::distributed::Triangulation<2> &);
  template std::vector<double>
  predicted_cells_per_process(const parallel::distributed::Triangulation<3> &);
  template bool
  execute_refinement(parallel::distributed::Triangulation<2> &, double);
  template bool
  execute_refinement(parallel::distributed::Triangulation<3> &, double);
} // namespace signorini
