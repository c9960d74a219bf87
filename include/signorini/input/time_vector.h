#ifndef signorini_input_time_vector_h
#define signorini_input_time_vector_h

#include <deal.II/base/function_parser.h>
#include <deal.II/base/tensor.h>

#include <array>
#include <memory>
#include <optional>
#include <string>

namespace signorini
{
  /**
   * A vector entry whose components are numbers or muparser expressions of
   * the pseudo-time t of the load history, separated by ',' (a ',' inside
   * parentheses belongs to its expression: `0, -0.01*min(t, 1)`). A
   * number is read as parse::point() reads it, so that an entry of numbers
   * gives the same vector as before t existed. Copies share the parsed
   * expressions.
   */
  template <int dim>
  class TimeVector
  {
  public:
    /** The zero vector. */
    TimeVector() = default;

    /** The constant @p value. */
    TimeVector(const dealii::Tensor<1, dim> &value);

    /** Parses @p text of @p entry; throws InputError naming the entry for a
     * wrong number of components, a number that is not finite or an
     * expression that does not parse. */
    TimeVector(const std::string &text, const std::string &entry);

    /** The vector at pseudo-time @p t. Throws InputError naming the entry,
     * its text and t where a component is not a finite number. */
    dealii::Tensor<1, dim>
    value(const double t) const;

    /** Whether a component is an expression (which may depend on t). */
    bool
    depends_on_time() const;

    /** Component @p d if it is a number, nothing if it is an expression. */
    std::optional<double>
    constant_component(const unsigned int d) const;

  private:
    std::string                                                 entry;
    std::string                                                 text;
    dealii::Tensor<1, dim>                                      constants;
    std::array<std::shared_ptr<dealii::FunctionParser<1>>, dim> expressions;
  };

  /** The items of @p text separated by @p separator outside parentheses,
   * trimmed (empty items kept, unlike parse::split). */
  std::vector<std::string>
  split_outside_parentheses(const std::string &text, const char separator);
} // namespace signorini

#endif
