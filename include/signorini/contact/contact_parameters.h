#ifndef signorini_contact_contact_parameters_h
#define signorini_contact_contact_parameters_h

#include <deal.II/base/parameter_handler.h>

#include <signorini/input/entry_text.h>

namespace signorini
{
  /**
   * How contact is enforced: subsection `Contact`.
   *
   * - `active set`: primal-dual active set (semismooth Newton) with a lumped
   *   contact-boundary mass: exact non-penetration at the contact nodes.
   * - `penalty`: the contact pressure is p = [penetration]_+ / epsilon, i.e.
   *   the obstacle acts as a Winkler layer of compliance epsilon [mm/MPa]; the
   *   penetration is epsilon times the local pressure. Solved by semismooth
   *   Newton iterations.
   * - `augmented lagrangian`: Uzawa updates of a multiplier (the contact
   *   pressure) around a penalty of compliance epsilon: each inner problem
   *   has the pressure [lambda - gap / epsilon]_+ and is solved by semismooth
   *   Newton; lambda then takes that pressure. At convergence the
   *   penetration vanishes, without the penalty's ill-conditioning.
   * - `none`: linear elasticity, the obstacle is ignored (but its gap is
   *   reported).
   */
  struct ContactParameters
  {
    enum class Method
    {
      none,
      active_set,
      penalty,
      augmented_lagrangian
    };

    /** Each method's name in a parameter file and what it does. A new
     * formulation adds its value to Method, its line here, and a line in
     * create_contact_formulation(). */
    static const Choices<Method> &
    methods()
    {
      static const Choices<Method> choices{
        {Method::active_set,
         "active set",
         "exact non-penetration (primal-dual active set)"},
        {Method::penalty,
         "penalty",
         "penetration = penalty parameter x contact pressure"},
        {Method::augmented_lagrangian,
         "augmented lagrangian",
         "Uzawa updates of the contact pressure around a penalty, each "
         "solved by Newton, converging to the exact non-penetration"},
        {Method::none, "none", "no contact"}};
      return choices;
    }

    Method method = Method::active_set;
    /** epsilon [mm/MPa]; 0: h_min / (10 E) of each cycle's mesh. */
    double penalty_parameter = 0.;
    /** Relative change of the multipliers at convergence. */
    double       multiplier_tolerance = 1e-8;
    unsigned int max_updates          = 100;
    /** Apply (and report) the cheap remedy of each method's failure. */
    bool         remedies                 = true;
    double       complementarity_constant = 0.;
    unsigned int max_iterations           = 50;
    double       tolerance                = 1e-8;

    static void
    declare_parameters(dealii::ParameterHandler &prm);

    void
    parse_parameters(dealii::ParameterHandler &prm);

    /** Whether the obstacles act on the body at all (every method but
     * none): what the scene checks and the contact surface ask. */
    bool
    acts() const
    {
      return method != Method::none;
    }
  };
} // namespace signorini

#endif
