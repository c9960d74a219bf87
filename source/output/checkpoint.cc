#include <deal.II/base/mpi.h>
#include <deal.II/base/utilities.h>

#include <signorini/input/entry_text.h>
#include <signorini/input/input_error.h>
#include <signorini/output/atomic_file.h>
#include <signorini/output/checkpoint.h>
#include <signorini/output/checkpoint_manifest.h>
#include <signorini/output/output_series.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iostream>
#include <iterator>
#include <limits>
#include <map>
#include <set>
#include <sstream>
#include <sys/resource.h>
#include <sys/statvfs.h>
#include <tuple>
#include <unistd.h>
#include <vector>

namespace signorini
{
  using namespace dealii;

  void
  CheckpointParameters::declare_parameters(ParameterHandler &prm)
  {
    const CheckpointParameters defaults;
    prm.enter_subsection("Output");
    prm.declare_entry(
      "Checkpoint",
      entry_text::of(defaults.enabled),
      Patterns::Bool(),
      "After every cycle, and after every load step of a load history, write "
      "a checkpoint (checkpoint-CC.*, of a step checkpoint-CC-SSS.*, in the "
      "output directory: the mesh, the displacement, the contact pressure, "
      "the error indicators and the results so far; only the newest is "
      "kept), from which `signorini --resume FILE.prm` continues an "
      "interrupted run.");
    prm.leave_subsection();
  }

