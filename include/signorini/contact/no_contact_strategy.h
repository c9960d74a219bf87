#ifndef signorini_contact_no_contact_strategy_h
#define signorini_contact_no_contact_strategy_h

#include <signorini/contact/contact_strategy.h>

namespace signorini
{
  /**
   * Contact/Method = none: linear elasticity in one solve; the obstacle is
   * ignored (its gap is still reported).
   */
  template <int dim>
  class NoContactStrategy : public ContactStrategy<dim>
  {
  public:
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
  };
} // namespace signorini

#endif
