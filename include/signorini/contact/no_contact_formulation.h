#ifndef signorini_contact_no_contact_formulation_h
#define signorini_contact_no_contact_formulation_h

#include <signorini/contact/contact_formulation.h>

namespace signorini
{
  /**
   * Contact/Method = none: linear elasticity in one solve; the obstacle is
   * ignored (its gap is still reported).
   */
  template <int dim>
  class NoContactFormulation : public ContactFormulation<dim>
  {
  public:
    std::string
    name() const override;

    void
    solve(NewtonDriver<dim> &newton, const unsigned int cycle) override;

    double
    state_pressure(const unsigned int      i,
                   const ContactNode<dim> &node,
                   const double            gap,
                   const double            pressure) const override;

    double
    residual_pressure(const unsigned int      i,
                      const ContactNode<dim> &node,
                      const double            gap,
                      const double            pressure) const override;

    void
    linearise(const ContactSurface<dim>            &surface,
              const ContactLaw<dim>                &law,
              const std::vector<NodeTraction<dim>> &tractions,
              SystemAdditions<dim>                 &additions) const override;
  };
} // namespace signorini

#endif
