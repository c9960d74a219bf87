#include <deal.II/base/bounding_box.h>
#include <deal.II/base/multithread_info.h>
#include <deal.II/base/utilities.h>

#include <signorini/input/entry_text.h>
#include <signorini/output/contact_pressure_table.h>
#include <signorini/output/file_output.h>
#include <signorini/output/obstacle_output.h>
#include <signorini/output/postprocessors.h>
#include <signorini/output/solution_piece.h>
#include <signorini/postprocessing/balance.h>
#include <signorini/postprocessing/contact_zone.h>
#include <signorini/postprocessing/pressure_recovery.h>
#include <signorini/postprocessing/probes.h>
#include <signorini/problem/contact_problem.h>

#include <cmath>
#include <filesystem>
#include <limits>
#include <optional>
#include <ostream>
#include <sstream>
#include <stdexcept>
#include <vector>

namespace signorini
{
  using namespace dealii;

  template <int dim>
  void
  ContactProblem<dim>::write_obstacle_and_parameters() const
  {
    const std::string &directory = parameters.output.directory;
    write_collectively(mpi_communicator, [&]() {
      if (Utilities::MPI::this_mpi_process(mpi_communicator) != 0)
        return;
      std::error_code error;
      std::filesystem::create_directories(directory, error);
      if (error)
        throw std::runtime_error("cannot create the output directory '" +
                                 directory + "': " + error.message());
      write_atomically(directory + "/parameters.prm",
                       [this](std::ostream &out) { out << parameters.text; });

      const auto             &mesh = discretisation.triangulation();
      std::vector<Point<dim>> vertices;
      for (unsigned int v = 0; v < mesh.n_vertices(); ++v)
        if (mesh.get_used_vertices()[v])
          vertices.push_back(mesh.get_vertices()[v]);
      const BoundingBox<dim> box(vertices);
      write_atomically(directory + "/obstacle.vtu", [&](std::ostream &out) {
        write_obstacles_vtu(out, *obstacle, box);
      });
      if (parameters.load_history.stepped())
        write_atomically(directory + "/force_displacement.gnuplot",
                         [&](std::ostream &out) {
                           write_force_displacement_chart(out);
                         });
    });
  }

