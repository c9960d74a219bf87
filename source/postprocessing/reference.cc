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

  ReferenceNumber::ReferenceNumber(
    const std::string                   &text,
    const std::string                   &entry,
    const std::map<std::string, double> &constants,
    const bool                           at_least_zero,
    const std::string                   &why)
    : entry(entry)
    , text(text)
    , at_least_zero(at_least_zero)
    , why(why)
  {
    if (text.empty())
      return;
    function = parse_function<1>(text, 1, entry, constants, true);
    // A number that does not depend on t is checked now.
    time_dependent = names_variable(text, "t");
    if (!time_dependent)
      at(0.);
  }

  double
  ReferenceNumber::at(const double t) const
  {
    function->set_time(t);
    const double value = function->value(Point<1>());
    if (!std::isfinite(value))
      throw InputError(entry,
                       "'" + text + "' is not a finite number" +
                         (time_dependent ? " at t = " + entry_text::of(t) :
                                           std::string()));
    if (at_least_zero)
      parse::in_range(value, parse::Range::at_least(0.), entry, why);
    return value;
  }

  template <int dim>
  void
  Reference<dim>::declare_parameters(ParameterHandler &prm)
  {
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
                      "",
                      Patterns::Anything(),
                      "Closed-form peak contact pressure [MPa], a number or "
                      "an expression of the constants and of the load "
                      "history's pseudo-time t. If given, "
                      "statistics.csv gains max_pressure_error, the "
                      "relative error of max_pressure.");
    prm.declare_entry("Contact width",
                      "",
                      Patterns::Anything(),
                      "Closed-form extent of the contact zone along x [mm], "
                      "a number or an expression of the constants and of t. "
                      "If given, "
                      "statistics.csv gains contact_width_error, the "
                      "relative error of contact_width.");
    prm.declare_entry("Stick width",
                      "",
                      Patterns::Anything(),
                      "With friction: closed-form extent of the stick zone "
                      "[mm], along the same direction as the contact width; a "
                      "number or an expression of the constants and of t. "
                      "If given, statistics.csv gains stick_width_error.");
    prm.declare_entry("Maximum shear",
                      "",
                      Patterns::Anything(),
                      "With friction: closed-form peak shear traction [MPa]; "
                      "a number or an expression of the constants and of t. "
                      "If given, statistics.csv gains max_shear_error.");
    prm.declare_entry(
      "Energy",
      "",
      Patterns::Anything(),
      "Potential energy 1/2 a(u,u) - f(u) of the exact solution [N mm; per "
      "mm of thickness in 2D], e.g. from an overkill run; a number or an "
      "expression of the constants and of t. If given, "
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
    const auto number = [&](const std::string &name,
                            const std::string &why = "") {
      return ReferenceNumber(
        prm.get(name), "Reference/" + name, constants, true, why);
    };
    max_pressure =
      number("Maximum pressure", "a contact pressure is not negative");
    contact_width = number("Contact width");
    stick_width   = number("Stick width");
    max_shear     = number("Maximum shear");
    energy =
      ReferenceNumber(prm.get("Energy"), "Reference/Energy", constants, false);
    prm.leave_subsection();
  }

  template struct Reference<2>;
  template struct Reference<3>;
} // namespace signorini
