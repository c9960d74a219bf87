#ifndef signorini_input_parsed_function_h
#define signorini_input_parsed_function_h

#include <deal.II/base/function_parser.h>

#include <map>
#include <memory>
#include <string>

namespace signorini
{
  /**
   * A muparser function of x, y[, z] from a parameter entry: @p n_components
   * expressions separated by ';', or a single expression used for every
   * component. The constant `pi` is defined, and so is every name of
   * @p constants. Throws an InputError naming @p entry if the text does not
   * parse.
   */
  template <int dim>
  std::unique_ptr<dealii::FunctionParser<dim>>
  parse_function(const std::string                   &text,
                 const unsigned int                   n_components,
                 const std::string                   &entry,
                 const std::map<std::string, double> &constants = {});
} // namespace signorini

#endif
