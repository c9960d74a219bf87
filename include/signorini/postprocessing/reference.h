#ifndef signorini_postprocessing_reference_h
#define signorini_postprocessing_reference_h

#include <deal.II/base/function_parser.h>
#include <deal.II/base/parameter_handler.h>

#include <map>
#include <memory>
#include <optional>
#include <string>

namespace signorini
{
  /**
   * A closed-form number of Reference: an expression of its constants and
   * of the load history's pseudo-time t (e.g. `t < 1.5 ? 2*a : 2*c`), or
   * none. One that does not use t is checked when parsed, one that does
   * when evaluated.
   */
  class ReferenceNumber
  {
  public:
    /** None. */
    ReferenceNumber() = default;

    /** The expression @p text of the entry @p entry (its full name) with
     * @p constants; none if @p text is empty. @p at_least_zero: the
     * quantity is not negative (@p why: the reason, for the message).
     * Throws an InputError if it does not parse, or if it does not use t
     * and is not a finite number (or negative). */
    ReferenceNumber(const std::string                   &text,
                    const std::string                   &entry,
                    const std::map<std::string, double> &constants,
                    const bool                           at_least_zero,
                    const std::string                   &why = "");

    /** Whether the entry gives a number. */
    explicit operator bool() const
    {
      return function != nullptr;
    }

    /** The value at pseudo-time @p t; throws an InputError naming the entry
     * and t if it is not a finite number (or negative). */
    double
    at(const double t) const;

  private:
    std::string                                entry;
    std::string                                text;
    std::shared_ptr<dealii::FunctionParser<1>> function;
    bool                                       at_least_zero = false;
    std::string                                why;
    /** The text names t. */
    bool time_dependent = false;
  };

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
    /** Peak contact pressure [MPa]. */
    ReferenceNumber max_pressure;
    /** Extent of the contact zone along x [mm]. */
    ReferenceNumber contact_width;
    /** With friction: extent of the stick zone [mm]. */
    ReferenceNumber stick_width;
    /** With friction: peak shear traction [MPa]. */
    ReferenceNumber max_shear;
    /** Potential energy of the exact solution [N mm, per mm of thickness in
     * 2D]. */
    ReferenceNumber energy;

    /** Declares the entries, with the defaults of a default-constructed
     * instance: no reference (empty entries). */
    static void
    declare_parameters(dealii::ParameterHandler &prm);

    void
    parse_parameters(dealii::ParameterHandler &prm);
  };
} // namespace signorini

#endif
