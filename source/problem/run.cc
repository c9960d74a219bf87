#include <deal.II/base/utilities.h>
#include <deal.II/lac/la_parallel_vector.h>

#include <signorini/base/failures.h>
#include <signorini/base/interruption.h>
#include <signorini/base/memory.h>
#include <signorini/base/text.h>
#include <signorini/discretisation/axisymmetry.h>
#include <signorini/elasticity/rigid_motions.h>
#include <signorini/input/entry_text.h>
#include <signorini/input/input_error.h>
#include <signorini/mesh_adaptation/kelly_indicator.h>
#include <signorini/postprocessing/boundary_penetration.h>
#include <signorini/problem/contact_problem.h>

#include <chrono>
#include <iostream>
#include <set>

namespace signorini
{
  using namespace dealii;

  template <int dim>
  void
  ContactProblem<dim>::run(const bool resume)
  {
    try
      {
        run_cycles(resume);
      }
    catch (...)
      {
        // A failed or interrupted run reports one line, not a timer
        // summary, and keeps the files of its finished cycles: the writes
        // queued finish, what is unfinished is removed.
        timer.disable_output();
        std::exception_ptr failure     = std::current_exception();
        const auto         interrupted = [&failure]() {
          try
            {
              std::rethrow_exception(failure);
            }
          catch (const Interrupted &)
            {
              return true;
            }
          catch (...)
            {
              return false;
            }
        };
        try
          {
            background_writer.launch();
            background_writer.wait();
          }
        catch (...)
          {
            // A write that failed matters more than the interruption.
            if (interrupted())
              failure = std::current_exception();
          }
        tidy_output();
        try
          {
            std::rethrow_exception(failure);
          }
        catch (Interrupted &stop)
          {
            stop.finished_cycle = finished_cycle;
            if (finished_step &&
                (!finished_cycle || finished_step->cycle > *finished_cycle))
              stop.finished_step =
                std::make_pair(*finished_step->step, finished_step->cycle);
            stop.resumable = (stop.finished_cycle || stop.finished_step) &&
                             writes_checkpoints();
            throw;
          }
      }
  }

  template <int dim>
  void
  ContactProblem<dim>::run_cycles(const bool resume)
  {
    double run_time = 0., start = wall_time();
    // The entries of t alone (the obstacles' displacements, the traction
    // resultant) at every step, before anything is written; the functions
    // of the points too are checked where they are evaluated.
    const auto &history = parameters.load_history;
    for (unsigned int step = 1; step <= history.n_steps; ++step)
      {
        const double t = history.time(step);
        obstacle->set_time(t);
        if (const auto &resultant =
              parameters.boundary_conditions.traction_resultant)
          resultant->value(t);
      }
    // The mesh, its constraints and the contact surface at the end of the
    // load history: a run of one step is solved there.
    set_time(history.end_time);
    {
      TimerOutput::Scope           t(timer, "Setup: grid");
      std::set<types::boundary_id> dirichlet_ids;
      for (const auto &[id, mask] : parameters.boundary_conditions.dirichlet)
        dirichlet_ids.insert(id);
      discretisation.make_grid(
        {{"Boundary conditions/Dirichlet", dirichlet_ids},
         {"Boundary conditions/Traction boundary ids",
          parameters.boundary_conditions.traction_ids},
         {"Obstacle/Contact boundary ids", parameters.obstacle.contact_ids}});
      if (discretisation.axisymmetric())
        axisymmetry::check_off_axis(discretisation.triangulation(),
                                    parameters.boundary_conditions.traction_ids,
                                    "Boundary conditions/Traction boundary ids",
                                    axisymmetry::axis_tolerance(
                                      discretisation.body_size()));
    }
    setup_system();
    {
      std::vector<HeldDirection<dim>> contact_directions;
      for (const auto &node : contact_surface.nodes())
        if (node.owned)
          {
            contact_directions.push_back({node.position, node.normal});
            // Friction holds the body along the node's tangents too.
            if (law->frictional(node))
              for (const auto &tangent : node.tangents)
                contact_directions.push_back({node.position, tangent});
          }
      const bool supports_hold =
        check_rigid_motions_held(discretisation,
                                 contact_directions,
                                 rigid_body_modes(discretisation),
                                 parameters.contact.acts());
      // Where the supports hold the body, a singular system is the
      // material's or the mesh's.
      if (supports_hold)
        {
          const auto  &material = parameters.material;
          const double ratio = material.template lambda<dim>() / material.mu();
          newton.supports_hold_body(ratio > 1e3 ?
                                      "is Material/Poisson's ratio (" +
                                        entry_text::of(material.poisson_ratio) +
                                        ", lambda / mu = " + number(ratio) +
                                        ") too near 0.5?" :
                                      std::string());
        }
    }
    if (const auto warning =
          parameters.material.check_element(discretisation.simplex());
        !warning.empty() &&
        Utilities::MPI::this_mpi_process(mpi_communicator) == 0)
      std::cerr << "signorini: warning: " << warning << std::endl;
    run_time += wall_time() - start;
    const auto resumed = start_output(resume);
    if (resumed)
      {
        restore_checkpoint(*resumed, run_time);
        if (resumed->step)
          {
            finished_step = resumed;
            if (resumed->cycle > 0)
              finished_cycle = resumed->cycle - 1;
          }
        else
          finished_cycle = resumed->cycle;
      }
    // After a checkpoint within a cycle, the cycle continues on its mesh
    // with the next load step.
    const unsigned int first_cycle =
      resumed ? resumed->cycle + (resumed->step ? 0 : 1) : 0;
    for (unsigned int cycle = first_cycle;
         cycle < parameters.refinement.n_cycles;
         ++cycle)
      {
        const bool continued = resumed && resumed->step && cycle == first_cycle;
        // A signal stops the run here, after the last cycle's files, or
        // between Newton steps (NewtonDriver::iterate).
        interruption::check(mpi_communicator);
        CycleTimings timings;
        timings.cycle = cycle;
        start         = wall_time();
        if (cycle > 0 && !continued)
          refine_grid();
        pcout << "Cycle " << cycle << ": "
              << discretisation.triangulation().n_global_active_cells()
              << " cells, " << discretisation.dof_handler().n_dofs() << " dofs"
              << std::endl;
        const double solve_start = wall_time();
        if (history.stepped())
          // Every step but the last with its results and checkpoints; the
          // last one is finished as a cycle without a history.
          solve_history(cycle,
                        continued ? *resumed->step + 1 : 1,
                        run_time,
                        start);
        else
          solve(cycle);
        timings.contact_solve = wall_time() - solve_start;
        // The system is built anew on the next mesh: free it before the
        // error estimate and the output's patches take their memory. (The
        // timing table solves once more on this mesh.)
        if (!parameters.output.timing_table)
          elastic_operator->release();
        estimate_error();
        run_time += wall_time() - start;
        timings.run_time = run_time;
        record_statistics(cycle, history.n_steps);
        output_results(cycle);
        // The cycle's results are written: a body that an obstacle passes
        // through where it may not touch stops the run after them.
        if (parameters.contact.acts())
          check_boundary_penetration(discretisation,
                                     contact_surface,
                                     solution,
                                     cycle);
        if (parameters.output.timing_table)
          {
            timings.linear_solve = time_linear_solve();
            write_timings(timings);
          }
        // The solution file's arrays are free (unless the background
        // writer still holds them) before the checkpoint packs the mesh.
        release_free_memory();
        save_checkpoint({cycle, {}}, run_time);
        background_writer.launch();
        release_free_memory();
        finished_cycle = cycle;
      }
    {
      TimerOutput::Scope t(timer, "Output");
      background_writer.wait();
    }
    if (parameters.output.print_timings)
      {
        Utilities::System::MemoryStats memory;
        Utilities::System::get_memory_stats(memory);
        const double peak =
          Utilities::MPI::sum(static_cast<double>(memory.VmHWM),
                              mpi_communicator) /
          1024.;
        pcout << "Peak memory: " << number(peak) << " MB on "
              << Utilities::MPI::n_mpi_processes(mpi_communicator)
              << " processes, "
              << number(peak * 1024. / discretisation.dof_handler().n_dofs())
              << " kB per dof of the final mesh" << std::endl;
      }
  }

