#ifndef signorini_elasticity_direct_solver_status_h
#define signorini_elasticity_direct_solver_status_h

#include <string>

class Amesos_BaseSolver;

namespace signorini
{
  /**
   * What went wrong in the last phase of a Trilinos Amesos direct solver,
   * where it can tell. Amesos' MUMPS reports a failure on standard error
   * only and returns success: its INFOG(1) (negative on an error) and
   * INFOG(2) are read here. Compiled outside the unity build, as MUMPS'
   * header defines macros (INFO, ICNTL, ...) that other sources' names
   * would meet.
   */
  struct DirectSolverStatus
  {
    /** MUMPS' INFOG(1): 0 success, negative an error. */
    int error = 0;
    /** MUMPS' INFOG(2): the error's detail (for -13, the size that could
     * not be allocated, in MB if negative, else in words). */
    int detail = 0;

    /** Whether the error is a lack of memory (-8, -9, -13 to -15, -17,
     * -19, -20). */
    bool
    out_of_memory() const;

    /** The error for a message: "the direct solver could not allocate 400 MB
     * for the factorisation (MUMPS INFOG(1) = -13, INFOG(2) = -400)". Empty
     * on success. */
    std::string
    text() const;
  };

  /** The status of @p solver's last phase (success if it is not MUMPS). */
  DirectSolverStatus
  direct_solver_status(Amesos_BaseSolver &solver);
} // namespace signorini

#endif
