#include <signorini/input/entry_text.h>
#include <signorini/input/input_error.h>
#include <signorini/input/parsed_function.h>
#include <signorini/postprocessing/reference.h>

#include <cmath>
#include <map>
#include <optional>

namespace signorini
{
  using namespace dealii;

  template <int dim>
  void
  Reference<dim>::declare_parameters(ParameterHandler &prm)
  {
    const Reference<dim> defaults;
    prm.enter_subsection("Reference");
    prm.declare_entry(
      "Function constants",
      "",
      Patterns::Anything(),
      "Names for numbers in the expressions below, "
      "separated by ',', each of the form name=expression; "
      "an expression may use the names before it, e.g. "
      "'R=1, E=1000, nu=0.3, F=10, a=2*sqrt(F*R*(1-nu^2)/(pi*E))'.");
    prm.declare_entry(
      "Contact pressure",
      "",
      Patterns::Anything(),
      "Closed-form contact pressure [MPa] as a function of x, y[, z], zero "
      "outside the contact zone. If given, statistics.csv gains "
      "pressure_error: the L2 norm over the contact boundary of the "
      "computed minus this pressure, relative to the L2 norm of this one.");
    prm.declare_entry("Maximum pressure",
                      entry_text::of(defaults.max_pressure),
                      Patterns::Anything(),
                      "Closed-form peak contact pressure [MPa], a number or "
                      "an expression of the constants. If given, "
                      "statistics.csv gains max_pressure_error, the "
                      "relative error of max_pressure.");
    prm.declare_entry("Contact width",
                      entry_text::of(defaults.contact_width),
                      Patterns::Anything(),
                      "Closed-form extent of the contact zone along x [mm], "
                      "a number or an expression of the constants. If given, "
                      "statistics.csv gains contact_width_error, the "
                      "relative error of contact_width.");
    prm.declare_entry(
      "Energy",
      entry_text::of(defaults.energy),
      Patterns::Anything(),
      "Potential energy 1/2 a(u,u) - f(u) of the exact solution [N mm; per "
      "mm of thickness in 2D], e.g. from an overkill run; a number or an "
      "expression of the constants. If given, "
      "statistics.csv gains energy_error = sqrt((J(u_h) - J(u)) / |J(u)|), "
      "the relative energy-norm error.");
    prm.leave_subsection();
  }

  template <int dim>
  void
  Reference<dim>::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Reference");
    std::map<std::string, double> constants;
    for (const auto &definition :
         parse::split(prm.get("Function constants"), ','))
      {
        // name=expression; the expression may use the names before it.
        const auto parts = parse::split(definition, '=');
        if (parts.size() != 2)
          throw InputError("Reference/Function constants",
                           "'" + definition +
                             "' is not of the form name=expression");
        const double value = parse_function<1>(parts[1],
                                               1,
                                               "Reference/Function constants",
                                               constants)
                               ->value(Point<1>());
        if (!std::isfinite(value))
          throw InputError("Reference/Function constants",
                           "'" + definition + "' is not a finite number");
        constants[parts[0]] = value;
      }
    const std::string pressure = prm.get("Contact pressure");
    contact_pressure.reset();
    if (!pressure.empty())
      contact_pressure = parse_function<dim>(pressure,
                                             1,
                                             "Reference/Contact pressure",
                                             constants);
    // A number, or an expression of the constants.
    const auto number = [&](const std::string &name) -> std::optional<double> {
      const std::string text = prm.get(name);
      if (text.empty())
        return {};
      const double value =
        parse_function<1>(text, 1, "Reference/" + name, constants)
          ->value(Point<1>());
      if (!std::isfinite(value))
        throw InputError("Reference/" + name,
                         "'" + text + "' is not a finite number");
      return value;
    };
    max_pressure  = number("Maximum pressure");
    contact_width = number("Contact width");
    energy        = number("Energy");
    prm.leave_subsection();
    if (max_pressure)
      parse::in_range(*max_pressure,
                      parse::Range::at_least(0.),
                      "Reference/Maximum pressure",
                      "a contact pressure is not negative");
    if (contact_width)
      parse::in_range(*contact_width,
                      parse::Range::at_least(0.),
                      "Reference/Contact width");
  }

  template struct Reference<2>;
  template struct Reference<3>;
} // namespace signorini
