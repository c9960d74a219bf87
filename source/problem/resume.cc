#include <deal.II/base/mpi.h>

#include <signorini/input/input_error.h>
#include <signorini/output/atomic_file.h>
#include <signorini/output/output_series.h>
#include <signorini/problem/contact_problem.h>

#include <boost/archive/binary_iarchive.hpp>
#include <boost/archive/binary_oarchive.hpp>
#include <boost/serialization/map.hpp>
#include <boost/serialization/string.hpp>
#include <boost/serialization/utility.hpp>
#include <boost/serialization/vector.hpp>
#include <boost/serialization/version.hpp>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

namespace signorini
{
  using namespace dealii;

  namespace
  {
    /** What a run needs, besides the mesh and the vectors attached to it,
     * to continue after the cycle or the load step of a checkpoint. */
    struct CheckpointState
    {
      double    run_time = 0.;
      RunRecord record;
      /** The tables as they were after the cycle, rewritten on resume. */
      std::map<std::string, std::string> files;
      /** Meshes that are not saved (simplex meshes refined globally): the
       * vectors in dof order; the shear tractions with friction (version
       * 1). */
      std::vector<double> solution, pressure, tangential;

      template <class Archive>
      void
      serialize(Archive &archive, const unsigned int version)
      {
        archive &run_time &record &files &solution &pressure;
        if (version > 0)
          archive &tangential;
      }
    };

    /** The tables restored on resume. */
    const std::vector<std::string> tables = {"solution.pvd",
                                             "statistics.csv",
                                             "timings.csv",
                                             "force_displacement.csv",
                                             "history.pvd"};
  } // namespace
} // namespace signorini

BOOST_CLASS_VERSION(signorini::CheckpointState, 1)

namespace signorini
{
  template <int dim>
  std::optional<CheckpointPoint>
  ContactProblem<dim>::start_output(const bool resume)
  {
    const std::string &directory = parameters.output.directory;
    // A directory that no run wrote to keeps its files: a user's own
    // statistics.csv or solution-01.vtu would be overwritten or removed.
    std::vector<std::string> foreign;
    if (Utilities::MPI::this_mpi_process(mpi_communicator) == 0)
      foreign = output_series::foreign_files(directory);
    foreign = Utilities::MPI::broadcast(mpi_communicator, foreign, 0);
    if (!foreign.empty())
      {
        std::string names;
        for (std::size_t i = 0; i < foreign.size() && i < 3; ++i)
          names += (i > 0 ? ", " : "") + foreign[i];
        if (foreign.size() > 3)
          names += " and " + std::to_string(foreign.size() - 3) + " more";
        throw InputError("Output/Directory",
                         "'" + directory +
                           "' holds files a run would "
                           "overwrite or remove (" +
                           names +
                           ") and no parameters.prm of an earlier run: "
                           "choose another directory, or move them away");
      }
    // The run owns the directory (and tidy_output() may remove what it
    // left unfinished) once the checkpoint to resume from is found: a
    // refused resume leaves the directory as it was.
    auto found = std::make_unique<Checkpoint>(directory,
                                              parameters.text,
                                              mpi_communicator);
    const std::optional<CheckpointPoint> resumed =
      resume ? found->find_latest() : std::nullopt;
    checkpoint = std::move(found);
    if (resume && !resumed)
      pcout << "No checkpoint in " << directory << ": starting at cycle 0"
            << std::endl;

    // Own the directory before writing to it: no cycles of an earlier run
    // are left beside this run's.
    write_collectively(mpi_communicator, [&]() {
      if (Utilities::MPI::this_mpi_process(mpi_communicator) != 0)
        return;
      // The files of the load steps are the final cycle's.
      output_series::remove_stale_files(
        directory,
        resumed ? std::optional<unsigned int>(resumed->cycle) : std::nullopt,
        parameters.refinement.n_cycles - 1,
        resumed ? resumed->step : std::nullopt);
    });
    write_obstacle_and_parameters();
    return resumed;
  }

  template <int dim>
  void
  ContactProblem<dim>::restore_checkpoint(const CheckpointPoint &point,
                                          double                &run_time)
  {
    const std::string &directory = parameters.output.directory;
    CheckpointState    state;
    try
      {
        std::istringstream              in(checkpoint->state());
        boost::archive::binary_iarchive archive(in);
        archive >> state;
      }
    catch (const std::exception &error)
      {
        throw InputError::at(checkpoint->state_file(point),
                             std::string("cannot be read: ") + error.what());
      }
    record = state.record;
    run_time += state.run_time;
    write_collectively(mpi_communicator, [&]() {
      if (Utilities::MPI::this_mpi_process(mpi_communicator) != 0)
        return;
      for (const auto &[name, text] : state.files)
        write_atomically(directory + "/" + name,
                         [&](std::ostream &out) { out << text; });
    });

    pcout << "Resuming after " << (point.step ? "load step " : "")
          << (point.step ? std::to_string(*point.step) + " of " : "")
          << "cycle " << point.cycle << " from "
          << checkpoint->state_file(point) << std::endl;
    if (!point.step && point.cycle + 1 >= parameters.refinement.n_cycles)
      {
        pcout << "All " << parameters.refinement.n_cycles
              << " cycles were finished already" << std::endl;
        return;
      }

    TimerOutput::Scope t(timer, "Setup: resume");
    const auto        &owned_dofs = discretisation.locally_owned_dofs();
    VectorType         owned_solution, owned_pressure, owned_tangential;
    // With friction, the shear tractions too: the next step's active set
    // and multipliers start from them, or the next cycle's, which carries
    // them to its mesh.
    const bool                shear   = law->path_dependent();
    std::vector<VectorType *> vectors = {&owned_solution, &owned_pressure};
    if (shear)
      vectors.push_back(&owned_tangential);
    if (discretisation.saves_mesh())
      try
        {
          discretisation.load(checkpoint->mesh_file(point),
                              vectors,
                              estimated_error_per_cell);
        }
      catch (const ExceptionBase &error)
        {
          throw InputError::at(checkpoint->mesh_file(point),
                               "cannot be loaded: " + one_line(error));
        }
    else
      {
        // Cycle k's mesh is the initial one refined k times, with the same
        // numbering.
        discretisation.refine_globally(point.cycle);
        const std::vector<const std::vector<double> *> values = {
          &state.solution, &state.pressure, &state.tangential};
        for (unsigned int v = 0; v < vectors.size(); ++v)
          {
            if (values[v]->size() != discretisation.dof_handler().n_dofs())
              throw InputError::at(checkpoint->state_file(point),
                                   "the checkpoint does not fit the mesh");
            vectors[v]->reinit(owned_dofs, mpi_communicator);
            for (const auto i : owned_dofs)
              (*vectors[v])(i) = (*values[v])[i];
            vectors[v]->compress(VectorOperation::insert);
          }
      }
    setup_system();
    solution = owned_solution;
    pressure = owned_pressure;
    if (shear)
      newton.restore_tangential_traction(owned_tangential);
    if (!discretisation.saves_mesh() && !point.step)
      estimate_error();
  }

