// execute_refinement: a refined p4est mesh keeps its partition while no
// process would own more than (1 + tolerance) times the mean number of
// cells, and is balanced by the number of cells beyond that. The unit
// square (cube) refined globally lies on two processes as the halves
// y < 1/2 and y > 1/2 (z in 3D) of p4est's curve: refining the half x < 1/2
// adds as many cells to both, refining the corner at the origin adds them
// to the first only, and tolerance 0 balances every refined mesh that is
// not balanced already. Printed: the predicted and the actual cells per
// process, whether the partition moved, how many cells changed processes,
// and the largest share over the mean.

#include <deal.II/base/mpi.h>
#include <deal.II/distributed/tria.h>
#include <deal.II/grid/cell_id.h>
#include <deal.II/grid/grid_generator.h>

#include <signorini/mesh_adaptation/partition_balance.h>

#include "checks.h"
#include <algorithm>
#include <functional>
#include <iostream>
#include <numeric>
#include <set>
#include <string>
#include <vector>

using namespace dealii;
using namespace signorini;
using checks::first_process;
using checks::report;

namespace
{
  template <int dim>
  void
  refine(const std::string                             &what,
         const std::function<bool(const Point<dim> &)> &flag,
         const double                                   tolerance,
         const bool                                     expect_balanced)
  {
    const MPI_Comm                            comm = MPI_COMM_WORLD;
    parallel::distributed::Triangulation<dim> mesh(comm);
    GridGenerator::hyper_cube(mesh, 0., 1.);
    mesh.refine_global(dim == 2 ? 4 : 3);

    std::set<CellId> owned_before;
    for (const auto &cell : mesh.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          owned_before.insert(cell->id());
          if (flag(cell->center()))
            cell->set_refine_flag();
        }
    mesh.prepare_coarsening_and_refinement();
    const auto predicted = predicted_cells_per_process(mesh);
    const bool balanced  = execute_refinement(mesh, tolerance);

    unsigned int moved = 0, owned = 0;
    for (const auto &cell : mesh.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          ++owned;
          const bool stayed =
            owned_before.count(cell->id()) > 0 ||
            (cell->level() > 0 && owned_before.count(cell->parent()->id()));
          moved += stayed ? 0 : 1;
        }
    moved               = Utilities::MPI::sum(moved, comm);
    const auto   actual = Utilities::MPI::all_gather(comm, owned);
    const double mean =
      std::accumulate(actual.begin(), actual.end(), 0.) / actual.size();
    const double share = *std::max_element(actual.begin(), actual.end()) / mean;

    if (first_process())
      {
        std::cout << dim << "D, " << what << ", tolerance " << tolerance << ": "
                  << mesh.n_global_active_cells() << " cells\n"
                  << "  predicted per process:";
        for (const double n : predicted)
          std::cout << ' ' << n;
        std::cout << "\n  actual per process:   ";
        for (const unsigned int n : actual)
          std::cout << ' ' << n;
        std::cout << "\n  balanced anew: " << (balanced ? "yes" : "no")
                  << (balanced == expect_balanced ? "  (ok)" : "  (FAILED)")
                  << "\n  cells that changed processes: " << moved << '\n';
      }
    if (balanced)
      report("largest share over the mean, minus 1", share - 1., 0.01);
    else
      {
        double off = 0.;
        for (unsigned int p = 0; p < actual.size(); ++p)
          off = std::max(off, std::abs(actual[p] - predicted[p]));
        report("kept: |actual - predicted| cells", off, 0.);
        report("kept: cells that changed processes", moved, 0.);
      }
  }

  template <int dim>
  void
  run()
  {
    const bool several = Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD) > 1;
    const auto half    = [](const Point<dim> &p) { return p[0] < 0.5; };
    const auto corner  = [](const Point<dim> &p) { return p.norm() < 0.3; };
    // The corner puts 18 % (2D) and 9 % (3D) more cells than the mean on
    // the first process.
    refine<dim>("the half x < 1/2 refined", half, 0.1, false);
    refine<dim>("the corner at the origin refined", corner, 0.05, several);
    refine<dim>("the corner at the origin refined", corner, 0.2, false);
    refine<dim>("the corner at the origin refined", corner, 0., several);
  }
} // namespace

int
main(int argc, char *argv[])
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  run<2>();
  run<3>();
}
