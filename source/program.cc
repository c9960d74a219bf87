#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>

#include <signorini/base/failures.h>
#include <signorini/base/interruption.h>
#include <signorini/input/input_error.h>
#include <signorini/input/parameter_file.h>
#include <signorini/input/parameters.h>
#include <signorini/problem/contact_problem.h>
#include <signorini/program.h>

#include <exception>
#include <filesystem>
#include <fstream>
#include <iostream>

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
      "Exit status: 0 success, 1 bad input, 2 contact solver did not converge,\n"
      "3 active set cycling, 4 linear solver failed, 5 other error,\n"
      "6 contact solver stalled, 7 augmented Lagrangian multipliers too slow.\n";

    template <int dim>
    void
    run_scene(const ParameterFile &input, const bool resume)
    {
      ParameterHandler prm;
      declare_parameters(prm, dim);
      input.parse(prm);
      Parameters<dim> parameters;
      parameters.parse_parameters(prm, input.folders());
      // The problem is destroyed before a failure propagates, so that its
      // timer does not finish while an exception is in flight.
      std::exception_ptr failure;
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
        std::rethrow_exception(failure);
    }
  } // namespace

  int
  run_program(int argc, char **argv)
  {
    ConditionalOStream             out(std::cout,
                           Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) ==
                             0);
    ConditionalOStream             err(std::cerr,
                           Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) ==
                             0);
    const std::vector<std::string> arguments(argv + 1, argv + argc);
    if (arguments.size() == 1 &&
        (arguments[0] == "--help" || arguments[0] == "-h"))
      {
        out << usage;
        return exit_status::success;
      }

    if (!arguments.empty() && arguments[0] == "--print-parameters")
      {
        const std::string dim = arguments.size() == 2 ? arguments[1] : "2";
        if (arguments.size() > 2 || (dim != "2" && dim != "3"))
          {
            err << "signorini: error: --print-parameters takes a dimension, "
                   "2 or 3\n"
                << usage;
            return exit_status::input_error;
          }
        ParameterHandler prm;
        declare_parameters(prm, std::stoi(dim));
        prm.set("Dimension", dim);
        if (Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
          prm.print_parameters(std::cout, ParameterHandler::PRM);
        return exit_status::success;
      }
    const bool resume = arguments.size() == 2 && arguments[0] == "--resume";
    const std::string file = arguments.empty() ? "" : arguments.back();
    if (arguments.size() != (resume ? 2 : 1) || file.empty() || file[0] == '-')
      {
        err << "signorini: error: expected one parameter file\n" << usage;
        return exit_status::input_error;
      }

    try
      {
        if (!std::filesystem::is_regular_file(file) || !std::ifstream(file))
          throw InputError::at(file, "cannot open the parameter file");
        const ParameterFile input(file);
        if (read_dimension(input) == 2)
          run_scene<2>(input, resume);
        else
          run_scene<3>(input, resume);
        return exit_status::success;
      }
    catch (const InputError &error)
      {
        err << "signorini: error: "
            << (error.location.empty() ? file : error.location);
        if (!error.entry.empty())
          err << ": entry '" << error.entry << "'";
        err << ": " << error.what() << std::endl;
        return exit_status::input_error;
      }
    catch (const Interrupted &stop)
      {
        err << "signorini: " << stop.message(file) << std::endl;
        return stop.status();
      }
    catch (const SolverFailure &failure)
      {
        err << "signorini: error: " << failure.what() << std::endl;
        return failure.status;
      }
    catch (const ExceptionBase &error)
      {
        err << "signorini: error: " << one_line(error) << std::endl;
      }
    catch (const std::exception &error)
      {
        err << "signorini: error: " << error.what() << std::endl;
      }
    catch (...)
      {
        err << "signorini: error: unknown failure" << std::endl;
      }
    return exit_status::other;
  }
} // namespace signorini
