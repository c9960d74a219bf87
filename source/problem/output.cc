#include <deal.II/base/bounding_box.h>
#include <deal.II/base/data_out_base.h>
#include <deal.II/base/multithread_info.h>
#include <deal.II/base/utilities.h>
#include <deal.II/fe/fe_values.h>

#include <signorini/input/input_error.h>
#include <signorini/output/file_output.h>
#include <signorini/output/postprocessors.h>
#include <signorini/output/solution_piece.h>
#include <signorini/problem/contact_problem.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <map>
#include <memory>
#include <sstream>
#include <stdexcept>

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
                       [this](std::ostream &out) { out << parameter_text; });

      std::vector<Point<dim>> vertices;
      for (unsigned int v = 0; v < triangulation->n_vertices(); ++v)
        if (triangulation->get_used_vertices()[v])
          vertices.push_back(triangulation->get_vertices()[v]);
      const BoundingBox<dim> box(vertices);
      write_atomically(directory + "/obstacle.vtu", [&](std::ostream &out) {
        parameters.obstacle.write_vtu(out, box);
      });
    });
  }

  template <int dim>
  bool
  ContactProblem<dim>::evaluate_displacement(const Point<dim> &point,
                                             Tensor<1, dim>   &value) const
  {
    // deal.II 9.4's GridTools::find_active_cell_around_point can return a
    // tetrahedron that does not contain the point; test containment here.
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned() &&
          cell->bounding_box().point_inside(point, 1e-10))
        {
          Point<dim> unit;
          try
            {
              unit = mapping->transform_real_to_unit_cell(cell, point);
            }
          catch (const typename Mapping<dim>::ExcTransformationFailed &)
            {
              continue;
            }
          if (!cell->reference_cell().contains_point(unit, 1e-10))
            continue;
          FEValues<dim> fe_values(*mapping,
                                  *fe,
                                  Quadrature<dim>(
                                    std::vector<Point<dim>>{unit}),
                                  update_values);
          fe_values.reinit(cell);
          std::vector<Vector<double>> values(1, Vector<double>(dim));
          fe_values.get_function_values(solution, values);
          for (unsigned int d = 0; d < dim; ++d)
            value[d] = values[0](d);
          return true;
        }
    return false;
  }

  template <int dim>
  void
  ContactProblem<dim>::record_statistics(const unsigned int cycle)
  {
    CycleStatistics<dim> row;
    row.cycle              = cycle;
    row.cells              = triangulation->n_global_active_cells();
    row.dofs               = dof_handler.n_dofs();
    row.iterations         = newton_iterations;
    row.multiplier_updates = multiplier_updates;
    row.penalty_parameter  = penalty_parameter;

    const bool contact =
      parameters.contact.method != ContactParameters::Method::none;
    unsigned int active      = 0;
    double       penetration = 0.;
    for (const auto &node : contact_nodes)
      if (node.owned)
        {
          active += contact && node.active ? 1 : 0;
          for (unsigned int d = 0; d < dim; ++d)
            row.contact_force[d] += residual(node.dofs[d]);
          penetration =
            std::max(penetration, -(solution(node.dofs[dim - 1]) + node.gap));
        }
    row.active_nodes = Utilities::MPI::sum(active, mpi_communicator);
    row.contact_force =
      Utilities::MPI::sum(row.contact_force, mpi_communicator);
    row.max_penetration = Utilities::MPI::max(penetration, mpi_communicator);

    double error_squared = 0.;
    for (const auto &cell : triangulation->active_cell_iterators())
      if (cell->is_locally_owned())
        error_squared +=
          std::pow(estimated_error_per_cell(cell->active_cell_index()), 2);
    row.estimated_error =
      std::sqrt(Utilities::MPI::sum(error_squared, mpi_communicator));

    // Each probe is evaluated by the lowest-ranked process that owns a cell
    // around it.
    const unsigned int rank =
      Utilities::MPI::this_mpi_process(mpi_communicator);
    const unsigned int n_ranks =
      Utilities::MPI::n_mpi_processes(mpi_communicator);
    for (const auto &point : parameters.output.probe_points)
      {
        Tensor<1, dim>     value;
        const unsigned int owner =
          Utilities::MPI::min(evaluate_displacement(point, value) ? rank :
                                                                    n_ranks,
                              mpi_communicator);
        if (owner == n_ranks)
          {
            std::ostringstream text;
            text << "the point (" << point << ") is not in the body";
            throw InputError("Output/Probe points", text.str());
          }
        row.probes.push_back(
          Utilities::MPI::sum(rank == owner ? value : Tensor<1, dim>(),
                              mpi_communicator));
      }
    evaluate_contact_zone(row);
    evaluate_balance_and_energy(row);
    cycle_statistics.push_back(row);

    if (parameters.contact.method ==
        ContactParameters::Method::augmented_lagrangian)
      pcout << "   " << row.multiplier_updates << " multiplier updates, "
            << "penalty parameter " << row.penalty_parameter << std::endl;
    pcout << "   " << row.iterations << " iterations, " << row.active_nodes
          << " active nodes, contact force " << row.contact_force[dim - 1]
          << ", max penetration " << row.max_penetration << std::endl;
    pcout << "   max pressure " << row.max_pressure << ", contact width "
          << row.contact_width << ", energy " << row.energy << std::endl;
    pcout << "   equilibrium: load (" << row.applied_force << ") + supports ("
          << row.support_reaction << ") + integrated pressure "
          << row.integrated_pressure << ": relative mismatch "
          << row.equilibrium_error << std::endl;
    if (parameters.reference.max_pressure)
      pcout << "   max pressure error " << row.max_pressure_error << std::endl;
    if (parameters.reference.contact_width)
      pcout << "   contact width error " << row.contact_width_error
            << std::endl;
    if (parameters.reference.contact_pressure)
      pcout << "   pressure error " << row.pressure_error << std::endl;
    if (parameters.reference.energy)
      pcout << "   energy error " << row.energy_error << std::endl;
    for (unsigned int i = 0; i < row.probes.size(); ++i)
      pcout << "   probe " << i << " (" << parameters.output.probe_points[i]
            << "): u = (" << row.probes[i] << ")" << std::endl;
  }

  namespace
  {
    template <int dim>
    void
    write_statistics(std::ostream                            &out,
                     const std::vector<CycleStatistics<dim>> &rows,
                     const Reference<dim>                    &reference,
                     const ContactParameters::Method          method)
    {
      const char *axes = "xyz";
      // The penalty in use (a remedy may change it), and the multiplier
      // updates of the augmented Lagrangian method.
      const bool penalty =
        method == ContactParameters::Method::penalty ||
        method == ContactParameters::Method::augmented_lagrangian;
      const bool lagrangian =
        method == ContactParameters::Method::augmented_lagrangian;
      out << "cycle,cells,dofs,iterations,active_set";
      if (lagrangian)
        out << ",multiplier_updates";
      if (penalty)
        out << ",penalty_parameter";
      for (unsigned int d = 0; d < dim; ++d)
        out << ",contact_force_" << axes[d];
      out << ",max_penetration,estimated_error,max_pressure,contact_width";
      for (unsigned int d = 0; d < dim; ++d)
        out << ",support_reaction_" << axes[d];
      out << ",equilibrium_error,energy";
      if (reference.max_pressure)
        out << ",max_pressure_error";
      if (reference.contact_width)
        out << ",contact_width_error";
      if (reference.energy)
        out << ",energy_error";
      if (reference.contact_pressure)
        out << ",pressure_error";
      for (unsigned int i = 0; !rows.empty() && i < rows[0].probes.size(); ++i)
        for (unsigned int d = 0; d < dim; ++d)
          out << ",probe" << i << "_u" << axes[d];
      out << '\n';

      char       number[32];
      const auto put = [&](const double value) {
        std::snprintf(number, sizeof(number), ",%.10e", value);
        out << number;
      };
      for (const auto &row : rows)
        {
          out << row.cycle << ',' << row.cells << ',' << row.dofs << ','
              << row.iterations << ',' << row.active_nodes;
          if (lagrangian)
            out << ',' << row.multiplier_updates;
          if (penalty)
            put(row.penalty_parameter);
          for (unsigned int d = 0; d < dim; ++d)
            put(row.contact_force[d]);
          put(row.max_penetration);
          put(row.estimated_error);
          put(row.max_pressure);
          put(row.contact_width);
          for (unsigned int d = 0; d < dim; ++d)
            put(row.support_reaction[d]);
          put(row.equilibrium_error);
          put(row.energy);
          if (reference.max_pressure)
            put(row.max_pressure_error);
          if (reference.contact_width)
            put(row.contact_width_error);
          if (reference.energy)
            put(row.energy_error);
          if (reference.contact_pressure)
            put(row.pressure_error);
          for (const auto &probe : row.probes)
            for (unsigned int d = 0; d < dim; ++d)
              put(probe[d]);
          out << '\n';
        }
    }
  } // namespace

  template <int dim>
  std::map<std::string, std::string>
  ContactProblem<dim>::series_records() const
  {
    std::ostringstream pvd, statistics;
    DataOutBase::write_pvd_record(pvd, written_cycles);
    write_statistics(statistics,
                     cycle_statistics,
                     parameters.reference,
                     parameters.contact.method);
    return {{"solution.pvd", pvd.str()}, {"statistics.csv", statistics.str()}};
  }

  template <int dim>
  void
  ContactProblem<dim>::output_results(const unsigned int cycle)
  {
    TimerOutput::Scope t(timer, "Output");
    // The previous cycle's files are written by now (they had its whole
    // computation to be).
    background_writer.wait();
    const unsigned int rank =
      Utilities::MPI::this_mpi_process(mpi_communicator);
    const unsigned int n_ranks =
      Utilities::MPI::n_mpi_processes(mpi_communicator);

    // The active set as a nodal vector with ghost entries (a process's
    // cells reach contact nodes that another owns).
    TrilinosWrappers::MPI::Vector owned_active(locally_owned_dofs,
                                               mpi_communicator);
    if (parameters.contact.method != ContactParameters::Method::none)
      for (const auto &node : contact_nodes)
        if (node.owned && node.active)
          owned_active(node.dofs[dim - 1]) = 1.;
    owned_active.compress(VectorOperation::insert);
    TrilinosWrappers::MPI::Vector active(locally_owned_dofs,
                                         locally_relevant_dofs,
                                         mpi_communicator);
    active = owned_active;

    const DisplacementFields<dim> fields(parameters.material,
                                         parameters.obstacle);
    const std::vector<double>     relevant_displacement =
      relevant_entries(solution, locally_relevant_dofs);
    const std::vector<double> relevant_pressure =
      relevant_entries(pressure, locally_relevant_dofs);
    const std::vector<double> relevant_active =
      relevant_entries(active, locally_relevant_dofs);
    const auto piece = std::make_shared<const VtuPiece>(
      build_piece(PieceInputs<dim>{*mapping,
                                   dof_handler,
                                   locally_relevant_dofs,
                                   relevant_displacement,
                                   relevant_pressure,
                                   relevant_active,
                                   estimated_error_per_cell,
                                   static_cast<float>(rank),
                                   fields},
                  MultithreadInfo::n_threads()));

    const std::string &directory = parameters.output.directory;
    const std::string  base = "solution-" + Utilities::int_to_string(cycle, 2);
    const std::string  name = base + (n_ranks == 1 ? ".vtu" : ".pvtu");
    written_cycles.emplace_back(cycle, name);
    const auto records       = series_records();
    const auto write_records = [directory, records]() {
      for (const auto &[file, text] : records)
        write_atomically(directory + "/" + file,
                         [&](std::ostream &out) { out << text; });
    };

    if (n_ranks == 1)
      {
        // In the background: the VTU file, then the records that list it
        // (run_cycles launches them after the checkpoint is queued). Until
        // the last cycle the file is compressed while the next cycle
        // computes, on the core that computation leaves free; the last one
        // has nothing to overlap, and run_cycles waits for it: it takes all
        // cores.
        const unsigned int threads =
          cycle + 1 < parameters.refinement.n_cycles ?
            1 :
            MultithreadInfo::n_threads();
        background_writer.add([piece, directory, name, threads]() {
          write_atomically(directory + "/" + name, [&](std::ostream &out) {
            write_vtu(out, *piece, threads);
          });
        });
        background_writer.add(write_records);
      }
    else
      {
        write_collectively(mpi_communicator, [&]() {
          write_atomically(directory + "/" + base + "." +
                             Utilities::int_to_string(rank, 4) + ".vtu",
                           [&](std::ostream &out) {
                             write_vtu(out,
                                       *piece,
                                       MultithreadInfo::n_threads());
                           });
        });
        write_collectively(mpi_communicator, [&]() {
          if (rank != 0)
            return;
          std::vector<std::string> pieces;
          for (unsigned int r = 0; r < n_ranks; ++r)
            pieces.push_back(base + "." + Utilities::int_to_string(r, 4) +
                             ".vtu");
          write_atomically(directory + "/" + name, [&](std::ostream &out) {
            write_pvtu_record(out, pieces, *piece);
          });
          write_records();
        });
      }
    if (parameters.output.contact_pressure_table)
      write_collectively(mpi_communicator,
                         [&]() { write_contact_pressure_table(cycle); });
  }

  template void
  ContactProblem<2>::write_obstacle_and_parameters() const;
  template void
  ContactProblem<3>::write_obstacle_and_parameters() const;
  template void
  ContactProblem<2>::record_statistics(unsigned int);
  template void
  ContactProblem<3>::record_statistics(unsigned int);
  template void
  ContactProblem<2>::output_results(unsigned int);
  template void
  ContactProblem<3>::output_results(unsigned int);
} // namespace signorini
