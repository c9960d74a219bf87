#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>

#include <signorini/base/failures.h>
#include <signorini/base/interruption.h>
#include <signorini/base/memory.h>
#include <signorini/input/input_error.h>
#include <signorini/input/parameter_file.h>
#include <signorini/input/text_check.h>
#include <signorini/problem/contact_problem.h>
#include <signorini/problem/parameters.h>
#include <signorini/program.h>

#include <cerrno>
#include <cstring>
#include <exception>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <new>
#include <stdexcept>
#include <string>
#include <vector>

namespace signorini
{
  using namespace dealii;

  namespace
  {
    const char *usage =
      "Usage: signorini FILE.prm          run the scene described in FILE.prm\n"
      "       signorini --resume FILE.prm continue after the newest checkpoint\n"
      "                                    in the output directory (from cycle\n"
      "                                    0 if there is none)\n"
      "       signorini --print-parameters [2|3]\n"
      "                                    print every parameter with its\n"
      "                                    default in 2D (or 3D) and its\n"
      "                                    documentation\n"
      "       signorini --help            show this text\n"
      "Run in parallel with: mpirun -np N signorini FILE.prm\n"
      "Exit status: 0 success, 1 bad input or command line, 2 contact solver\n"
      "did not converge, 3 active set cycling, 4 linear solver failed, 5 other\n"
      "error (out of memory, a file that cannot be written), 6 contact solver\n"
      "stalled, 7 augmented Lagrangian multipliers too slow, 130 interrupted\n"
      "by SIGINT and 143 by SIGTERM (after the last finished cycle, which\n"
      "--resume continues from).\n";

    /** What the command line asks for. */
    struct Command
    {
      enum class Action
      {
        run,
        print_parameters,
        help
      };
      Action      action = Action::run;
      bool        resume = false;
      std::string file;
      std::string dimension = "2";
    };

    /** A mistake on the command line, reported with the usage. */
    class UsageError : public std::runtime_error
    {
    public:
      using std::runtime_error::runtime_error;
    };

    /** The options of mpirun that a user may give signorini instead. */
    bool
    is_mpirun_option(const std::string &argument)
    {
      for (const char *option : {"-np",
                                 "-n",
                                 "--np",
                                 "--n",
                                 "-c",
                                 "-N",
                                 "-H",
                                 "--host",
                                 "--hostfile",
                                 "--oversubscribe",
                                 "--map-by",
                                 "--bind-to"})
        if (argument == option)
          return true;
      return false;
    }

    /** The command of @p arguments; throws a UsageError. */
    Command
    parse_command_line(const std::vector<std::string> &arguments)
    {
      Command command;
      for (const auto &argument : arguments)
        if (argument == "--help" || argument == "-h")
          {
            command.action = Command::Action::help;
            return command;
          }
      for (std::size_t i = 0; i < arguments.size(); ++i)
        {
          const std::string &argument = arguments[i];
          if (argument == "--resume")
            {
              if (command.resume)
                throw UsageError("--resume is given twice");
              if (!command.file.empty())
                throw UsageError("--resume comes before the parameter file: "
                                 "signorini --resume " +
                                 command.file);
              command.resume = true;
            }
          else if (argument == "--print-parameters")
            {
              command.action = Command::Action::print_parameters;
              if (i + 1 < arguments.size() && !arguments[i + 1].empty() &&
                  arguments[i + 1][0] != '-')
                {
                  const std::string &next = arguments[++i];
                  if (next != "2" && next != "3")
                    throw UsageError(
                      "--print-parameters takes a dimension, 2 or 3, not '" +
                      next + "'" +
                      (std::filesystem::exists(next) ?
                         " (it prints the defaults, not a file's entries)" :
                         ""));
                  command.dimension = next;
                }
            }
          else if (is_mpirun_option(argument))
            throw UsageError("'" + argument +
                             "' is an option of mpirun, not of signorini: "
                             "mpirun -np N signorini FILE.prm");
          else if (argument.size() > 1 && argument[0] == '-')
            throw UsageError("unknown option '" + argument + "'");
          else if (argument.empty())
            throw UsageError("an empty argument where a parameter file is "
                             "expected");
          else if (!command.file.empty())
            throw UsageError("expected one parameter file, got '" +
                             command.file + "' and '" + argument + "'");
          else
            command.file = argument;
        }
      if (command.action == Command::Action::print_parameters &&
          (!command.file.empty() || command.resume))
        throw UsageError(
          "--print-parameters prints the defaults and takes no " +
          std::string(command.resume ?
                        "--resume" :
                        "parameter file ('" + command.file + "')"));
      if (command.action == Command::Action::run && command.file.empty())
        throw UsageError(command.resume ? "--resume needs a parameter file" :
                                          "expected a parameter file");
      return command;
    }

    /** The number of cycles that statistics.csv in @p directory lists. */
    unsigned int
    listed_cycles(const std::string &directory)
    {
      std::ifstream in(directory + "/statistics.csv");
      std::string   line;
      unsigned int  n = 0;
      while (std::getline(in, line))
        ++n;
      return n > 0 ? n - 1 : 0;
    }

