#ifndef signorini_input_parsed_function_h
#define signorini_input_parsed_function_h

#include <deal.II/base/function_parser.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/point.h>

#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <utility>

namespace signorini
{
  /**
   * A muparser function of a parameter entry that remembers the first point
   * at which it evaluated to a value that is not a finite number (1/x at
   * x = 0, sqrt of a negative number, an overflow), so that the places that
   * use it can stop with an error naming the entry and the point
   * (check_finite()) instead of solving with it.
   */
  template <int dim>
  class ParsedFunction : public dealii::FunctionParser<dim>
  {
  public:
    /** A function of @p n_components components for @p entry, whose text
     * is @p text; initialize() it as a FunctionParser (@p time_dependent:
     * with the time variable t). */
    ParsedFunction(const unsigned int n_components,
                   const std::string &entry,
                   const std::string &text,
                   const bool         time_dependent = false);

    /** The value; one that is not finite is remembered once watch() was
     * called, with the point and the time. */
    double
    value(const dealii::Point<dim> &p,
          const unsigned int        component = 0) const override;

    /** From now on, values that are not finite are remembered. */
    void
    watch();

    /**
     * Throws, on every process of @p comm, an InputError naming the entry,
     * the text and the point (and the pseudo-time t, if the text uses t) if
     * this function evaluated to a value that is not finite on any process
     * (the first such point of the lowest such process). Collective.
     */
    void
    check_finite(const MPI_Comm comm) const;

    /** Whether every component's expression is the number 0 (a load that
     * is not there need not be integrated). */
    bool
    vanishes() const
    {
      return zero;
    }

  private:
    const std::string entry;
    const std::string text;
    /** Each expression of the text is the number 0. */
    bool zero;
    /** The function depends on time and its text names it, t. */
    bool               uses_time;
    bool               watching = false;
    mutable std::mutex mutex;
    /** The first point where the value was not finite, the value and the
     * time. */
    struct NonFinite
    {
      dealii::Point<dim> point;
      double             value;
      double             time;
    };
    mutable std::optional<NonFinite> non_finite;
  };

  /** Whether the muparser expression @p text names the variable @p name
   * (as a whole identifier: `t` in `0.1*t`, not in `sqrt(x)`). */
  bool
  names_variable(const std::string &text, const std::string &name);

  /**
   * Initializes @p function with the muparser @p expressions (one per
   * component) of the comma-separated @p variables, the constant `pi` and
   * every name of @p constants; with @p time_dependent the last variable is
   * the function's time (FunctionTime::set_time). Throws an InputError
   * naming @p entry and its @p text if an expression does not parse (some
   * errors muparser reports only on a first evaluation, at the origin).
   */
  template <int dim>
  void
  initialize_parser(dealii::FunctionParser<dim>         &function,
                    const std::string                   &variables,
                    const std::vector<std::string>      &expressions,
                    const std::map<std::string, double> &constants,
                    const bool                           time_dependent,
                    const std::string                   &entry,
                    const std::string                   &text);

  /**
   * A muparser function of x, y[, z] from a parameter entry: @p n_components
   * expressions separated by ';', or a single expression used for every
   * component. The constant `pi` is defined, and so is every name of
   * @p constants; with @p time_dependent also the variable t, the
   * pseudo-time of the load history, which FunctionTime::set_time() sets (0
   * until then). Throws an InputError naming @p entry if the text does not
   * parse. The function is a ParsedFunction: check_finite() tells whether
   * it evaluated to a value that is not finite.
   */
  template <int dim>
  std::unique_ptr<dealii::FunctionParser<dim>>
  parse_function(const std::string                   &text,
                 const unsigned int                   n_components,
                 const std::string                   &entry,
                 const std::map<std::string, double> &constants      = {},
                 const bool                           time_dependent = false);

  /** ParsedFunction::check_finite() of @p function if it is a
   * ParsedFunction; nothing for other functions. Collective over @p comm
   * (every process must pass a function of the same kind). */
  template <int dim>
  void
  check_finite(const dealii::Function<dim> &function, const MPI_Comm comm);

  /** ParsedFunction::vanishes() of @p function if it is a ParsedFunction;
   * false for other functions. */
  template <int dim>
  bool
  vanishes(const dealii::Function<dim> &function);
} // namespace signorini

#endif
