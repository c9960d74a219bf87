#ifndef signorini_output_output_parameters_h
#define signorini_output_output_parameters_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/point.h>

#include <signorini/output/file_output.h>

#include <string>
#include <vector>

namespace signorini
{
  /** What is written and printed: subsection `Output`. */
  template <int dim>
  struct OutputParameters
  {
    /** The folder of the results, relative to the current folder. */
    std::string directory = "output";
    /** Points [mm] whose displacement goes into statistics.csv. */
    std::vector<dealii::Point<dim>> probe_points;
    /** Print a line per Newton iteration. */
    bool verbose = true;
    /** Print the timer summary at the end of the run. */
    bool print_timings = true;
    /** Write contact_pressure-CC.csv for every cycle. */
    bool contact_pressure_table = false;
    /** Write timings.csv, with a linear solve per cycle to compare with. */
    bool timing_table = false;
    /** How the solution files' arrays are compressed. */
    VtuCompression compression = VtuCompression::lz4;

    /** Declares the entries, with the defaults of a default-constructed
     * instance. */
    static void
    declare_parameters(dealii::ParameterHandler &prm);

    void
    parse_parameters(dealii::ParameterHandler &prm);
  };
} // namespace signorini

#endif
