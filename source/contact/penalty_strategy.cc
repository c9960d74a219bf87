#include <signorini/base/failures.h>
#include <signorini/base/text.h>
#include <signorini/contact/newton_driver.h>
#include <signorini/contact/penalty_strategy.h>

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
  void
  add_penalty_springs(const ContactSurface<dim> &surface,
                      const double               epsilon,
                      const std::vector<double> &multipliers,
                      ContactLinearisation<dim> &linearisation)
  {
    // The obstacle pushes back with p = penetration / epsilon on the
    // penetrating nodes, p_i m_i = -(u_i.n_i + gap_i) m_i / epsilon; the
    // augmented Lagrangian adds the multiplier, p = lambda - (u.n + gap) /
    // epsilon.
    const auto &nodes = surface.nodes();
    for (unsigned int i = 0; i < nodes.size(); ++i)
      if (nodes[i].owned && nodes[i].active)
        {
          const auto                                &node = nodes[i];
          typename ContactLinearisation<dim>::Spring spring;
          spring.node       = &node;
          spring.stiffness  = node.mass / epsilon;
          spring.rest_force = node.mass * node.gap / epsilon;
          if (!multipliers.empty())
            spring.extra_force = node.mass * multipliers[i];
          linearisation.springs.push_back(spring);
        }
    linearisation.penalised    = true;
    linearisation.extra_forces = !multipliers.empty();
    linearisation.key          = {surface.active_set_signature(), epsilon};
  }

  template <int dim>
  PenaltyStrategy<dim>::PenaltyStrategy(const ContactParameters &parameters,
                                        const double             young_modulus,
                                        ConditionalOStream      &pcout)
    : parameters(parameters)
    , young_modulus(young_modulus)
    , pcout(pcout)
  {
  }

  template <int dim>
  std::string
  PenaltyStrategy<dim>::name() const
  {
    return "penalty";
  }

  template <int dim>
  void
  PenaltyStrategy<dim>::solve(NewtonDriver<dim> &newton,
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
  bool
  PenaltyStrategy<dim>::update_rule(const unsigned int,
                                    const ContactNode<dim> &,
                                    const double gap,
                                    const double) const
  {
    // The penetrating nodes, a gap counting as negative only beyond
    // round-off, so that a node grazing the obstacle does not flip.
    return (sign_rule ? gap : gap + touching_tolerance) < 0;
  }

  template <int dim>
  void
  PenaltyStrategy<dim>::linearise(
    const ContactSurface<dim> &surface,
    ContactLinearisation<dim> &linearisation) const
  {
    add_penalty_springs(surface, epsilon, {}, linearisation);
  }

  template <int dim>
  double
  PenaltyStrategy<dim>::complementarity_force(const unsigned int,
                                              const ContactNode<dim> &node,
                                              const double,
                                              const double,
                                              const double gap) const
  {
    return node.mass * std::max(0., 0. - gap / epsilon);
  }

  template <int dim>
  std::string
  PenaltyStrategy<dim>::break_cycle()
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
  PenaltyStrategy<dim>::cycle_broken() const
  {
    return sign_rule;
  }

  template <int dim>
  std::string
  PenaltyStrategy<dim>::failure_hint() const
  {
    return " is Contact/Penalty parameter too small?";
  }

  template <int dim>
  std::string
  PenaltyStrategy<dim>::stall_hint() const
  {
    return "the round-off of a stiff penalty: is Contact/Penalty parameter "
           "too small? ";
  }

  template <int dim>
  void
  PenaltyStrategy<dim>::report(StatisticsRow &row, ConditionalOStream &) const
  {
    row.add("penalty_parameter", epsilon);
  }

  template void
  add_penalty_springs(const ContactSurface<2> &,
                      const double,
                      const std::vector<double> &,
                      ContactLinearisation<2> &);
  template void
  add_penalty_springs(const ContactSurface<3> &,
                      const double,
                      const std::vector<double> &,
                      ContactLinearisation<3> &);
  template class PenaltyStrategy<2>;
  template class PenaltyStrategy<3>;
} // namespace signorini