  template <int dim>
  void
  ContactProblem<dim>::write_force_displacement_chart(std::ostream &out) const
  {
    // Along each obstacle's travel at the end of the history (the
    // obstacles are there now): the travel and the force on the body along
    // it, of the final cycle; if no obstacle moves, the size of each force
    // against t.
    const char        *axes  = "xyz";
    const unsigned int last  = parameters.refinement.n_cycles - 1;
    bool               moves = false;
    for (unsigned int k = 0; k < obstacle->size(); ++k)
      moves = moves || obstacle->displacement(k).norm() > 0.;
    out << "# The force-displacement chart of a load history, written by "
           "signorini:\n"
           "#   gnuplot force_displacement.gnuplot\n"
           "# in the output directory draws force_displacement.png from "
           "force_displacement.csv\n"
        << (moves ? "# (the final cycle's steps): each moving obstacle's "
                    "force on the body along its\n"
                    "# travel against the travel, the direction of its "
                    "displacement at the last step.\n" :
                    "# (the final cycle's steps): the size of each "
                    "obstacle's force on the body and its components\n"
                    "# against the pseudo-time t.\n")
        << "set datafile separator ','\n"
           "set datafile columnheaders\n"
           "set terminal pngcairo size 800,560 font ',11'\n"
           "set output 'force_displacement.png'\n"
           "set grid\n"
           "set key top left\n"
        << (moves ? "set xlabel 'travel of the obstacle [mm]'\n"
                    "set ylabel 'force on the body along the travel [N]'\n" :
                    "set xlabel 'pseudo-time t'\n"
                    "set ylabel 'force on the body [N]'\n")
        << "last = " << last << "\n";
    std::vector<std::string> curves;
    for (unsigned int k = 0; k < obstacle->size(); ++k)
      {
        const Tensor<1, dim> &travel = obstacle->displacement(k);
        if (moves && !(travel.norm() > 0.))
          continue;
        const std::string n = std::to_string(obstacle->number(k));
        // The components along the unit travel, or the size.
        std::string along_travel, along_force, size;
        for (unsigned int d = 0; d < dim; ++d)
          {
            const std::string f = "column('force" + n + "_" + axes[d] + "')";
            size += (d > 0 ? " + " : "") + f + "**2";
            if (travel[d] == 0.)
              continue;
            const std::string e = entry_text::of(travel[d] / travel.norm());
            const std::string u =
              "column('displacement" + n + "_" + axes[d] + "')";
            along_travel += (along_travel.empty() ? "" : " + ") + e + "*" + u;
            along_force += (along_force.empty() ? "" : " + ") + e + "*" + f;
          }
        const std::string title = "Obstacle" + (n == "1" ? "" : " " + n);
        if (moves)
          curves.push_back(
            "'force_displacement.csv' using (column('cycle') == last ? " +
            along_travel + " : NaN):(" + along_force +
            ") with linespoints title '" + title + "'");
        else
          {
            // With friction the components tell the normal force from the
            // tangential one: the size and each component.
            curves.push_back("'force_displacement.csv' using (column('cycle') "
                             "== last ? column('time') : NaN):(sqrt(" +
                             size + ")) with linespoints title '" + title +
                             "'");
            for (unsigned int d = 0; d < dim; ++d)
              curves.push_back(
                "'force_displacement.csv' using (column('cycle') == last ? "
                "column('time') : NaN):(column('force" +
                n + "_" + axes[d] + "')) with lines title '" + title + ", " +
                axes[d] + "'");
          }
      }
    if (curves.empty())
      out << "# (no obstacle: nothing to draw)\n";
    for (unsigned int i = 0; i < curves.size(); ++i)
      out << (i == 0 ? "plot " : ", \\\n     ") << curves[i]
          << (i + 1 == curves.size() ? "\n" : "");
  }

