#include <deal.II/base/mpi.h>

#include <signorini/base/interruption.h>

#include <csignal>

namespace signorini
{
  namespace
  {
    /** The first signal received, 0 until one is. */
    volatile std::sig_atomic_t received_signal = 0;

    extern "C" void
    record_signal(const int signal)
    {
      if (received_signal == 0)
        received_signal = signal;
    }

    const char *
    signal_name(const int signal)
    {
      switch (signal)
        {
          case SIGINT:
            return "SIGINT";
          case SIGTERM:
            return "SIGTERM";
          default:
            return "a signal";
        }
    }
  } // namespace

  namespace interruption
  {
    void
    install()
    {
      struct sigaction action = {};
      action.sa_handler       = record_signal;
      sigemptyset(&action.sa_mask);
      // Interrupted system calls resume; the handler runs once per signal.
      action.sa_flags = SA_RESTART | SA_RESETHAND;
      sigaction(SIGINT, &action, nullptr);
      sigaction(SIGTERM, &action, nullptr);
      std::signal(SIGXFSZ, SIG_IGN);
    }

    int
    received()
    {
      return received_signal;
    }

    void
    check(const MPI_Comm mpi_communicator)
    {
      const int signal =
        dealii::Utilities::MPI::max(static_cast<int>(received_signal),
                                    mpi_communicator);
      if (signal != 0)
        throw Interrupted(signal);
    }
  } // namespace interruption

  Interrupted::Interrupted(const int signal)
    : std::runtime_error(std::string("interrupted by ") + signal_name(signal))
    , signal(signal)
  {
  }

  int
  Interrupted::status() const
  {
    return 128 + signal;
  }

  std::string
  Interrupted::message(const std::string &file) const
  {
    std::string line = what();
    if (finished_step)
      line += " after load step " + std::to_string(finished_step->first) +
              " of cycle " + std::to_string(finished_step->second);
    else if (!finished_cycle)
      return line + " before cycle 0 finished; nothing to resume";
    else
      line += " after cycle " + std::to_string(*finished_cycle);
    if (resumable)
      return line + "; resume with --resume " + file;
    return line + " (no checkpoint to resume from: Output/Checkpoint is off "
                  "or the mesh is remeshed by Gmsh)";
  }
} // namespace signorini
