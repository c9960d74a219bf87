#ifndef signorini_contact_frictionless_law_h
#define signorini_contact_frictionless_law_h

#include <signorini/contact/contact_law.h>

namespace signorini
{
  /**
   * Frictionless contact: u.n <= gap, sigma_n <= 0, sigma_n (u.n - gap) =
   * 0. A node is closed where its augmented pressure is positive, held on
   * the obstacle along its normal (n.u = -gap), free to slide along it; the
   * complementarity function is m [sigma]_+.
   */
  template <int dim>
  class FrictionlessLaw : public ContactLaw<dim>
  {
  public:
    std::string
    name() const override;

    NodeState
    state(const ContactNode<dim>  &node,
          const NodeTraction<dim> &traction) const override;

    double
    complementarity_force(const ContactNode<dim>  &node,
                          const NodeTraction<dim> &traction) const override;

    void
    conditions(const ContactNode<dim>          &node,
               const NodeTraction<dim>         &traction,
               std::vector<NodeCondition<dim>> &conditions,
               std::vector<NodeEquation<dim>>  &equations) const override;
  };
} // namespace signorini

#endif
