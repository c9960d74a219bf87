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
     * is @p text; initialize() it as a FunctionParser. */
    ParsedFunction(const unsigned int n_components,
                   const std::string &entry,
                   const std::string &text);

    /** The value; one that is not finite is remembered once watch() was
     * called. */
    double
    value(const dealii::Point<dim> &p,
          const unsigned int        component = 0) const override;

    /** From now on, values that are not finite are remembered. */
    void
    watch();

    /**
     * Throws, on every process of @p comm, an InputError naming the entry,
     * the text and the point if this function evaluated to a value that is
     * not finite on any process (the first such point of the lowest such
     * process). Collective.
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
    bool               zero;
    bool               watching = false;
    mutable std::mutex mutex;
    mutable std::optional<std::pair<dealii::Point<dim>, double>> non_finite;
  };

  /**
   * A muparser function of x, y[, z] from a parameter entry: @p n_components
   * expressions separated by ';', or a single expression used for every
   * component. The constant `pi` is defined, and so is every name of
   * @p constants. Throws an InputError naming @p entry if the text does not
   * parse. The function is a ParsedFunction: check_finite() tells whether
   * it evaluated to a value that is not finite.
   */
  template <int dim>
  std::unique_ptr<dealii::FunctionParser<dim>>
  parse_function(const std::string                   &text,
                 const unsigned int                   n_components,
                 const std::string                   &entry,
                 const std::map<std::string, double> &constants = {});

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
