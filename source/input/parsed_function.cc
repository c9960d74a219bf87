#include <deal.II/base/exceptions.h>
#include <deal.II/lac/vector.h>

#include <signorini/input/input_error.h>
#include <signorini/input/parsed_function.h>

#include <iostream>
#include <sstream>


namespace signorini
{
  template <int dim>
  std::unique_ptr<dealii::FunctionParser<dim>>
  parse_function(const std::string                   &text,
                 const unsigned int                   n_components,
                 const std::string                   &entry,
                 const std::map<std::string, double> &constants)
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
    // deal.II lets muparser describe a parse error on std::cerr over several
    // lines; keep that quiet and report the parser's own sentence once.
    std::ostringstream muted;
    std::streambuf    *cerr_buffer = std::cerr.rdbuf(muted.rdbuf());
    try
      {
        auto all_constants = constants;
        all_constants.emplace("pi", dealii::numbers::PI);
        function->initialize(variables, expressions, all_constants);
        // muparser reports some errors only on evaluation:
        dealii::Vector<double> values(n_components);
        function->vector_value(dealii::Point<dim>(), values);
        std::cerr.rdbuf(cerr_buffer);
      }
    catch (const dealii::ExceptionBase &error)
      {
        std::cerr.rdbuf(cerr_buffer);
        std::string       message = one_line(error);
        const std::string said    = "The parser said: ";
        if (message.find(said) != std::string::npos)
          message = message.substr(message.find(said) + said.size());
        throw InputError(entry, "cannot parse '" + text + "': " + message);
      }
    return function;
  }

  template std::unique_ptr<dealii::FunctionParser<1>>
  parse_function<1>(const std::string &,
                    unsigned int,
                    const std::string &,
                    const std::map<std::string, double> &);
  template std::unique_ptr<dealii::FunctionParser<2>>
  parse_function<2>(const std::string &,
                    unsigned int,
                    const std::string &,
                    const std::map<std::string, double> &);
  template std::unique_ptr<dealii::FunctionParser<3>>
  parse_function<3>(const std::string &,
                    unsigned int,
                    const std::string &,
                    const std::map<std::string, double> &);
} // namespace signorini
