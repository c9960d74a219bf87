#ifndef signorini_contact_friction_parameters_h
#define signorini_contact_friction_parameters_h

#include <deal.II/base/parameter_handler.h>

#include <signorini/contact/obstacle_parameters.h>

#include <array>
#include <string>
#include <vector>

namespace signorini
{
  /**
   * The friction between the body and each obstacle, declared in each
   * obstacle's subsection (`Obstacle`, `Obstacle 2`, ...): a Coulomb
   * friction coefficient mu, or a Tresca slip bound s [MPa] (the shear
   * traction at which the body slips, whatever the pressure). Neither:
   * frictionless.
   */
  struct FrictionParameters
  {
    /** mu of the obstacle of each subsection (index: its number - 1). */
    std::array<double, max_obstacles> coefficient = {};
    /** s [MPa] of the obstacle of each subsection, 0 for none. */
    std::array<double, max_obstacles> slip_bound = {};

    /** Whether any obstacle has friction. */
    bool
    any() const;

    static void
    declare_parameters(dealii::ParameterHandler &prm);

    /** Throws InputError for a coefficient that is negative or not a
     * number, a slip bound that is not a positive number, and both on one
     * obstacle. */
    void
    parse_parameters(dealii::ParameterHandler &prm);

    /** Throws InputError for friction in a subsection that is no obstacle
     * (not in @p obstacle_numbers), friction with a Contact/Method that
     * does not solve it (@p method: its name, @p method_solves: whether it
     * does). */
    void
    check(const std::vector<unsigned int> &obstacle_numbers,
          const std::string               &method,
          const bool                       method_solves) const;
  };
} // namespace signorini

#endif
