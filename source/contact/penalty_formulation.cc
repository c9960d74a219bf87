#include <signorini/base/failures.h>
#include <signorini/base/text.h>
#include <signorini/contact/condition_enforcement.h>
#include <signorini/contact/newton_driver.h>
#include <signorini/contact/penalty_formulation.h>

#include <algorithm>

namespace signorini
{
  using namespace dealii;

  double
  penalty_compliance(const ContactParameters &parameters,
                     const double             minimal_cell_diameter,
                     const double             young_modulus)
  {
    // Automatic: r = epsilon E / h_min = 0.1.
    return parameters.penalty_parameter > 0 ?
             parameters.penalty_parameter :
             0.1 * minimal_cell_diameter / young_modulus;
  }

  template <int dim>
  PenaltyFormulation<dim>::PenaltyFormulation(
    const ContactParameters &parameters,
    const double             young_modulus,
    ConditionalOStream      &pcout)
    : parameters(parameters)
    , young_modulus(young_modulus)
    , pcout(pcout)
  {
  }

  template <int dim>
  std::string
  PenaltyFormulation<dim>::name() const
  {
    return "penalty";
  }

  template <int dim>
  void
  PenaltyFormulation<dim>::solve(NewtonDriver<dim> &newton,
                                 const unsigned int cycle)
  {
    epsilon            = penalty_compliance(parameters,
                                 newton.minimal_cell_diameter(),
                                 young_modulus);
    touching_tolerance = newton.contact_surface().touching_tolerance();
    sign_rule          = false;
    newton.initialize_active_set();
    if (!parameters.remedies)
      {
        newton.iterate(cycle);
        return;
      }
    try
      {
        newton.iterate(cycle);
        return;
      }
    catch (const SolverFailure &failure)
      {
        if (failure.status != exit_status::active_set_cycling &&
            failure.status != exit_status::contact_stalled &&
            failure.status != exit_status::contact_no_converge)
          throw;
        // Penalty continuation: from a 1000 times softer penalty, whose
        // Newton iteration settles easily, down to the asked one by factors
        // of 10, each stage starting from the one before (for a cycling set,
        // after the cycle breaking failed).
        const double target = epsilon;
        pcout << "   remedy: " << failure.what()
              << "; penalty continuation from epsilon = "
              << number(1000. * target) << " down to " << number(target)
              << std::endl;
        for (double stage = 1000. * target;; stage /= 10.)
          {
            epsilon = std::max(stage, target);
            newton.initialize_active_set();
            try
              {
                newton.iterate(cycle);
              }
            catch (const SolverFailure &again)
              {
                throw SolverFailure(again.status,
                                    std::string(again.what()) +
                                      "; penalty continuation did not help "
                                      "(failed at epsilon = " +
                                      number(epsilon) + ")");
              }
            if (epsilon <= target)
              return;
          }
      }
  }

  template <int dim>
  double
  PenaltyFormulation<dim>::state_pressure(const unsigned int,
                                          const ContactNode<dim> &,
                                          const double gap,
                                          const double) const
  {
    // The penetrating nodes, a gap counting as negative only beyond
    // round-off, so that a node grazing the obstacle does not flip.
    return -(sign_rule ? gap : gap + touching_tolerance) / epsilon;
  }

  template <int dim>
  double
  PenaltyFormulation<dim>::residual_pressure(const unsigned int,
                                             const ContactNode<dim> &,
                                             const double gap,
                                             const double) const
  {
    return 0. - gap / epsilon;
  }

  template <int dim>
  Tensor<1, dim>
  PenaltyFormulation<dim>::tangential_traction(const unsigned int i,
                                               const ContactNode<dim> &,
                                               const Tensor<1, dim> &slip,
                                               const Tensor<1, dim> &) const
  {
    // The tangential springs' traction: a regularised stick.
    return -tangential_stiffness(i) * slip;
  }

  template <int dim>
  double
  PenaltyFormulation<dim>::tangential_stiffness(const unsigned int) const
  {
    return 1. / epsilon;
  }

  template <int dim>
  double
  PenaltyFormulation<dim>::shear_weight() const
  {
    return 0.;
  }

  template <int dim>
  void
  PenaltyFormulation<dim>::linearise(
    const ContactSurface<dim>            &surface,
    const ContactLaw<dim>                &law,
    const std::vector<NodeTraction<dim>> &tractions,
    SystemAdditions<dim>                 &additions) const
  {
    condition_enforcement::add_springs(
      surface, law, tractions, epsilon, {}, {}, additions);
    additions.key = {surface.active_set_signature(), epsilon};
  }

  template <int dim>
  std::string
  PenaltyFormulation<dim>::break_cycle()
  {
    // A node whose penetration epsilon x pressure is below the touching
    // tolerance flips on every step; it is penetrating if its gap is
    // negative at all.
    if (sign_rule)
      return "";
    sign_rule = true;
    return "counting every negative gap as penetrating";
  }

  template <int dim>
  bool
  PenaltyFormulation<dim>::cycle_broken() const
  {
    return sign_rule;
  }

  template <int dim>
  std::string
  PenaltyFormulation<dim>::failure_hint() const
  {
    return " is Contact/Penalty parameter too small?";
  }

  template <int dim>
  std::string
  PenaltyFormulation<dim>::stall_hint() const
  {
    return "the round-off of a stiff penalty: is Contact/Penalty parameter "
           "too small? ";
  }

  template <int dim>
  void
  PenaltyFormulation<dim>::report(StatisticsRow &row,
                                  ConditionalOStream &) const
  {
    row.add("penalty_parameter", epsilon);
  }

  template class PenaltyFormulation<2>;
  template class PenaltyFormulation<3>;
} // namespace signorini
