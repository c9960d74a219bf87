#ifndef signorini_base_failures_h
#define signorini_base_failures_h

#include <new>
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

  /**
   * A lack of memory that a library reported rather than threw (MUMPS):
   * a std::bad_alloc, so that it is reported as one, with what could not
   * be had.
   */
  class OutOfMemory : public std::bad_alloc
  {
  public:
    explicit OutOfMemory(const std::string &what_failed)
      : message(what_failed)
    {
    }

    const char *
    what() const noexcept override
    {
      return message.c_str();
    }

  private:
    std::string message;
  };
} // namespace signorini

#endif