  template <int dim>
  void
  ContactProblem<dim>::set_time(const double t)
  {
    loads.set_time(t);
    discretisation.set_time(t);
    obstacle->set_time(t);
  }

  template <int dim>
  double
  ContactProblem<dim>::wall_time() const
  {
    MPI_Barrier(mpi_communicator);
    return std::chrono::duration<double>(
             std::chrono::steady_clock::now().time_since_epoch())
      .count();
  }

  template <int dim>
  void
  ContactProblem<dim>::solve(const unsigned int cycle)
  {
    elastic_operator->assemble_load();
    newton.start_cycle();
    formulation->solve(newton, cycle);
  }

  template <int dim>
  void
  ContactProblem<dim>::estimate_error()
  {
    TimerOutput::Scope t(timer, "Refine: error estimate");
    // Weighted by 2 pi r in an axisymmetric model, as its energy norm is,
    // unless the scene asks for the error of the section.
    const axisymmetry::KellyCoefficient<dim> revolved;
    const bool                               weighted =
      discretisation.axisymmetric() &&
      parameters.refinement.kelly_weight == Refinement::KellyWeight::revolution;
    const auto u = discretisation.relevant_copy(solution);
    estimate_kelly_indicators(discretisation.mapping(),
                              discretisation.dof_handler(),
                              discretisation.face_quadrature(),
                              u,
                              weighted ? &revolved : nullptr,
                              estimated_error_per_cell);
  }

  template <int dim>
  void
  ContactProblem<dim>::refine_grid()
  {
    TimerOutput::Scope t(timer, "Refine: mesh and transfer");
    // The next cycle starts from this one's displacement and active set
    // when the mesh adaptation carries them over (not across a remesh).
    // With friction the obstacle's shear traction too: the stick and slip
    // states start from it where the last mesh left them (not where a load
    // history starts again from zero).
    const bool shear = newton.tangential_traction().size() > 0 &&
                       !parameters.load_history.stepped();
    std::vector<const VectorType *> vectors = {&solution, &pressure};
    if (shear)
      vectors.push_back(&newton.tangential_traction());
    auto carried = discretisation.refine(estimated_error_per_cell, vectors);
    setup_system();
    if (!carried.empty())
      {
        solution = carried[0];
        pressure = carried[1];
        if (shear)
          newton.restore_tangential_traction(carried[2]);
        newton.carry_over();
      }
  }

  template void
  ContactProblem<2>::run(bool);
  template void
  ContactProblem<3>::run(bool);
  template void
  ContactProblem<2>::run_cycles(bool);
  template void
  ContactProblem<3>::run_cycles(bool);
  template void
  ContactProblem<2>::set_time(double);
  template void
  ContactProblem<3>::set_time(double);
  template double
  ContactProblem<2>::wall_time() const;
  template double
  ContactProblem<3>::wall_time() const;
  template void
  ContactProblem<2>::solve(unsigned int);
  template void
  ContactProblem<3>::solve(unsigned int);
  template void
  ContactProblem<2>::estimate_error();
  template void
  ContactProblem<3>::estimate_error();
  template void
  ContactProblem<2>::refine_grid();
  template void
  ContactProblem<3>::refine_grid();
} // namespace signorini