  template <int dim>
  void
  ContactProblem<dim>::record_statistics(const unsigned int cycle,
                                         const unsigned int step)
  {
    TimerOutput::Scope t(timer, "Output: statistics");
    const char        *axes    = "xyz";
    const auto        &history = parameters.load_history;
    StatisticsRow      row;
    row.add_count("cycle", cycle);
    // Only with a load history: a run of one step keeps its columns.
    if (history.stepped())
      {
        row.add_count("step", step);
        row.add("time", history.time(step));
      }
    row.add_count("cells",
                  discretisation.triangulation().n_global_active_cells());
    row.add_count("dofs", discretisation.dof_handler().n_dofs());
    row.add_count("iterations", newton.iterations());

    // The obstacle's force on the contact nodes, K u - f there.
    unsigned int   active = 0, sticking = 0, slipping = 0;
    double         penetration = 0.;
    Tensor<1, dim> contact_force;
    for (const auto &node : contact_surface.nodes())
      if (node.owned)
        {
          active += node.in_contact() ? 1 : 0;
          sticking += node.state == NodeState::stick ? 1 : 0;
          slipping += node.state == NodeState::slip ? 1 : 0;
          // A vertex's force once, at its first node.
          if (node.primary)
            for (unsigned int d = 0; d < dim; ++d)
              contact_force[d] += newton.residual()(node.dofs[d]);
          penetration = std::max(penetration,
                                 -contact_surface.deformed_gap(node, solution));
        }
    active        = Utilities::MPI::sum(active, mpi_communicator);
    contact_force = Utilities::MPI::sum(contact_force, mpi_communicator);
    // Where a support fixes a component of a contact node, K u - f there
    // is the support's reaction and the obstacle's force together: the
    // obstacle's share is its own.
    const auto &tangential = newton.tangential_traction();
    auto        zone       = evaluate_contact_zone(
      discretisation,
      contact_surface,
      recover_pressure(discretisation, contact_surface, pressure),
      solution,
      parameters.reference,
      tangential.size() > 0 ? &tangential : nullptr);
    if (zone.supported)
      contact_force += zone.supported_force;
    // The radial forces of a whole revolution cancel: its resultants are
    // axial (the sums of the radial nodal forces are not resultants).
    const bool revolution = discretisation.axisymmetric();
    if (revolution)
      contact_force[0] = 0.;
    penetration = Utilities::MPI::max(penetration, mpi_communicator);
    row.add_count("active_set", active);
    // With friction, how many of them stick and slip, the extent of the
    // stick zone, and the largest shear traction.
    double max_shear = 0.;
    if (law->path_dependent())
      {
        row.add_count("stick", Utilities::MPI::sum(sticking, mpi_communicator));
        row.add_count("slip", Utilities::MPI::sum(slipping, mpi_communicator));
        const auto &shear = newton.tangential_traction();
        for (const auto &node : contact_surface.nodes())
          if (node.owned)
            {
              Tensor<1, dim> q;
              for (unsigned int d = 0; d < dim; ++d)
                q[d] = shear(node.dofs[d]);
              max_shear = std::max(max_shear, q.norm());
            }
        row.add("stick_width", zone.stick_width);
        max_shear = Utilities::MPI::max(max_shear, mpi_communicator);
        row.add("max_shear", max_shear);
      }
    formulation->report(row, pcout);
    for (unsigned int d = 0; d < dim; ++d)
      row.add(std::string("contact_force_") + axes[d], contact_force[d]);
    row.add("max_penetration", penetration);

    double error_squared = 0.;
    for (const auto &cell :
         discretisation.triangulation().active_cell_iterators())
      if (cell->is_locally_owned())
        error_squared +=
          std::pow(estimated_error_per_cell(cell->active_cell_index()), 2);
    row.add("estimated_error",
            std::sqrt(Utilities::MPI::sum(error_squared, mpi_communicator)));

    const auto probes =
      evaluate_probes(discretisation, solution, parameters.output.probe_points);
    auto balance =
      evaluate_balance(discretisation, loads, parameters.material, solution);
    if (zone.supported)
      balance.support_reaction -= zone.supported_force;
    if (revolution)
      {
        balance.applied_force[0]    = 0.;
        balance.support_reaction[0] = 0.;
        zone.pressure_resultant[0]  = 0.;
      }
    row.add("max_pressure", zone.max_pressure);
    row.add("contact_width", zone.contact_width);
    std::ostringstream contact_columns;
    add_contact_columns(row, zone, *obstacle, contact_columns);
    for (unsigned int d = 0; d < dim; ++d)
      row.add(std::string("support_reaction_") + axes[d],
              balance.support_reaction[d]);
    // Load, supports and obstacle in equilibrium.
    const Tensor<1, dim> mismatch = balance.applied_force +
                                    balance.support_reaction +
                                    zone.pressure_resultant;
    const double scale = balance.applied_force.norm();
    const double equilibrium_error =
      scale > 0 ? mismatch.norm() / scale : mismatch.norm();
    row.add("equilibrium_error", equilibrium_error);
    row.add("energy", balance.energy);

    // The reference numbers at the step's pseudo-time.
    const auto  &reference      = parameters.reference;
    const double time           = history.time(step);
    const auto   relative_error = [time](const double           value,
                                       const ReferenceNumber &exact) {
      if (!exact)
        return std::numeric_limits<double>::quiet_NaN();
      const double v = exact.at(time);
      return std::abs(value - v) / (v != 0 ? std::abs(v) : 1.);
    };
    const double max_pressure_error =
      relative_error(zone.max_pressure, reference.max_pressure);
    const double contact_width_error =
      relative_error(zone.contact_width, reference.contact_width);
    const double stick_width_error =
      relative_error(zone.stick_width, reference.stick_width);
    const double max_shear_error =
      relative_error(max_shear, reference.max_shear);
    double energy_error = std::numeric_limits<double>::quiet_NaN();
    if (reference.energy)
      {
        const double exact = reference.energy.at(time);
        energy_error       = std::sqrt(std::abs(balance.energy - exact) /
                                 (exact != 0 ? std::abs(exact) : 1.));
      }
    const bool friction = law->path_dependent();
    if (reference.max_pressure)
      row.add("max_pressure_error", max_pressure_error);
    if (reference.contact_width)
      row.add("contact_width_error", contact_width_error);
    if (friction && reference.stick_width)
      row.add("stick_width_error", stick_width_error);
    if (friction && reference.max_shear)
      row.add("max_shear_error", max_shear_error);
    if (reference.energy)
      row.add("energy_error", energy_error);
    if (reference.contact_pressure)
      row.add("pressure_error", zone.pressure_error);
    for (unsigned int i = 0; i < probes.size(); ++i)
      for (unsigned int d = 0; d < dim; ++d)
        row.add("probe" + std::to_string(i) + "_u" + axes[d], probes[i][d]);
    record.add_statistics(row);

    if (history.stepped())
      {
        // Each obstacle's displacement and its force on the body, as the
        // statistics give it: K u - f at the contact nodes for a single
        // obstacle, the nodal p m n of its nodes for each of several; axial
        // alone in a revolved model.
        StatisticsRow travel;
        travel.add_count("cycle", cycle);
        travel.add_count("step", step);
        travel.add("time", history.time(step));
        for (unsigned int k = 0; k < obstacle->size(); ++k)
          {
            const std::string n = std::to_string(obstacle->number(k));
            Tensor<1, dim>    force =
              obstacle->size() == 1 ? contact_force : zone.obstacles[k].force;
            if (revolution)
              force[0] = 0.;
            for (unsigned int d = 0; d < dim; ++d)
              travel.add("displacement" + n + "_" + axes[d],
                         obstacle->displacement(k)[d]);
            for (unsigned int d = 0; d < dim; ++d)
              travel.add("force" + n + "_" + axes[d], force[d]);
          }
        record.add_force_displacement(travel);
      }

    pcout << "   " << newton.iterations() << " iterations, " << active
          << " active nodes, contact force ";
    if (obstacle->single_height())
      pcout << contact_force[dim - 1];
    else
      pcout << "(" << contact_force << ")";
    pcout << ", max penetration " << penetration << std::endl;
    pcout << "   max pressure " << zone.max_pressure << ", contact width "
          << zone.contact_width << ", energy " << balance.energy << std::endl;
    pcout << contact_columns.str();
    pcout << "   equilibrium: load (" << balance.applied_force
          << ") + supports (" << balance.support_reaction
          << ") + integrated pressure " << zone.integrated_pressure
          << ": relative mismatch " << equilibrium_error << std::endl;
    if (reference.max_pressure)
      pcout << "   max pressure error " << max_pressure_error << std::endl;
    if (reference.contact_width)
      pcout << "   contact width error " << contact_width_error << std::endl;
    if (friction && reference.stick_width)
      pcout << "   stick width error " << stick_width_error << std::endl;
    if (friction && reference.max_shear)
      pcout << "   max shear error " << max_shear_error << std::endl;
    if (reference.contact_pressure)
      pcout << "   pressure error " << zone.pressure_error << std::endl;
    if (reference.energy)
      pcout << "   energy error " << energy_error << std::endl;
    for (unsigned int i = 0; i < probes.size(); ++i)
      pcout << "   probe " << i << " (" << parameters.output.probe_points[i]
            << "): u = (" << probes[i] << ")" << std::endl;
  }

