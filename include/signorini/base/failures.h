#ifndef signorini_base_failures_h
#define signorini_base_failures_h

#include <stdexcept>
#include <string>

namespace signorini
{
  /** Exit statuses of the program; README lists them. */
  namespace exit_status
  {
    constexpr int success             = 0;
    constexpr int input_error         = 1;
    constexpr int contact_no_converge = 2;
    constexpr int active_set_cycling  = 3;
    constexpr int linear_solver       = 4;
    constexpr int other               = 5;
    constexpr int contact_stalled     = 6;
    constexpr int multipliers_slow    = 7;
  } // namespace exit_status

  /**
   * A solver that failed: the message is one line for the user, and the
   * exit status tells scripts which failure it was.
   */
  class SolverFailure : public std::runtime_error
  {
  public:
    SolverFailure(const int status, const std::string &message)
      : std::runtime_error(message)
      , status(status)
    {
    }

    const int status;
  };
} // namespace signorini

#endif
