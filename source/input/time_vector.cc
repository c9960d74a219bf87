#include <signorini/base/text.h>
#include <signorini/input/input_error.h>
#include <signorini/input/parsed_function.h>
#include <signorini/input/time_vector.h>

#include <cmath>
#include <cstdlib>

namespace signorini
{
  std::vector<std::string>
  split_outside_parentheses(const std::string &text, const char separator)
  {
    std::vector<std::string> items(1);
    int                      depth = 0;
    for (const char c : text)
      {
        if (c == '(')
          ++depth;
        else if (c == ')')
          --depth;
        if (c == separator && depth == 0)
          items.emplace_back();
        else
          items.back() += c;
      }
    for (auto &item : items)
      {
        item.erase(0, item.find_first_not_of(" \t"));
        item.erase(item.find_last_not_of(" \t") + 1);
      }
    return items;
  }

  template <int dim>
  TimeVector<dim>::TimeVector(const dealii::Tensor<1, dim> &value)
    : constants(value)
  {
  }

  template <int dim>
  TimeVector<dim>::TimeVector(const std::string &text, const std::string &entry)
    : entry(entry)
    , text(text)
  {
    const auto components = split_outside_parentheses(text, ',');
    if (components.size() != dim)
      throw InputError(entry,
                       "'" + text + "' is not a vector of " +
                         std::to_string(dim) +
                         " components (numbers or expressions of t "
                         "separated by ',')");
    for (unsigned int d = 0; d < dim; ++d)
      {
        const std::string &component = components[d];
        char              *end       = nullptr;
        std::strtod(component.c_str(), &end);
        if (!component.empty() && *end == '\0')
          // A number, read as parse::point() reads one.
          constants[d] = parse::number(component, entry);
        else
          {
            auto expression = std::make_shared<dealii::FunctionParser<1>>(1);
            initialize_parser<1>(
              *expression, "t", {component}, {}, false, entry, text);
            expressions[d] = expression;
          }
      }
  }

  template <int dim>
  dealii::Tensor<1, dim>
  TimeVector<dim>::value(const double t) const
  {
    dealii::Tensor<1, dim> v = constants;
    for (unsigned int d = 0; d < dim; ++d)
      if (expressions[d])
        {
          v[d] = expressions[d]->value(dealii::Point<1>(t));
          if (!std::isfinite(v[d]))
            throw InputError(entry,
                             "'" + text + "' evaluates to " +
                               (std::isnan(v[d]) ? std::string("nan") :
                                                   number(v[d])) +
                               " in component " + std::to_string(d + 1) +
                               " at t = " + number(t));
        }
    return v;
  }

  template <int dim>
  bool
  TimeVector<dim>::depends_on_time() const
  {
    for (const auto &expression : expressions)
      if (expression)
        return true;
    return false;
  }

  template <int dim>
  std::optional<double>
  TimeVector<dim>::constant_component(const unsigned int d) const
  {
    if (expressions[d])
      return {};
    return constants[d];
  }

  template class TimeVector<2>;
  template class TimeVector<3>;
} // namespace signorini
