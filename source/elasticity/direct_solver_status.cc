#include <signorini/elasticity/direct_solver_status.h>

#include <Amesos_Mumps.h>

namespace signorini
{
  bool
  DirectSolverStatus::out_of_memory() const
  {
    switch (error)
      {
        case -8:
        case -9:
        case -13:
        case -14:
        case -15:
        case -17:
        case -19:
        case -20:
          return true;
        default:
          return false;
      }
  }

  std::string
  DirectSolverStatus::text() const
  {
    if (error == 0)
      return "";
    const std::string code = "(MUMPS INFOG(1) = " + std::to_string(error) +
                             ", INFOG(2) = " + std::to_string(detail) + ")";
    if (error == -13)
      {
        // INFOG(2): words, or millions of bytes if negative.
        const double megabytes =
          detail < 0 ? -static_cast<double>(detail) : 8e-6 * detail;
        return "the direct solver could not allocate " +
               (megabytes >= 1 ?
                  std::to_string(static_cast<long long>(megabytes + 0.5)) +
                    " MB" :
                  std::string("memory")) +
               " for the factorisation " + code;
      }
    if (out_of_memory())
      return "the direct solver ran out of memory " + code;
    return "the direct solver failed " + code;
  }

  DirectSolverStatus
  direct_solver_status(Amesos_BaseSolver &solver)
  {
    DirectSolverStatus status;
    if (auto *mumps = dynamic_cast<Amesos_Mumps *>(&solver))
      {
        status.error  = mumps->GetINFOG()[0];
        status.detail = mumps->GetINFOG()[1];
      }
    return status;
  }
} // namespace signorini