  template <int dim>
  std::shared_ptr<const VtuPiece>
  ContactProblem<dim>::solution_piece()
  {
    const unsigned int rank =
      Utilities::MPI::this_mpi_process(mpi_communicator);
    const auto &owned_dofs    = discretisation.locally_owned_dofs();
    const auto &relevant_dofs = discretisation.locally_relevant_dofs();

    // The nodes' states (0 open, 1 closed) as a nodal vector with ghost
    // entries (a process's cells reach contact nodes that another owns):
    // the field active_set.
    VectorType owned_active(owned_dofs, mpi_communicator);
    for (const auto &node : contact_surface.nodes())
      if (node.owned && node.in_contact())
        owned_active(node.scalar_dof) = static_cast<double>(node.state);
    owned_active.compress(VectorOperation::insert);
    VectorType active;
    active.reinit(solution); // its map, not a third one (see setup_system)
    active = owned_active;

    const DisplacementFields<dim> fields(parameters.material,
                                         *obstacle,
                                         axisymmetry::axis_tolerance(
                                           discretisation.body_size()));
    const std::vector<double>     relevant_displacement =
      relevant_entries(solution, relevant_dofs);
    const std::vector<double> relevant_pressure = relevant_entries(
      recover_pressure(discretisation, contact_surface, pressure),
      relevant_dofs);
    const std::vector<double> relevant_active =
      relevant_entries(active, relevant_dofs);
    return std::make_shared<const VtuPiece>(
      build_piece(PieceInputs<dim>{discretisation.mapping(),
                                   discretisation.dof_handler(),
                                   relevant_dofs,
                                   relevant_displacement,
                                   relevant_pressure,
                                   relevant_active,
                                   estimated_error_per_cell,
                                   static_cast<float>(rank),
                                   fields},
                  MultithreadInfo::n_threads()));
  }

