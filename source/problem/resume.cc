#include <deal.II/distributed/solution_transfer.h>
#include <deal.II/distributed/tria.h>

#include <signorini/input/input_error.h>
#include <signorini/output/checkpoint.h>
#include <signorini/output/file_output.h>
#include <signorini/output/output_series.h>
#include <signorini/problem/contact_problem.h>

#include <boost/archive/binary_iarchive.hpp>
#include <boost/archive/binary_oarchive.hpp>
#include <boost/serialization/map.hpp>
#include <boost/serialization/string.hpp>
#include <boost/serialization/utility.hpp>
#include <boost/serialization/vector.hpp>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

namespace signorini
{
  using namespace dealii;

  // The results so far, for a checkpoint. A field added to these structs
  // must be added here too; the sizes below remind of it.
  template <class Archive, int dim>
  void
  serialize(Archive &archive, CycleStatistics<dim> &row, const unsigned int)
  {
    static_assert(sizeof(CycleStatistics<dim>) == (dim == 2 ? 200 : 224),
                  "CycleStatistics changed: serialize the new field here");
    archive &row.cycle &row.cells &row.dofs &row.iterations &row
      .multiplier_updates &row.sign_rule &row.penalty_parameter &row
      .active_nodes &row.contact_force &row.max_penetration &row
      .estimated_error &row.max_pressure &row.contact_width &row
      .applied_force &row.support_reaction &row.integrated_pressure &row
      .equilibrium_error &row.energy &row.max_pressure_error &row
      .contact_width_error &row.energy_error &row.pressure_error &row.probes;
  }

  template <class Archive>
  void
  serialize(Archive &archive, CycleTimings &row, const unsigned int)
  {
    static_assert(sizeof(CycleTimings) == 40,
                  "CycleTimings changed: serialize the new field here");
    archive &row.cycle &row.contact_solve &row.linear_solve &row.run_time &row
      .peak_memory;
  }

  namespace
  {
    /** What a run needs, besides the mesh and the vectors attached to it,
     * to continue after the cycle of a checkpoint. */
    template <int dim>
    struct State
    {
      double                                      run_time = 0.;
      std::vector<CycleStatistics<dim>>           statistics;
      std::vector<CycleTimings>                   timings;
      std::vector<std::pair<double, std::string>> written_cycles;
      /** The tables as they were after the cycle, rewritten on resume. */
      std::map<std::string, std::string> files;
      /** Simplex meshes (one process, global refinement): the mesh is
       * rebuilt and the vectors are stored here in dof order. */
      std::vector<double> solution, pressure;

      template <class Archive>
      void
      serialize(Archive &archive, const unsigned int)
      {
        archive &run_time &statistics &timings &written_cycles &files &solution
          &pressure;
      }
    };

    /** The tables restored on resume. */
    const std::vector<std::string> tables = {"solution.pvd",
                                             "statistics.csv",
                                             "timings.csv"};

    using VectorType = TrilinosWrappers::MPI::Vector;
  } // namespace