    template <int dim>
    void
    run_scene(const ParameterFile &input,
              const std::string   &file,
              const bool           resume)
    {
      ParameterHandler prm;
      declare_parameters(prm, dim);
      input.parse(prm);
      Parameters<dim> parameters;
      try
        {
          parameters.parse_parameters(prm, input.folders());
        }
      catch (const InputError &error)
        {
          // An entry that an included file set: say where, and how the
          // including file sets it back (to change a Type, say).
          const auto where = error.entry.empty() ?
                               std::nullopt :
                               input.included_setting(error.entry);
          if (!where || !error.location.empty())
            throw;
          std::string reset;
          try
            {
              ParameterHandler defaults;
              declare_parameters(defaults, dim);
              const auto path = parse::split(error.entry, '/');
              for (std::size_t i = 0; i + 1 < path.size(); ++i)
                defaults.enter_subsection(path[i]);
              reset = "; after the include, `set " + path.back() + " = " +
                      defaults.get(path.back()) + "` sets it back";
            }
          catch (...)
            {
              // Not an entry of its own (a combination of entries).
            }
          throw InputError(error.entry,
                           std::string(error.what()) + " (set at " + *where +
                             reset + ")");
        }
      ConditionalOStream err(std::cerr,
                             Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) ==
                               0);
      for (const auto &warning : take_warnings())
        err << text_check::printable("signorini: warning: " + file +
                                     ": entry '" + warning.entry +
                                     "': " + warning.message)
            << std::endl;
      // The problem is destroyed before a failure propagates, so that its
      // timer does not finish while an exception is in flight.
      std::exception_ptr failure;
      reserve_blas_workspace();
      {
        ContactProblem<dim> problem(parameters, MPI_COMM_WORLD);
        try
          {
            problem.run(resume);
          }
        catch (...)
          {
            failure = std::current_exception();
          }
      }
      if (failure)
        try
          {
            std::rethrow_exception(failure);
          }
        catch (const std::bad_alloc &lack)
          {
            // What ran out, where a library said (MUMPS).
            const auto        *known = dynamic_cast<const OutOfMemory *>(&lack);
            const std::string &directory = parameters.output.directory;
            const std::string  message =
              "out of memory on cycle " +
              std::to_string(listed_cycles(directory)) +
              (known ? std::string(": ") + known->what() : "") +
              " (the cycles before it are in " + directory +
              (known ? "; Linear solver/Type = amg cg needs far less" : "") +
              "; fewer Mesh refinement/Number of cycles or a smaller Mesh "
              "refinement/Refine fraction need less)";
            // An allocation that failed may have failed on this process
            // alone (MUMPS' report is global): the others would wait for it
            // at their next collective step for ever. This one says so and
            // stops them all.
            if (!known && Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD) > 1)
              {
                std::cerr << "signorini: error: " +
                               text_check::printable(message)
                          << std::endl;
                MPI_Abort(MPI_COMM_WORLD, exit_status::other);
              }
            throw SolverFailure(exit_status::other, message);
          }
    }

    /** "signorini: error: WHAT", fit for a terminal. */
    std::string
    error_line(const std::string &what, const std::string &where = "")
    {
      // Only the message is shortened, so that how much of it is shown does
      // not depend on the length of the file's path.
      return "signorini: error: " + text_check::printable(where) +
             text_check::printable(what);
    }
  } // namespace

  int
  run_program(int argc, char **argv)
  {
    const bool first = Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0;
    ConditionalOStream             out(std::cout, first);
    ConditionalOStream             err(std::cerr, first);
    const std::vector<std::string> arguments(argv + 1, argv + argc);
    Command                        command;
    try
      {
        command = parse_command_line(arguments);
      }
    catch (const UsageError &error)
      {
        err << error_line(error.what()) << '\n' << usage;
        return exit_status::input_error;
      }
    if (command.action == Command::Action::help)
      {
        out << usage;
        return exit_status::success;
      }
    if (command.action == Command::Action::print_parameters)
      {
        ParameterHandler prm;
        declare_parameters(prm, std::stoi(command.dimension));
        prm.set("Dimension", command.dimension);
        if (first)
          prm.print_parameters(std::cout, ParameterHandler::PRM);
        return exit_status::success;
      }

    const std::string &file = command.file;
    try
      {
        std::error_code error;
        const auto      status = std::filesystem::status(file, error);
        if (error)
          throw InputError::at(file,
                               "cannot open the parameter file: " +
                                 error.message());
        if (std::filesystem::is_directory(status))
          throw InputError::at(file, "is a directory, not a parameter file");
        if (!std::filesystem::is_regular_file(status))
          throw InputError::at(file, "is not a regular file");
        if (!std::ifstream(file))
          throw InputError::at(file,
                               std::string("cannot open the parameter file: ") +
                                 std::strerror(errno));
        const ParameterFile input(file);
        if (read_dimension(input) == 2)
          run_scene<2>(input, file, command.resume);
        else
          run_scene<3>(input, file, command.resume);
        return exit_status::success;
      }
    catch (const InputError &error)
      {
        err << error_line(error.what(),
                          (error.location.empty() ? file : error.location) +
                            (error.entry.empty() ?
                               std::string() :
                               ": entry '" + error.entry + "'") +
                            ": ")
            << std::endl;
        return exit_status::input_error;
      }
    catch (const Interrupted &stop)
      {
        err << "signorini: " << stop.message(file) << std::endl;
        return stop.status();
      }
    catch (const SolverFailure &failure)
      {
        err << error_line(failure.what()) << std::endl;
        return failure.status;
      }
    catch (const ExceptionBase &error)
      {
        err << error_line(one_line(error)) << std::endl;
      }
    catch (const std::bad_alloc &lack)
      {
        const auto *known = dynamic_cast<const OutOfMemory *>(&lack);
        err << error_line(std::string("out of memory before cycle 0") +
                          (known ? std::string(": ") + known->what() : ""))
            << std::endl;
      }
    catch (const std::exception &error)
      {
        err << error_line(error.what()) << std::endl;
      }
    catch (...)
      {
        err << error_line("unknown failure") << std::endl;
      }
    return exit_status::other;
  }
} // namespace signorini
