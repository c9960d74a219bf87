#include <deal.II/base/exceptions.h>
#include <deal.II/lac/vector.h>

#include <signorini/input_error.h>
#include <signorini/parsed_function.h>


namespace signorini
{
  template <int dim>
  std::unique_ptr<dealii::FunctionParser<dim>>
  parse_function(const std::string &text,
                 const unsigned int n_components,
                 const std::string &entry)
  {
    auto expressions = parse::split(text, ';');
    if (expressions.size() == 1 && n_components > 1)
      expressions.assign(n_components, expressions[0]);
    if (expressions.size() != n_components)
      throw InputError(entry,
                       "'" + text + "' should hold " +
                         std::to_string(n_components) +
                         " expressions separated by ';' (or one for all)");

    const std::string variables = dim == 1 ? "x" : (dim == 2 ? "x,y" : "x,y,z");
    auto function = std::make_unique<dealii::FunctionParser<dim>>(n_components);
    try
      {
        function->initialize(variables,
                             expressions,
                             {{"pi", dealii::numbers::PI}});
        // muparser reports some errors only on evaluation:
        dealii::Vector<double> values(n_components);
        function->vector_value(dealii::Point<dim>(), values);
      }
    catch (const dealii::ExceptionBase &error)
      {
        throw InputError(entry,
                         "cannot parse '" + text + "': " + one_line(error));
      }
    return function;
  }

  template std::unique_ptr<dealii::FunctionParser<1>>
  parse_function<1>(const std::string &, unsigned int, const std::string &);
  template std::unique_ptr<dealii::FunctionParser<2>>
  parse_function<2>(const std::string &, unsigned int, const std::string &);
  template std::unique_ptr<dealii::FunctionParser<3>>
  parse_function<3>(const std::string &, unsigned int, const std::string &);
} // namespace signorini