  template <int dim>
  unsigned int
  ContactProblem<dim>::start_output(const bool resume, double &run_time)
  {
    const std::string &directory = parameters.output.directory;
    checkpoint =
      std::make_unique<Checkpoint>(directory, parameter_text, mpi_communicator);
    const std::optional<unsigned int> resumed =
      resume ? checkpoint->find_latest() : std::nullopt;
    if (resume && !resumed)
      pcout << "No checkpoint in " << directory << ": starting at cycle 0"
            << std::endl;

    // Own the directory before writing to it: no cycles of an earlier run
    // are left beside this run's.
    State<dim> state;
    write_collectively(mpi_communicator, [&]() {
      if (Utilities::MPI::this_mpi_process(mpi_communicator) != 0)
        return;
      output_series::remove_stale_files(directory, resumed);
    });
    write_obstacle_and_parameters();
    if (!resumed)
      return 0;

    {
      std::istringstream              in(checkpoint->state());
      boost::archive::binary_iarchive archive(in);
      archive >> state;
    }
    cycle_statistics = state.statistics;
    cycle_timings    = state.timings;
    written_cycles   = state.written_cycles;
    run_time += state.run_time;
    write_collectively(mpi_communicator, [&]() {
      if (Utilities::MPI::this_mpi_process(mpi_communicator) != 0)
        return;
      for (const auto &[name, text] : state.files)
        write_atomically(directory + "/" + name,
                         [&](std::ostream &out) { out << text; });
    });

    const unsigned int cycle = *resumed;
    pcout << "Resuming after cycle " << cycle << " from "
          << checkpoint->state_file(cycle) << std::endl;
    if (cycle + 1 >= parameters.refinement.n_cycles)
      {
        pcout << "All " << parameters.refinement.n_cycles
              << " cycles were finished already" << std::endl;
        return cycle + 1;
      }

    TimerOutput::Scope t(timer, "Setup: resume");
    if (simplex)
      {
        // Simplex meshes refine globally: cycle k's mesh is the initial one
        // refined k times, with the same numbering.
        triangulation->refine_global(cycle);
        setup_system();
        if (state.solution.size() != dof_handler.n_dofs())
          throw InputError::at(checkpoint->state_file(cycle),
                               "the checkpoint does not fit the mesh");
        VectorType owned_solution(locally_owned_dofs, mpi_communicator);
        VectorType owned_pressure(locally_owned_dofs, mpi_communicator);
        for (const auto i : locally_owned_dofs)
          {
            owned_solution(i) = state.solution[i];
            owned_pressure(i) = state.pressure[i];
          }
        owned_solution.compress(VectorOperation::insert);
        owned_pressure.compress(VectorOperation::insert);
        solution = owned_solution;
        pressure = owned_pressure;
        estimate_error();
        return cycle + 1;
      }

    // The saved mesh is loaded into its coarse mesh.
    Triangulation<dim> coarse_mesh;
    parameters.geometry.create_coarse_mesh(coarse_mesh, mpi_communicator);
    auto loaded = std::make_unique<parallel::distributed::Triangulation<dim>>(
      mpi_communicator, triangulation->get_mesh_smoothing());
    loaded->copy_triangulation(coarse_mesh);
    loaded->load(checkpoint->mesh_file(cycle));
    dof_handler.reinit(*loaded);
    triangulation = std::move(loaded);
    setup_system();

    parallel::distributed::SolutionTransfer<dim, VectorType> transfer(
      dof_handler);
    VectorType owned_solution(locally_owned_dofs, mpi_communicator);
    VectorType owned_pressure(locally_owned_dofs, mpi_communicator);
    std::vector<VectorType *> vectors{&owned_solution, &owned_pressure};
    transfer.deserialize(vectors);
    solution = owned_solution;
    pressure = owned_pressure;

    // The error indicators, registered after the vectors as when saved.
    auto &distributed =
      dynamic_cast<parallel::distributed::Triangulation<dim> &>(*triangulation);
    estimated_error_per_cell.reinit(triangulation->n_active_cells());
    const unsigned int handle = distributed.register_data_attach(
      [](const auto &, const auto) { return std::vector<char>(); }, false);
    distributed.notify_ready_to_unpack(
      handle, [this](const auto &cell, const auto, const auto &data) {
        float value;
        std::memcpy(&value, &*data.begin(), sizeof(value));
        estimated_error_per_cell(cell->active_cell_index()) = value;
      });
    return cycle + 1;
  }

  template <int dim>
  void
  ContactProblem<dim>::save_checkpoint(const unsigned int cycle,
                                       const double       run_time)
  {
    // A mesh remeshed from a .geo is not the initial one refined: it
    // would have to be stored whole. Such runs write no checkpoint (and a
    // resume starts at cycle 0, saying so).
    if (!parameters.checkpoint.enabled ||
        (simplex && parameters.geometry.from_geometry_file()))
      return;
    TimerOutput::Scope t(timer, "Output: checkpoint");
    State<dim>         state;
    if (auto *distributed =
          dynamic_cast<parallel::distributed::Triangulation<dim> *>(
            triangulation.get()))
      {
        parallel::distributed::SolutionTransfer<dim, VectorType> transfer(
          dof_handler);
        transfer.prepare_for_serialization(
          std::vector<const VectorType *>{&solution, &pressure});
        distributed->register_data_attach(
          [this](const auto &cell, const auto) {
            const float value =
              estimated_error_per_cell(cell->active_cell_index());
            std::vector<char> data(sizeof(value));
            std::memcpy(data.data(), &value, sizeof(value));
            return data;
          },
          false);
        write_collectively(mpi_communicator, [&]() {
          distributed->save(checkpoint->mesh_file(cycle));
        });
      }
    else
      for (const auto i : locally_owned_dofs)
        {
          state.solution.push_back(solution(i));
          state.pressure.push_back(pressure(i));
        }

    state.run_time       = run_time;
    state.statistics     = cycle_statistics;
    state.timings        = cycle_timings;
    state.written_cycles = written_cycles;
    std::ostringstream out;
    if (Utilities::MPI::this_mpi_process(mpi_communicator) == 0)
      {
        // The records as output_results() writes them (perhaps still in
        // the background), the other tables as they are on disk.
        const auto records = series_records();
        for (const auto &name : tables)
          if (const auto record = records.find(name); record != records.end())
            state.files[name] = record->second;
          else if (std::ifstream in(parameters.output.directory + "/" + name,
                                    std::ios::binary);
                   in)
            state.files[name] =
              std::string(std::istreambuf_iterator<char>(in), {});
        boost::archive::binary_oarchive archive(out);
        archive << state;
      }
    if (Utilities::MPI::n_mpi_processes(mpi_communicator) == 1)
      // After the cycle's files, which the background writer writes.
      background_writer.add([this, cycle, text = out.str()]() {
        checkpoint->write_state_file(cycle, text);
      });
    else
      checkpoint->write_state(cycle, out.str());
  }

  template unsigned int
  ContactProblem<2>::start_output(bool, double &);
  template unsigned int
  ContactProblem<3>::start_output(bool, double &);
  template void
  ContactProblem<2>::save_checkpoint(unsigned int, double);
  template void
  ContactProblem<3>::save_checkpoint(unsigned int, double);
} // namespace signorini
