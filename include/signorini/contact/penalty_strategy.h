#ifndef signorini_contact_penalty_strategy_h
#define signorini_contact_penalty_strategy_h

#include <signorini/contact/contact_strategy.h>

#include <vector>

namespace signorini
{
  /** The penalty compliance epsilon [mm/MPa] of Contact/Penalty parameter,
   * or, for 0, h_min / (10 E): a penalty ten times as stiff as the finest
   * cell. */
  double
  penalty_compliance(const ContactParameters &parameters,
                     const double             minimal_cell_diameter,
                     const double             young_modulus);

  /** Springs of stiffness m / @p epsilon on the owned active nodes of
   * @p surface, with the extra force m lambda_i of @p multipliers (if not
   * empty; indexed like the nodes). */
  template <int dim>
  void
  add_penalty_springs(const ContactSurface<dim> &surface,
                      const double               epsilon,
                      const std::vector<double> &multipliers,
                      ContactLinearisation<dim> &linearisation);

  /**
   * Contact/Method = penalty: the contact pressure is p = [penetration]_+ /
   * epsilon, the obstacle a Winkler layer of compliance epsilon [mm/MPa];
   * the penetration is epsilon times the local pressure. Active nodes
   * (penetrating ones) get a spring of stiffness m / epsilon. Remedies:
   * cycle breaking (every negative gap counts as penetrating), then penalty
   * continuation from a 1000 times softer penalty.
   */
  template <int dim>
  class PenaltyStrategy : public ContactStrategy<dim>
  {
  public:
    PenaltyStrategy(const ContactParameters    &parameters,
                    const double                young_modulus,
                    dealii::ConditionalOStream &pcout);

    std::string
    name() const override;

    void
    solve(NewtonDriver<dim> &newton, const unsigned int cycle) override;

    bool
    update_rule(const unsigned int      i,
                const ContactNode<dim> &node,
                const double            gap,
                const double            pressure) const override;

    void
    linearise(const ContactSurface<dim> &surface,
              ContactLinearisation<dim> &linearisation) const override;

    double
    complementarity_force(const unsigned int      i,
                          const ContactNode<dim> &node,
                          const double            force,
                          const double            pressure,
                          const double            gap) const override;

    std::string
    break_cycle() override;

    bool
    cycle_broken() const override;

    std::string
    failure_hint() const override;

    std::string
    stall_hint() const override;

    void
    report(StatisticsRow              &row,
           dealii::ConditionalOStream &pcout) const override;

  private:
    const ContactParameters    &parameters;
    const double                young_modulus;
    dealii::ConditionalOStream &pcout;
    /** epsilon in use [mm/MPa]. */
    double epsilon = 0.;
    /** Gaps below this count as touching [mm]. */
    double touching_tolerance = 0.;
    /** Cycle breaking: every negative gap is penetrating. */
    bool sign_rule = false;
  };
} // namespace signorini

#endif
