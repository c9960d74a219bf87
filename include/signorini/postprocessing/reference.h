#ifndef signorini_postprocessing_reference_h
#define signorini_postprocessing_reference_h

#include <deal.II/base/function_parser.h>
#include <deal.II/base/parameter_handler.h>

#include <memory>
#include <optional>

namespace signorini
{
  /**
   * What the numerical solution is measured against: a closed-form contact
   * pressure (Hertz, say) and the potential energy of an overkill solution.
   * Each one given adds an error column to statistics.csv.
   */
  template <int dim>
  struct Reference
  {
    /** Closed-form contact pressure [MPa] as a function of x, y[, z]; null
     * if not given. */
    std::unique_ptr<dealii::FunctionParser<dim>> contact_pressure;
    /** Peak contact pressure [MPa], if given. */
    std::optional<double> max_pressure;
    /** Extent of the contact zone along x [mm], if given. */
    std::optional<double> contact_width;
    /** Potential energy of the exact solution [N mm, per mm of thickness in
     * 2D], if given. */
    std::optional<double> energy;

    /** Declares the entries, with the defaults of a default-constructed
     * instance: no reference (empty entries). */
    static void
    declare_parameters(dealii::ParameterHandler &prm);

    void
    parse_parameters(dealii::ParameterHandler &prm);
  };
} // namespace signorini

#endif
