// What the unit tests print of their checks: a difference, and whether it
// is within its tolerance, on the first process only.
#ifndef signorini_tests_unit_checks_h
#define signorini_tests_unit_checks_h

#include <deal.II/base/mpi.h>

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
} // namespace checks

#endif
