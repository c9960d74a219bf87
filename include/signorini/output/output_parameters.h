#ifndef signorini_output_output_parameters_h
#define signorini_output_output_parameters_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/point.h>

#include <string>
#include <vector>

namespace signorini
{
  /** What is written and printed: subsection `Output`. */
  template <int dim>
  struct OutputParameters
  {
    std::string                     directory = "output";
    std::vector<dealii::Point<dim>> probe_points;
    bool                            verbose       = true;
    bool                            print_timings = true;
    /** Write contact_pressure-CC.csv for every cycle. */
    bool contact_pressure_table = false;
    /** Write timings.csv, with a linear solve per cycle to compare with. */
    bool timing_table = false;

    static void
    declare_parameters(dealii::ParameterHandler &prm);

    void
    parse_parameters(dealii::ParameterHandler &prm);
  };
} // namespace signorini

#endif
