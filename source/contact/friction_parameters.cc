#include <deal.II/base/utilities.h>

#include <signorini/contact/friction_parameters.h>
#include <signorini/input/input_error.h>

#include <algorithm>

namespace signorini
{
  using namespace dealii;

  namespace
  {
    std::string
    section(const unsigned int number)
    {
      return number == 1 ? "Obstacle" : "Obstacle " + std::to_string(number);
    }
  } // namespace

  bool
  FrictionParameters::any() const
  {
    const auto positive = [](const double value) { return value > 0.; };
    return std::any_of(coefficient.begin(), coefficient.end(), positive) ||
           std::any_of(slip_bound.begin(), slip_bound.end(), positive);
  }

  void
  FrictionParameters::declare_parameters(ParameterHandler &prm)
  {
    for (unsigned int number = 1; number <= max_obstacles; ++number)
      {
        prm.enter_subsection(section(number));
        prm.declare_entry(
          "Friction coefficient",
          "0",
          Patterns::Anything(),
          "Coulomb's friction coefficient mu between the body and this "
          "obstacle (no unit): a node in contact sticks while its shear "
          "traction is below mu x its contact pressure and slips, against "
          "its slip, at that traction. 0: frictionless. Needs Contact/Method "
          "= active set (exact), penalty (a regularised stick) or augmented "
          "lagrangian (exact as its updates converge); slip is counted over each load step (Load "
          "history).");
        prm.declare_entry(
          "Tresca slip bound",
          "",
          Patterns::Anything(),
          "Tresca friction instead of Coulomb's: the shear traction s [MPa] "
          "at which a node in contact slips, whatever its pressure (a "
          "model of a thin layer of given shear strength). Empty: none.");
        prm.leave_subsection();
      }
  }

  void
  FrictionParameters::parse_parameters(ParameterHandler &prm)
  {
    const auto number_of = [](const std::string &text,
                              const std::string &entry) {
      try
        {
          return Utilities::string_to_double(text);
        }
      catch (...)
        {
          throw InputError(entry, "'" + text + "' is not a number");
        }
    };
    for (unsigned int number = 1; number <= max_obstacles; ++number)
      {
        const std::string name = section(number);
        prm.enter_subsection(name);
        const std::string mu_text    = prm.get("Friction coefficient");
        const std::string bound_text = prm.get("Tresca slip bound");
        prm.leave_subsection();
        const std::string mu_entry    = name + "/Friction coefficient";
        const std::string bound_entry = name + "/Tresca slip bound";
        coefficient[number - 1] = parse::in_range(number_of(mu_text, mu_entry),
                                                  parse::Range::at_least(0.),
                                                  mu_entry);
        slip_bound[number - 1] =
          bound_text.find_first_not_of(" \t") == std::string::npos ?
            0. :
            parse::in_range(number_of(bound_text, bound_entry),
                            parse::Range::positive(),
                            bound_entry);
        if (coefficient[number - 1] > 0 && slip_bound[number - 1] > 0)
          throw InputError(bound_entry,
                           "is given with " + mu_entry +
                             " > 0: an obstacle has Coulomb's or Tresca's "
                             "friction, not both");
      }
  }

  void
  FrictionParameters::check(const std::vector<unsigned int> &obstacle_numbers,
                            const std::string               &method,
                            const bool method_solves) const
  {
    for (unsigned int number = 1; number <= max_obstacles; ++number)
      if ((coefficient[number - 1] > 0 || slip_bound[number - 1] > 0) &&
          std::find(obstacle_numbers.begin(), obstacle_numbers.end(), number) ==
            obstacle_numbers.end())
        throw InputError(section(number) + (coefficient[number - 1] > 0 ?
                                              "/Friction coefficient" :
                                              "/Tresca slip bound"),
                         "is given for no obstacle (" + section(number) +
                           "/Type is none)");
    if (!any())
      return;
    if (!method_solves)
      throw InputError("Contact/Method",
                       "friction (an obstacle's Friction coefficient or "
                       "Tresca slip bound) needs a contact method, not '" +
                         method + "'");
  }
} // namespace signorini