  void
  CheckpointParameters::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Output");
    enabled = prm.get_bool("Checkpoint");
    prm.leave_subsection();
  }

  namespace
  {
    /** "Subsection/Entry" -> value of a parameter text in ShortPRM form. */
    std::vector<std::pair<std::string, std::string>>
    entries(const std::string &text)
    {
      std::vector<std::pair<std::string, std::string>> result;
      std::vector<std::string>                         path;
      std::istringstream                               in(text);
      std::string                                      line;
      while (std::getline(in, line))
        {
          line = Utilities::trim(line);
          if (line.rfind("subsection ", 0) == 0)
            path.push_back(Utilities::trim(line.substr(11)));
          else if (line == "end" && !path.empty())
            path.pop_back();
          else if (line.rfind("set ", 0) == 0 &&
                   line.find('=') != std::string::npos)
            {
              std::string name;
              for (const auto &section : path)
                name += section + "/";
              const auto equal = line.find('=');
              name += Utilities::trim(line.substr(4, equal - 4));
              result.emplace_back(name,
                                  Utilities::trim(line.substr(equal + 1)));
            }
        }
      return result;
    }

    /** Entries a resumed run may change: they choose how the same
     * equations are solved, not which (a checkpoint written with one
     * elastic operator resumes with the other). */
    bool
    free_on_resume(const std::string &name)
    {
      return name == "Linear solver/Type";
    }

    /** What differs between the parameter texts @p saved and @p current,
     * one entry, apart from the entries free on resume; empty if nothing
     * does. */
    std::string
    first_difference(const std::string &saved, const std::string &current)
    {
      const auto                         here = entries(current);
      std::map<std::string, std::string> there;
      for (const auto &[name, value] : entries(saved))
        there[name] = value;
      if (there.size() != here.size())
        return "the number of entries differs";
      for (const auto &[name, value] : here)
        {
          if (free_on_resume(name))
            continue;
          const auto found = there.find(name);
          if (found == there.end())
            return "entry '" + name + "' is not in it";
          if (found->second != value)
            return "entry '" + name + "' is '" + found->second +
                   "' there and '" + value + "' here";
        }
      return "";
    }

    /** The outcome of looking for a checkpoint, sent from process 0. */
    struct Found
    {
      std::string  error;
      bool         exists = false;
      unsigned int cycle  = 0;
      /** The step of a checkpoint within its cycle, 0 for none. */
      unsigned int step = 0;
      std::string  state;

      template <class Archive>
      void
      serialize(Archive &archive, const unsigned int)
      {
        archive &error &exists &cycle &step &state;
      }
    };

    /** The checkpoint whose file is classified as @p member. */
    CheckpointPoint
    point_of(const output_series::Member &member)
    {
      return {*member.cycle, member.step};
    }

    /** Whether the file system of @p directory has no space left for this
     * process (root may use the blocks reserved for it). */
    bool
    file_system_full(const std::string &directory)
    {
      struct statvfs status;
      if (::statvfs(directory.c_str(), &status) != 0)
        return false;
      return (::geteuid() == 0 ? status.f_bfree : status.f_bavail) == 0;
    }

    /** The size of the file @p path, 0 if it cannot be read. */
    std::uint64_t
    size_of(const std::string &path)
    {
      std::error_code error;
      const auto      size = std::filesystem::file_size(path, error);
      return error ? 0 : size;
    }
  } // namespace

  bool
  CheckpointPoint::operator<(const CheckpointPoint &other) const
  {
    // After the steps of a cycle comes the cycle (its last step).
    const auto order = [](const CheckpointPoint &point) {
      return std::make_pair(point.cycle,
                            point.step ? *point.step :
                                         std::numeric_limits<unsigned>::max());
    };
    return order(*this) < order(other);
  }

  bool
  CheckpointPoint::operator==(const CheckpointPoint &other) const
  {
    return cycle == other.cycle && step == other.step;
  }

  std::string
  CheckpointPoint::suffix() const
  {
    return Utilities::int_to_string(cycle, 2) +
           (step ? "-" + Utilities::int_to_string(*step, 3) : "");
  }

  std::ostream &
  operator<<(std::ostream &out, const CheckpointPoint &point)
  {
    if (point.step)
      out << "step " << *point.step << " of ";
    return out << "cycle " << point.cycle;
  }

  Checkpoint::Checkpoint(const std::string &directory,
                         const std::string &parameter_text,
                         const MPI_Comm     mpi_communicator)
    : directory(directory)
    , parameter_text(parameter_text)
    , mpi_communicator(mpi_communicator)
  {
  }

  std::string
  Checkpoint::mesh_file(const CheckpointPoint &point) const
  {
    return directory + "/checkpoint-" + point.suffix() + ".mesh";
  }

  std::string
  Checkpoint::state_file(const CheckpointPoint &point) const
  {
    return directory + "/checkpoint-" + point.suffix() + ".state";
  }

  std::vector<std::string>
  Checkpoint::mesh_pieces(const CheckpointPoint &point) const
  {
    namespace fs = std::filesystem;
    std::vector<std::string> names;
    std::error_code          error;
    for (const auto &entry : fs::directory_iterator(directory, error))
      {
        const std::string name   = entry.path().filename().string();
        const auto        member = output_series::classify(name);
        if (member.checkpoint && !member.partial && point_of(member) == point &&
            entry.path().extension() != ".state")
          names.push_back(name);
      }
    std::sort(names.begin(), names.end());
    return names;
  }

  std::optional<CheckpointPoint>
  Checkpoint::find_latest()
  {
    Found found;
    if (Utilities::MPI::this_mpi_process(mpi_communicator) == 0)
      {
        namespace fs = std::filesystem;
        // The points of every checkpoint piece, newest first.
        std::set<CheckpointPoint> points;
        std::error_code           error;
        if (fs::is_directory(directory, error))
          for (const auto &entry : fs::directory_iterator(directory, error))
            {
              const auto member =
                output_series::classify(entry.path().filename().string());
              if (member.checkpoint && !member.partial)
                points.insert(point_of(member));
            }
        // A checkpoint without its state file is one whose writing was
        // stopped (its state is written last): it is passed over with a
        // note. One whose files are damaged is passed over with a warning,
        // or refused if no intact one is left.
        std::vector<std::string> faults;
        CheckpointManifest       manifest;
        CheckpointPoint          intact;
        for (auto point = points.rbegin(); point != points.rend(); ++point)
          {
            const std::string name = state_file(*point);
            std::ifstream     in(name, std::ios::binary);
            if (!in)
              {
                std::cout << "Checkpoint of " << *point << " incomplete (no "
                          << name
                          << "; the run stopped while writing it): passed over"
                          << std::endl;
                continue;
              }
            std::string fault = manifest.read(
              std::string(std::istreambuf_iterator<char>(in), {}));
            const CheckpointPoint held{manifest.cycle, manifest.step};
            if (!fault.empty())
              fault = name + ": " + fault;
            else if (!(held == *point))
              {
                std::ostringstream text;
                text << name << ": damaged (it holds the checkpoint of " << held
                     << ")";
                fault = text.str();
              }
            else
              fault = manifest.verify_pieces(directory);
            if (fault.empty())
              {
                found.exists = true;
                found.cycle  = point->cycle;
                found.step   = point->step ? *point->step : 0;
                intact       = *point;
                break;
              }
            faults.push_back(fault);
          }
        if (found.exists)
          {
            for (const auto &fault : faults)
              std::cerr << "signorini: warning: " << fault
                        << "; resuming from the checkpoint of " << intact
                        << " instead" << std::endl;
            const std::string difference =
              manifest.parameters == parameter_text ?
                "" :
                first_difference(manifest.parameters, parameter_text);
            if (!difference.empty())
              found.error = state_file(intact) +
                            ": written by a different parameter set (" +
                            difference +
                            "); run without --resume to start afresh";
            else
              found.state = std::move(manifest.state);
          }
        else if (!faults.empty())
          found.error = faults.front() +
                        "; no intact checkpoint to resume from (run without "
                        "--resume to start afresh)";
      }
    found = Utilities::MPI::broadcast(mpi_communicator, found, 0);
    if (!found.error.empty())
      {
        const auto colon = found.error.find(": ");
        throw InputError::at(found.error.substr(0, colon),
                             found.error.substr(colon + 2));
      }
    found_state = found.state;
    if (!found.exists)
      return {};
    return CheckpointPoint{found.cycle,
                           found.step > 0 ?
                             std::optional<unsigned int>(found.step) :
                             std::nullopt};
  }

  const std::string &
  Checkpoint::state() const
  {
    return found_state;
  }

  void
  Checkpoint::write_state(const CheckpointPoint &point,
                          const std::string     &state) const
  {
    // Each process reads a slice of every mesh piece for its checksum;
    // process 0 joins the slices' checksums.
    const unsigned int rank =
      Utilities::MPI::this_mpi_process(mpi_communicator);
    const unsigned int n_ranks =
      Utilities::MPI::n_mpi_processes(mpi_communicator);
    std::vector<std::pair<std::string, std::uint64_t>> pieces;
    if (rank == 0)
      for (const auto &name : mesh_pieces(point))
        pieces.emplace_back(name, size_of(directory + "/" + name));
    pieces = Utilities::MPI::broadcast(mpi_communicator, pieces, 0);
    std::vector<std::pair<std::uint32_t, std::uint64_t>> slices;
    std::string                                          error;
    try
      {
        for (const auto &[name, size] : pieces)
          {
            const std::uint64_t begin = size * rank / n_ranks,
                                end   = size * (rank + 1) / n_ranks;
            const auto slice =
              checksum_of_file(directory + "/" + name, begin, end - begin);
            slices.emplace_back(slice.crc, slice.size);
          }
      }
    catch (const std::exception &failure)
      {
        error = failure.what();
      }
    const auto all_slices =
      Utilities::MPI::gather(mpi_communicator,
                             std::make_pair(slices, error),
                             0);
    write_collectively(mpi_communicator, [&]() {
      if (rank != 0)
        return;
      std::vector<CheckpointManifest::Piece> checksums;
      for (unsigned int i = 0; i < pieces.size(); ++i)
        {
          FileChecksum checksum;
          for (const auto &[process_slices, process_error] : all_slices)
            {
              if (!process_error.empty())
                throw std::runtime_error(process_error);
              checksum = concatenate(checksum,
                                     {process_slices[i].second,
                                      process_slices[i].first});
            }
          checksums.push_back({pieces[i].first, checksum});
        }
      write_manifest(point, state, checksums);
    });
  }

  void
  Checkpoint::write_state_file(const CheckpointPoint &point,
                               const std::string     &state) const
  {
    std::vector<CheckpointManifest::Piece> pieces;
    for (const auto &name : mesh_pieces(point))
      pieces.push_back({name, checksum_of_file(directory + "/" + name)});
    write_manifest(point, state, pieces);
  }

  void
  Checkpoint::check_mesh_pieces(const CheckpointPoint &point,
                                const std::string     &save_failure) const
  {
    const auto  pieces = mesh_pieces(point);
    std::string fault;
    // A write that reached the file-size limit was cut there.
    struct rlimit limit;
    if (::getrlimit(RLIMIT_FSIZE, &limit) == 0 &&
        limit.rlim_cur != RLIM_INFINITY)
      for (const auto &name : pieces)
        if (fault.empty() && size_of(directory + "/" + name) >= limit.rlim_cur)
          fault = "cannot write '" + directory + "/" + name +
                  "': " + std::strerror(EFBIG);
    // One that found the file system full was cut short.
    if (fault.empty() && file_system_full(directory))
      fault =
        "cannot write '" + mesh_file(point) + "*': " + std::strerror(ENOSPC);
    // The pieces deal.II and p4est write; a directory in the place of one
    // failed its write and may have kept others from being written.
    std::vector<std::string> names;
    for (const std::string suffix :
         {".mesh", ".mesh.info", ".mesh_fixed.data", ".mesh_variable.data"})
      names.push_back("checkpoint-" + point.suffix() + suffix);
    for (const auto &name : names)
      {
        std::error_code error;
        if (fault.empty() &&
            std::filesystem::is_directory(directory + "/" + name, error))
          fault = "cannot write '" + directory + "/" + name +
                  "': " + std::strerror(EISDIR);
      }
    for (const auto &name : names)
      if (fault.empty() &&
          std::find(pieces.begin(), pieces.end(), name) == pieces.end())
        fault = "cannot write '" + directory + "/" + name + "'" +
                (save_failure.empty() ? "" : ": " + save_failure);
    if (fault.empty() && !save_failure.empty())
      fault = "cannot write '" + mesh_file(point) + "': " + save_failure;
    if (fault.empty())
      return;
    std::error_code error;
    for (const auto &name : pieces)
      std::filesystem::remove(directory + "/" + name, error);
    throw std::runtime_error(fault);
  }

  void
  Checkpoint::write_manifest(
    const CheckpointPoint                        &point,
    const std::string                            &state,
    const std::vector<CheckpointManifest::Piece> &pieces) const
  {
    CheckpointManifest manifest;
    manifest.cycle      = point.cycle;
    manifest.step       = point.step;
    manifest.parameters = parameter_text;
    manifest.state      = state;
    manifest.pieces     = pieces;
    write_atomically(state_file(point),
                     [&](std::ostream &out) { out << manifest.text(); });
    // The new checkpoint is complete: the older ones go.
    namespace fs = std::filesystem;
    std::error_code          error;
    std::vector<std::string> older;
    for (const auto &entry : fs::directory_iterator(directory, error))
      {
        const auto member =
          output_series::classify(entry.path().filename().string());
        // (A newer one may be being written: on one process this runs in
        // the background while the next load step's mesh is saved.)
        if (member.checkpoint && point_of(member) < point)
          older.push_back(entry.path().string());
      }
    for (const auto &name : older)
      fs::remove(name, error);
  }

  void
  Checkpoint::remove_incomplete() const
  {
    namespace fs = std::filesystem;
    std::error_code           error;
    std::set<CheckpointPoint> points;
    for (const auto &entry : fs::directory_iterator(directory, error))
      {
        const auto member =
          output_series::classify(entry.path().filename().string());
        if (member.checkpoint)
          points.insert(point_of(member));
      }
    for (const auto &point : points)
      if (!fs::exists(state_file(point), error))
        for (const auto &name : mesh_pieces(point))
          fs::remove(directory + "/" + name, error);
  }
} // namespace signorini
