#include <signorini/input/entry_text.h>
#include <signorini/input/input_error.h>
#include <signorini/output/output_parameters.h>

namespace signorini
{
  using namespace dealii;

  template <int dim>
  void
  OutputParameters<dim>::declare_parameters(ParameterHandler &prm)
  {
    const OutputParameters<dim> defaults;
    prm.enter_subsection("Output");
    prm.declare_entry("Directory",
                      entry_text::of(defaults.directory),
                      Patterns::Anything(),
                      "Folder for the results (relative to the current "
                      "folder); created if missing.");
    prm.declare_entry("Probe points",
                      entry_text::of(defaults.probe_points),
                      Patterns::Anything(),
                      "Points [mm] whose displacement goes into "
                      "statistics.csv as probe<i>_ux, probe<i>_uy[, "
                      "probe<i>_uz], i counting from 0; ';'-separated, e.g. "
                      "'10, 0; 5, 1'.");
    prm.declare_entry("Contact pressure table",
                      entry_text::of(defaults.contact_pressure_table),
                      Patterns::Bool(),
                      "Write contact_pressure-CC.csv for every cycle CC: one "
                      "row per contact node (and obstacle it faces), sorted "
                      "by x, with its coordinates x, y[, z] [mm], the "
                      "contact pressure [MPa], the gap to the obstacle "
                      "after deformation [mm] and the obstacle's number (1 "
                      "for Obstacle, N for Obstacle N).");
    prm.declare_entry(
      "Compression",
      defaults.compression == VtuCompression::lz4 ? "lz4" : "zlib",
      Patterns::Selection("lz4|zlib"),
      "How the arrays of the solution files (VTU) are compressed: lz4 writes "
      "them about 15 times faster, zlib (its fastest level) makes them about "
      "30 % smaller. ParaView reads both; a reader without LZ4 needs zlib.");
    prm.declare_entry("Verbose",
                      entry_text::of(defaults.verbose),
                      Patterns::Bool(),
                      "Print a line per Newton iteration as well as the "
                      "summary of each cycle.");
    prm.declare_entry("Print timings",
                      entry_text::of(defaults.print_timings),
                      Patterns::Bool(),
                      "Print the timer summary at the end of the run.");
    prm.declare_entry(
      "Timing table",
      entry_text::of(defaults.timing_table),
      Patterns::Bool(),
      "Write timings.csv, a row per cycle: the wall time [s] of the contact "
      "solve, of one linear elasticity solve on the same mesh with the same "
      "linear solver (the Newton system of the converged active set, "
      "assembled and solved anew after the cycle for this comparison), their "
      "ratio, the run time so far [s] without output "
      "and this comparison, and the peak memory [MB] of all processes.");
    prm.leave_subsection();
  }

  template <int dim>
  void
  OutputParameters<dim>::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Output");
    directory = prm.get("Directory");
    if (directory.empty())
      throw InputError("Output/Directory", "must not be empty");
    probe_points =
      parse::point_list<dim>(prm.get("Probe points"), "Output/Probe points");
    verbose                = prm.get_bool("Verbose");
    print_timings          = prm.get_bool("Print timings");
    contact_pressure_table = prm.get_bool("Contact pressure table");
    timing_table           = prm.get_bool("Timing table");
    compression = prm.get("Compression") == "lz4" ? VtuCompression::lz4 :
                                                    VtuCompression::zlib;
    prm.leave_subsection();
  }

  template struct OutputParameters<2>;
  template struct OutputParameters<3>;
} // namespace signorini
