// What the unit tests print of their checks: a difference, and whether it
// is within its tolerance, or a property and whether it holds, on the first
// process only. A check that fails also makes the program end with exit
// status 1 (on every process where it failed), so that the test fails at
// its run, whatever its .output says.
#ifndef signorini_tests_unit_checks_h
#define signorini_tests_unit_checks_h

#include <deal.II/base/mpi.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/tria.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <iomanip>
#include <iostream>
#include <string>

namespace checks
{
  /** Whether this is the first process (or the only one: a program that
   * does not start MPI). */
  inline bool
  first_process()
  {
    int initialized = 0, finalized = 0;
    MPI_Initialized(&initialized);
    MPI_Finalized(&finalized);
    return !initialized || finalized ||
           dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0;
  }

  /** Exit status 1 at the end of the program: the first failed check
   * registers it (after MPI has ended, when main returns). */
  inline void
  failed()
  {
    static bool registered = false;
    if (registered)
      return;
    registered = true;
    std::atexit([] {
      std::cout.flush();
      std::fflush(nullptr);
      std::_Exit(1);
    });
  }

  /** "  WHAT: DIFFERENCE  (ok)", or (FAILED) beyond @p tolerance (or not
   * a number). */
  inline void
  report(const std::string &what,
         const double       difference,
         const double       tolerance)
  {
    const bool ok = difference <= tolerance;
    if (!ok)
      failed();
    if (first_process())
      std::cout << "  " << what << ": " << std::scientific
                << std::setprecision(1) << difference
                << (ok ? "  (ok)" : "  (FAILED)") << std::defaultfloat
                << std::setprecision(10) << '\n';
  }

  /** "  WHAT: yes", or "  WHAT: NO (FAILED)" if @p holds is false. */
  inline bool
  expect(const std::string &what, const bool holds)
  {
    if (!holds)
      failed();
    if (first_process())
      std::cout << "  " << what << ": " << (holds ? "yes" : "NO (FAILED)")
                << '\n';
    return holds;
  }
  /** The unit cube (a boundary id per face) refined @p global times, then
   * @p steps times more where cell centres lie within @p radius of the
   * origin: a mesh with hanging nodes. */
  template <int dim>
  void
  corner_refined_cube(dealii::Triangulation<dim> &mesh,
                      const unsigned int          global,
                      const unsigned int          steps,
                      const double                radius)
  {
    dealii::GridGenerator::hyper_cube(mesh, 0., 1., true);
    mesh.refine_global(global);
    for (unsigned int step = 0; step < steps; ++step)
      {
        for (const auto &cell : mesh.active_cell_iterators())
          if (cell->is_locally_owned() && cell->center().norm() < radius)
            cell->set_refine_flag();
        mesh.execute_coarsening_and_refinement();
      }
  }
} // namespace checks

#endif
