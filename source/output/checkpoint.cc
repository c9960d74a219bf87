#include <deal.II/base/mpi.h>
#include <deal.II/base/utilities.h>

#include <signorini/input/entry_text.h>
#include <signorini/input/input_error.h>
#include <signorini/output/checkpoint.h>
#include <signorini/output/file_output.h>
#include <signorini/output/output_series.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <sstream>
#include <tuple>
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
      "After every cycle, write a checkpoint (checkpoint-CC.* in the output "
      "directory: the mesh, the displacement, the contact pressure, the error "
      "indicators and the results so far; only the newest is kept), from "
      "which `signorini --resume FILE.prm` continues an interrupted run.");
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
    const std::string magic = "signorini checkpoint 1";

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

    /** What differs between the parameter texts @p saved and @p current,
     * one entry. */
    std::string
    first_difference(const std::string &saved, const std::string &current)
    {
      const auto                         here = entries(current);
      std::map<std::string, std::string> there;
      for (const auto &[name, value] : entries(saved))
        there[name] = value;
      for (const auto &[name, value] : here)
        {
          const auto found = there.find(name);
          if (found == there.end())
            return "entry '" + name + "' is not in it";
          if (found->second != value)
            return "entry '" + name + "' is '" + found->second +
                   "' there and '" + value + "' here";
        }
      return "its entries differ";
    }

    /** The outcome of looking for a checkpoint, sent from process 0. */
    struct Found
    {
      std::string  error;
      bool         exists = false;
      unsigned int cycle  = 0;
      std::string  state;

      template <class Archive>
      void
      serialize(Archive &archive, const unsigned int)
      {
        archive &error &exists &cycle &state;
      }
    };

    /** Reads a "KEY SIZE\n" header and SIZE bytes after it. */
    bool
    read_block(std::istream &in, const std::string &key, std::string &bytes)
    {
      std::string word;
      std::size_t size = 0;
      if (!(in >> word >> size) || word != key || in.get() != '\n')
        return false;
      bytes.resize(size);
      return size == 0 || static_cast<bool>(in.read(&bytes[0], size));
    }
  } // namespace

  Checkpoint::Checkpoint(const std::string &directory,
                         const std::string &parameter_text,
                         const MPI_Comm     mpi_communicator)
    : directory(directory)
    , parameter_text(parameter_text)
    , mpi_communicator(mpi_communicator)
  {
  }

  std::string
  Checkpoint::mesh_file(const unsigned int cycle) const
  {
    return directory + "/checkpoint-" + Utilities::int_to_string(cycle, 2) +
           ".mesh";
  }

  std::string
  Checkpoint::state_file(const unsigned int cycle) const
  {
    return directory + "/checkpoint-" + Utilities::int_to_string(cycle, 2) +
           ".state";
  }

  std::optional<unsigned int>
  Checkpoint::find_latest()
  {
    Found found;
    if (Utilities::MPI::this_mpi_process(mpi_communicator) == 0)
      {
        namespace fs = std::filesystem;
        std::error_code error;
        if (fs::is_directory(directory, error))
          for (const auto &entry : fs::directory_iterator(directory, error))
            {
              const auto member =
                output_series::classify(entry.path().filename().string());
              if (member.checkpoint && !member.partial &&
                  entry.path().extension() == ".state" &&
                  (!found.exists || *member.cycle > found.cycle))
                {
                  found.exists = true;
                  found.cycle  = *member.cycle;
                }
            }
        if (found.exists)
          {
            const std::string name = state_file(found.cycle);
            std::ifstream     in(name, std::ios::binary);
            std::string       header, saved_parameters;
            unsigned int      cycle = 0;
            std::string       cycle_word;
            if (!std::getline(in, header) || header != magic ||
                !(in >> cycle_word >> cycle) || cycle_word != "cycle" ||
                cycle != found.cycle ||
                !read_block(in, "parameters", saved_parameters) ||
                !read_block(in, "state", found.state))
              found.error = name + ": not a signorini checkpoint, or damaged";
            else if (saved_parameters != parameter_text)
              found.error = name + ": written by a different parameter set (" +
                            first_difference(saved_parameters, parameter_text) +
                            "); run without --resume to start afresh";
          }
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
    return found.cycle;
  }

  const std::string &
  Checkpoint::state() const
  {
    return found_state;
  }

  void
  Checkpoint::write_state(const unsigned int cycle,
                          const std::string &state) const
  {
    write_collectively(mpi_communicator, [&]() {
      if (Utilities::MPI::this_mpi_process(mpi_communicator) == 0)
        write_state_file(cycle, state);
    });
  }

  void
  Checkpoint::write_state_file(const unsigned int cycle,
                               const std::string &state) const
  {
    write_atomically(state_file(cycle), [&](std::ostream &out) {
      out << magic << '\n'
          << "cycle " << cycle << '\n'
          << "parameters " << parameter_text.size() << '\n'
          << parameter_text << "state " << state.size() << '\n'
          << state;
    });
    // The new checkpoint is complete: the older ones go.
    namespace fs = std::filesystem;
    std::error_code          error;
    std::vector<std::string> older;
    for (const auto &entry : fs::directory_iterator(directory, error))
      {
        const auto member =
          output_series::classify(entry.path().filename().string());
        if (member.checkpoint && *member.cycle != cycle)
          older.push_back(entry.path().string());
      }
    for (const auto &name : older)
      fs::remove(name, error);
  }
} // namespace signorini
