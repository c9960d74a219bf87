#ifndef signorini_contact_active_set_strategy_h
#define signorini_contact_active_set_strategy_h

#include <signorini/contact/contact_strategy.h>

namespace signorini
{
  /**
   * Contact/Method = active set: the primal-dual active set method
   * (semismooth Newton) with a lumped contact-boundary mass. Active nodes are
   * held on the obstacle (exact non-penetration); a node is active where
   * pressure - c x gap > 0. Remedy for cycling: the c-free update (release
   * where the pressure is negative, add where the gap is).
   */
  template <int dim>
  class ActiveSetStrategy : public ContactStrategy<dim>
  {
  public:
    ActiveSetStrategy(const ContactParameters &parameters,
                      const double             young_modulus);

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

  private:
    const ContactParameters &parameters;
    const double             young_modulus;
    /** c [MPa/mm] of this cycle's mesh. */
    double complementarity_constant = 0.;
    /** Gaps below this count as touching [mm]. */
    double touching_tolerance = 0.;
    /** Cycle breaking: update by the signs of pressure and gap alone, for
     * the rest of the cycle. */
    bool sign_rule = false;
  };
} // namespace signorini

#endif
