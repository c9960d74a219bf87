// What the unit tests print of their checks: a difference, and whether it
// is within its tolerance, on the first process only.
#ifndef signorini_tests_unit_checks_h
#define signorini_tests_unit_checks_h

#include <deal.II/base/mpi.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/tria.h>

#include <iomanip>
#include <iostream>
#include <string>

namespace checks
{
  inline bool
  first_process()
  {
    return dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0;
  }

  /** "  WHAT: DIFFERENCE  (ok)", or (FAILED) beyond @p tolerance. */
  inline void
  report(const std::string &what,
         const double       difference,
         const double       tolerance)
  {
    if (first_process())
      std::cout << "  " << what << ": " << std::scientific
                << std::setprecision(1) << difference
                << (difference <= tolerance ? "  (ok)" : "  (FAILED)")
                << std::defaultfloat << std::setprecision(10) << '\n';
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
