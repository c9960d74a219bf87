#include <signorini/contact/contact_parameters.h>
#include <signorini/input/entry_text.h>
#include <signorini/input/input_error.h>

namespace signorini
{
  using namespace dealii;

  void
  ContactParameters::declare_parameters(ParameterHandler &prm)
  {
    const ContactParameters defaults;
    prm.enter_subsection("Contact");
    prm.declare_entry("Method",
                      methods().name(defaults.method),
                      methods().pattern(),
                      methods().documentation());
    prm.declare_entry(
      "Penalty parameter",
      entry_text::of(defaults.penalty_parameter),
      Patterns::Double(0.),
      "penalty and augmented lagrangian: epsilon [mm/MPa], the compliance of "
      "the obstacle's surface: contact pressure = penetration / epsilon "
      "(augmented lagrangian: plus the multiplier). Penalty: the "
      "penetration is epsilon x pressure; smaller epsilon, smaller "
      "penetration and a stiffer system. Augmented lagrangian: the "
      "multipliers converge by a factor of about r / (1 + r) per update, "
      "r = epsilon x E / h_min. 0: h_min / (10 E) of each cycle's mesh "
      "(r = 0.1).");
    prm.declare_entry("Multiplier tolerance",
                      entry_text::of(defaults.multiplier_tolerance),
                      Patterns::Double(0.),
                      "augmented lagrangian: converged when no multiplier "
                      "(contact pressure) changes by more than this times "
                      "the largest one in an update, i.e. the penetration is "
                      "below this x epsilon x the peak pressure.");
    prm.declare_entry("Maximum updates",
                      entry_text::of(defaults.max_updates),
                      Patterns::Integer(1),
                      "augmented lagrangian: multiplier updates allowed "
                      "per cycle.");
    prm.declare_entry(
      "Remedies",
      entry_text::of(defaults.remedies),
      Patterns::Bool(),
      "Apply the cheap remedy when a method fails, and report it: active "
      "set cycling is broken by fixing the nodes that flip; penalty Newton "
      "that oscillates or stalls is continued from a 1000 times softer "
      "penalty; augmented lagrangian multipliers that converge slowly "
      "get a stiffer penalty; a linear solve that CG cannot finish is "
      "done again with a fresh AMG, then by the direct solver. false: stop "
      "with the failure's exit status.");
    prm.declare_entry("Complementarity constant",
                      entry_text::of(defaults.complementarity_constant),
                      Patterns::Double(0.),
                      "active set: c [MPa/mm] in the update 'active where "
                      "pressure - c x gap > 0'. It matters only when a cycle "
                      "starts from the previous one. 0: Young's modulus "
                      "divided by the smallest cell diameter.");
    prm.declare_entry("Maximum iterations",
                      entry_text::of(defaults.max_iterations),
                      Patterns::Integer(1),
                      "Newton (active set) iterations allowed per cycle.");
    prm.declare_entry("Tolerance",
                      entry_text::of(defaults.tolerance),
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
    method               = methods().value(prm.get("Method"), "Contact/Method");
    penalty_parameter    = prm.get_double("Penalty parameter");
    multiplier_tolerance = prm.get_double("Multiplier tolerance");
    max_updates          = prm.get_integer("Maximum updates");
    remedies             = prm.get_bool("Remedies");
    complementarity_constant = prm.get_double("Complementarity constant");
    max_iterations           = prm.get_integer("Maximum iterations");
    tolerance                = prm.get_double("Tolerance");
    prm.leave_subsection();
    const auto relative = parse::Range::open(0., 1.);
    parse::in_range(tolerance,
                    relative,
                    "Contact/Tolerance",
                    "a residual relative to the load");
    parse::in_range(multiplier_tolerance,
                    relative,
                    "Contact/Multiplier tolerance",
                    "relative to the peak pressure");
    parse::in_range(penalty_parameter,
                    parse::Range::at_least(0.),
                    "Contact/Penalty parameter");
    parse::in_range(complementarity_constant,
                    parse::Range::at_least(0.),
                    "Contact/Complementarity constant");
  }
} // namespace signorini