  template <int dim>
  std::string
  ContactProblem<dim>::write_solution(
    const std::shared_ptr<const VtuPiece> &piece,
    const std::string                     &base,
    const unsigned int                     threads)
  {
    const unsigned int rank =
      Utilities::MPI::this_mpi_process(mpi_communicator);
    const unsigned int n_ranks =
      Utilities::MPI::n_mpi_processes(mpi_communicator);
    const std::string &directory = parameters.output.directory;
    const std::string  name      = base + (n_ranks == 1 ? ".vtu" : ".pvtu");
    if (n_ranks == 1)
      {
        // In the background, before the records that list it.
        const auto compression = parameters.output.compression;
        background_writer.add([piece, directory, name, compression, threads]() {
          write_atomically(directory + "/" + name, [&](std::ostream &out) {
            write_vtu(out, *piece, compression, threads);
          });
        });
        return name;
      }
    write_collectively(mpi_communicator, [&]() {
      write_atomically(directory + "/" + base + "." +
                         Utilities::int_to_string(rank, 4) + ".vtu",
                       [&](std::ostream &out) {
                         write_vtu(out,
                                   *piece,
                                   parameters.output.compression,
                                   MultithreadInfo::n_threads());
                       });
    });
    write_collectively(mpi_communicator, [&]() {
      if (rank != 0)
        return;
      std::vector<std::string> pieces;
      for (unsigned int r = 0; r < n_ranks; ++r)
        pieces.push_back(base + "." + Utilities::int_to_string(r, 4) + ".vtu");
      write_atomically(directory + "/" + name, [&](std::ostream &out) {
        write_pvtu_record(out, pieces, *piece);
      });
    });
    return name;
  }

  template <int dim>
  void
  ContactProblem<dim>::write_records()
  {
    const std::string &directory     = parameters.output.directory;
    const auto         records       = record.series_records();
    const auto         write_records = [directory, records]() {
      for (const auto &[file, text] : records)
        write_atomically(directory + "/" + file,
                         [&](std::ostream &out) { out << text; });
    };
    if (Utilities::MPI::n_mpi_processes(mpi_communicator) == 1)
      background_writer.add(write_records);
    else
      write_collectively(mpi_communicator, [&]() {
        if (Utilities::MPI::this_mpi_process(mpi_communicator) == 0)
          write_records();
      });
  }

