#include <deal.II/base/utilities.h>

#include <signorini/base/failures.h>
#include <signorini/base/interruption.h>
#include <signorini/base/text.h>
#include <signorini/input/input_error.h>
#include <signorini/postprocessing/boundary_penetration.h>
#include <signorini/problem/contact_problem.h>

namespace signorini
{
  using namespace dealii;

  template <int dim>
  void
  ContactProblem<dim>::solve_history(const unsigned int cycle,
                                     const unsigned int first_step,
                                     const double       run_time,
                                     const double       start)
  {
    const auto &history = parameters.load_history;
    // Each cycle replays the whole history on its mesh, from zero; a run
    // resumed from the checkpoint of a step continues with the next one
    // from the state the checkpoint restored.
    if (first_step == 1)
      {
        solution = 0.;
        pressure = 0.;
      }
    for (unsigned int step = first_step; step <= history.n_steps; ++step)
      {
        // A signal stops the run between steps too (or between Newton
        // steps); the files and the checkpoint of the finished steps stay.
        if (step > 1)
          interruption::check(mpi_communicator);
        const double t = history.time(step);
        pcout << "  Step " << step << " of " << history.n_steps << ": t = " << t
              << std::endl;
        start_load_step(step);
        try
          {
            solve(cycle);
          }
        catch (const SolverFailure &failure)
          {
            throw SolverFailure(failure.status,
                                std::string(failure.what()) + " (load step " +
                                  std::to_string(step) + " of " +
                                  std::to_string(history.n_steps) +
                                  ", t = " + number(t) + ")");
          }
        if (step == history.n_steps)
          break;
        estimate_error();
        record_statistics(cycle, step);
        output_step(cycle, step);
        if (parameters.contact.acts())
          check_boundary_penetration(discretisation,
                                     contact_surface,
                                     solution,
                                     cycle);
        // After the step's files (queued before it on one process).
        save_checkpoint({cycle, step}, run_time + wall_time() - start);
        background_writer.launch();
        finished_step = CheckpointPoint{cycle, step};
      }
  }

  template <int dim>
  void
  ContactProblem<dim>::start_load_step(const unsigned int step)
  {
    TimerOutput::Scope t(timer, "Setup: load step");
    const double       time = parameters.load_history.time(step);
    // The loads and the Dirichlet data of the step, and the obstacles where
    // it puts them.
    set_time(time);
    // The displacement of the last step (zero on the first) with the new
    // Dirichlet values: the Newton iteration's start.
    VectorType owned(discretisation.locally_owned_dofs(), mpi_communicator);
    owned = solution;
    discretisation.constraints().distribute(owned);
    solution = owned;
    // The elastic system holds the old constraints, loads and gaps: built
    // anew by the next solve.
    elastic_operator->invalidate();
    // The contact nodes (their gaps, and which obstacle each faces) of the
    // moved obstacles.
    try
      {
        contact_surface.setup(discretisation);
      }
    catch (const InputError &error)
      {
        throw InputError(error.entry,
                         std::string(error.what()) + " at t = " + number(time));
      }
    newton.start_step();
  }

  template void
  ContactProblem<2>::solve_history(unsigned int, unsigned int, double, double);
  template void
  ContactProblem<3>::solve_history(unsigned int, unsigned int, double, double);
  template void
  ContactProblem<2>::start_load_step(unsigned int);
  template void
  ContactProblem<3>::start_load_step(unsigned int);
} // namespace signorini
