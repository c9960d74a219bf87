#include <signorini/contact_parameters.h>
#include <signorini/input_error.h>

namespace signorini
{
  using namespace dealii;

  void
  ContactParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Contact");
    prm.declare_entry(
      "Method",
      "active set",
      Patterns::Selection("active set|penalty|none"),
      "active set: exact non-penetration (primal-dual active "
      "set); penalty: penetration = penalty parameter x contact "
      "pressure; none: no contact.");
    prm.declare_entry("Penalty parameter",
                      "1e-6",
                      Patterns::Double(0.),
                      "penalty: epsilon [mm/MPa], the compliance of the "
                      "obstacle's surface: contact pressure = penetration / "
                      "epsilon. Smaller epsilon, smaller penetration (in "
                      "proportion) and a stiffer system.");
    prm.declare_entry("Complementarity constant",
                      "0",
                      Patterns::Double(0.),
                      "active set: c [MPa/mm] in the update 'active where "
                      "pressure - c x gap > 0'. It matters only when a cycle "
                      "starts from the previous one. 0: Young's modulus "
                      "divided by the smallest cell diameter.");
    prm.declare_entry("Maximum iterations",
                      "50",
                      Patterns::Integer(1),
                      "Newton (active set) iterations allowed per cycle.");
    prm.declare_entry("Tolerance",
                      "1e-8",
                      Patterns::Double(0.),
                      "Converged when the active set is unchanged and the "
                      "residual (force balance and complementarity, relative "
                      "to the applied load) is below this, or stops falling "
                      "below 100 times this (the round-off floor of a fine "
                      "mesh); a residual that stops falling above that is a "
                      "failure.");
    prm.leave_subsection();
  }

  void
  ContactParameters::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Contact");
    const std::string name   = prm.get("Method");
    method                   = name == "none"    ? Method::none :
                               name == "penalty" ? Method::penalty :
                                                   Method::active_set;
    penalty_parameter        = prm.get_double("Penalty parameter");
    complementarity_constant = prm.get_double("Complementarity constant");
    max_iterations           = prm.get_integer("Maximum iterations");
    tolerance                = prm.get_double("Tolerance");
    prm.leave_subsection();
    if (method == Method::penalty && !(penalty_parameter > 0))
      throw InputError("Contact/Penalty parameter", "must be positive");
  }
} // namespace signorini