  template <int dim>
  void
  ContactProblem<dim>::output_results(const unsigned int cycle)
  {
    TimerOutput::Scope t(timer, "Output");
    // The previous cycle's files are written by now (they had its whole
    // computation to be).
    background_writer.wait();
    const auto piece = solution_piece();

    // On one process, until the last cycle the file is compressed while
    // the next cycle computes, on the core that computation leaves free;
    // the last one has nothing to overlap, and run_cycles waits for it: it
    // takes all cores. run_cycles launches the writes after the checkpoint
    // is queued.
    const bool         last_cycle = cycle + 1 == parameters.refinement.n_cycles;
    const unsigned int threads = last_cycle ? MultithreadInfo::n_threads() : 1;
    const auto        &history = parameters.load_history;
    if (history.stepped() && last_cycle)
      record.add_history_file(
        history.end_time,
        write_solution(piece,
                       "history-" +
                         Utilities::int_to_string(history.n_steps, 3),
                       threads));
    record.add_solution_file(
      cycle,
      write_solution(piece,
                     "solution-" + Utilities::int_to_string(cycle, 2),
                     threads));
    write_records();

    const std::string &directory = parameters.output.directory;
    if (parameters.output.contact_pressure_table)
      {
        const VectorType shown =
          recover_pressure(discretisation, contact_surface, pressure);
        write_collectively(mpi_communicator, [&]() {
          write_contact_pressure_table(directory + "/contact_pressure-" +
                                         Utilities::int_to_string(cycle, 2) +
                                         ".csv",
                                       contact_surface,
                                       shown,
                                       solution,
                                       mpi_communicator,
                                       newton.tangential_traction().size() > 0 ?
                                         &newton.tangential_traction() :
                                         nullptr);
        });
      }
  }

  template <int dim>
  void
  ContactProblem<dim>::output_step(const unsigned int cycle,
                                   const unsigned int step)
  {
    TimerOutput::Scope t(timer, "Output");
    const auto        &history = parameters.load_history;
    // The final cycle's steps as a series of their own; the next step
    // computes while one process writes them on one thread.
    if (cycle + 1 == parameters.refinement.n_cycles)
      record.add_history_file(
        history.time(step),
        write_solution(solution_piece(),
                       "history-" + Utilities::int_to_string(step, 3),
                       1));
    // The rows so far: a run that stops at a later step keeps them.
    // (Launched by solve_history() with the step's checkpoint.)
    write_records();
  }

  template void
  ContactProblem<2>::write_obstacle_and_parameters() const;
  template void
  ContactProblem<3>::write_obstacle_and_parameters() const;
  template void
  ContactProblem<2>::write_force_displacement_chart(std::ostream &) const;
  template void
  ContactProblem<3>::write_force_displacement_chart(std::ostream &) const;
  template void
  ContactProblem<2>::record_statistics(unsigned int, unsigned int);
  template void
  ContactProblem<3>::record_statistics(unsigned int, unsigned int);
  template void
  ContactProblem<2>::output_results(unsigned int);
  template void
  ContactProblem<3>::output_results(unsigned int);
  template void
  ContactProblem<2>::output_step(unsigned int, unsigned int);
  template void
  ContactProblem<3>::output_step(unsigned int, unsigned int);
  template std::shared_ptr<const VtuPiece>
  ContactProblem<2>::solution_piece();
  template std::shared_ptr<const VtuPiece>
  ContactProblem<3>::solution_piece();
  template std::string
  ContactProblem<2>::write_solution(const std::shared_ptr<const VtuPiece> &,
                                    const std::string &,
                                    unsigned int);
  template std::string
  ContactProblem<3>::write_solution(const std::shared_ptr<const VtuPiece> &,
                                    const std::string &,
                                    unsigned int);
  template void
  ContactProblem<2>::write_records();
  template void
  ContactProblem<3>::write_records();
} // namespace signorini