  template <int dim>
  bool
  ContactProblem<dim>::writes_checkpoints() const
  {
    // A mesh remeshed from a .geo is not the initial one refined: it
    // would have to be stored whole. Such runs write no checkpoint (and a
    // resume starts at cycle 0, saying so).
    return parameters.checkpoint.enabled &&
           !(discretisation.simplex() &&
             parameters.geometry.from_geometry_file());
  }

  template <int dim>
  void
  ContactProblem<dim>::save_checkpoint(const CheckpointPoint &point,
                                       const double           run_time)
  {
    if (!writes_checkpoints())
      return;
    TimerOutput::Scope t(timer, "Output: checkpoint");
    CheckpointState    state;
    // With friction, the shear tractions from which the next step or the
    // next cycle starts (restore_checkpoint()).
    std::vector<const VectorType *> vectors = {&solution, &pressure};
    if (law->path_dependent())
      vectors.push_back(&newton.tangential_traction());
    if (discretisation.saves_mesh())
      {
        std::string failure;
        try
          {
            discretisation.save(checkpoint->mesh_file(point),
                                vectors,
                                estimated_error_per_cell);
          }
        catch (const ExceptionBase &error)
          {
            failure = one_line(error);
          }
        catch (const std::exception &error)
          {
            failure = error.what();
          }
        // Every process's part of the files is written before process 0
        // checks them.
        MPI_Barrier(mpi_communicator);
        write_collectively(mpi_communicator, [&]() {
          if (Utilities::MPI::this_mpi_process(mpi_communicator) == 0)
            checkpoint->check_mesh_pieces(point, failure);
          else if (!failure.empty())
            throw std::runtime_error("cannot write '" +
                                     checkpoint->mesh_file(point) +
                                     "': " + failure);
        });
      }
    else
      {
        const std::vector<std::vector<double> *> values = {&state.solution,
                                                           &state.pressure,
                                                           &state.tangential};
        for (unsigned int v = 0; v < vectors.size(); ++v)
          for (const auto i : discretisation.locally_owned_dofs())
            values[v]->push_back((*vectors[v])(i));
      }

    state.run_time = run_time;
    state.record   = record;
    std::ostringstream out;
    if (Utilities::MPI::this_mpi_process(mpi_communicator) == 0)
      {
        // The records as output_results() writes them (perhaps still in
        // the background), the other tables as they are on disk.
        const auto records = record.series_records();
        for (const auto &name : tables)
          if (const auto found = records.find(name); found != records.end())
            state.files[name] = found->second;
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
      background_writer.add([this, point, text = out.str()]() {
        checkpoint->write_state_file(point, text);
      });
    else
      checkpoint->write_state(point, out.str());
  }

  template <int dim>
  void
  ContactProblem<dim>::tidy_output() const
  {
    if (!checkpoint || Utilities::MPI::this_mpi_process(mpi_communicator) != 0)
      return;
    // Temporaries of writes that did not finish, and the pieces of a
    // checkpoint whose state file was not written.
    namespace fs = std::filesystem;
    std::error_code error;
    const auto     &directory = parameters.output.directory;
    if (!fs::is_directory(directory, error))
      return;
    std::vector<fs::path> partial;
    for (const auto &entry : fs::directory_iterator(directory, error))
      if (const auto member =
            output_series::classify(entry.path().filename().string());
          member.owned && member.partial)
        partial.push_back(entry.path());
    for (const auto &path : partial)
      fs::remove(path, error);
    checkpoint->remove_incomplete();
  }

  template std::optional<CheckpointPoint>
  ContactProblem<2>::start_output(bool);
  template std::optional<CheckpointPoint>
  ContactProblem<3>::start_output(bool);
  template void
  ContactProblem<2>::restore_checkpoint(const CheckpointPoint &, double &);
  template void
  ContactProblem<3>::restore_checkpoint(const CheckpointPoint &, double &);
  template bool
  ContactProblem<2>::writes_checkpoints() const;
  template bool
  ContactProblem<3>::writes_checkpoints() const;
  template void
  ContactProblem<2>::save_checkpoint(const CheckpointPoint &, double);
  template void
  ContactProblem<3>::save_checkpoint(const CheckpointPoint &, double);
  template void
  ContactProblem<2>::tidy_output() const;
  template void
  ContactProblem<3>::tidy_output() const;
} // namespace signorini
