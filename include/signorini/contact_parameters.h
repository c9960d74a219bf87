#ifndef signorini_contact_parameters_h
#define signorini_contact_parameters_h

#include <deal.II/base/parameter_handler.h>

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
   * - `none`: linear elasticity, the obstacle is ignored (but its gap is
   *   reported).
   */
  struct ContactParameters
  {
    enum class Method
    {
      none,
      active_set,
      penalty
    };

    Method       method                   = Method::active_set;
    double       penalty_parameter        = 1e-6;
    double       complementarity_constant = 0.;
    unsigned int max_iterations           = 50;
    double       tolerance                = 1e-8;

    static void
    declare_parameters(dealii::ParameterHandler &prm);

    void
    parse_parameters(dealii::ParameterHandler &prm);
  };
} // namespace signorini

#endif
