#include <deal.II/base/utilities.h>

#include <signorini/output/file_output.h>
#include <signorini/problem/contact_problem.h>

#include <chrono>

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
    elastic_operator->invalidate();

    MPI_Barrier(mpi_communicator);
    const auto start = std::chrono::steady_clock::now();
    elastic_operator->assemble_load();
    newton.assemble_newton_system();
    newton.solve(true);
    MPI_Barrier(mpi_communicator);
    const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start)
        .count();

    solution = saved_solution;
    elastic_operator->invalidate();
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
    record.add_timings(complete);

    write_collectively(mpi_communicator, [&]() {
      if (Utilities::MPI::this_mpi_process(mpi_communicator) != 0)
        return;
      write_atomically(parameters.output.directory + "/timings.csv",
                       [&](std::ostream &out) {
                         out << record.timings_table();
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
