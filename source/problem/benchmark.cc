#include <deal.II/base/utilities.h>

#include <signorini/output/file_output.h>
#include <signorini/problem/contact_problem.h>

#include <chrono>
#include <cstdio>

namespace signorini
{
  using namespace dealii;

  template <int dim>
  double
  ContactProblem<dim>::time_linear_solve()
  {
    // The lower bound of a contact solve: one linear solve of what a solver
    // that knew the contact zone in advance would solve, the Newton system
    // of the converged active set (the body may be held by contact alone),
    // assembled anew and solved with the same linear solver from a zero
    // initial guess.
    const auto saved_solution = solution;
    solution                  = 0;
    matrix_assembled          = false;

    MPI_Barrier(mpi_communicator);
    const auto start = std::chrono::steady_clock::now();
    assemble_load();
    assemble_newton_system();
    solve(true);
    MPI_Barrier(mpi_communicator);
    const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start)
        .count();

    solution         = saved_solution;
    matrix_assembled = false;
    return seconds;
  }

  template <int dim>
  void
  ContactProblem<dim>::write_timings(const CycleTimings &row)
  {
    Utilities::System::MemoryStats memory;
    Utilities::System::get_memory_stats(memory);
    CycleTimings complete = row;
    complete.peak_memory =
      Utilities::MPI::sum(static_cast<double>(memory.VmHWM), mpi_communicator) /
      1024.;
    cycle_timings.push_back(complete);

    write_collectively(mpi_communicator, [&]() {
      if (Utilities::MPI::this_mpi_process(mpi_communicator) != 0)
        return;
      write_atomically(
        parameters.output.directory + "/timings.csv", [&](std::ostream &out) {
          out << "cycle,dofs,iterations,contact_solve,linear_solve,ratio,"
                 "run_time,peak_memory\n";
          char line[256];
          for (const auto &t : cycle_timings)
            {
              const auto &stats = cycle_statistics[t.cycle];
              std::snprintf(line,
                            sizeof(line),
                            "%u,%llu,%u,%.6f,%.6f,%.3f,%.6f,%.1f\n",
                            t.cycle,
                            static_cast<unsigned long long>(stats.dofs),
                            stats.iterations,
                            t.contact_solve,
                            t.linear_solve,
                            t.contact_solve / t.linear_solve,
                            t.run_time,
                            t.peak_memory);
              out << line;
            }
        });
    });
  }

  template double
  ContactProblem<2>::time_linear_solve();
  template double
  ContactProblem<3>::time_linear_solve();
  template void
  ContactProblem<2>::write_timings(const CycleTimings &);
  template void
  ContactProblem<3>::write_timings(const CycleTimings &);
} // namespace signorini
