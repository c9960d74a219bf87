#include <signorini/contact/newton_driver.h>
#include <signorini/contact/no_contact_strategy.h>

namespace signorini
{
  template <int dim>
  std::string
  NoContactStrategy<dim>::name() const
  {
    return "none";
  }

  template <int dim>
  void
  NoContactStrategy<dim>::solve(NewtonDriver<dim> &newton, const unsigned int)
  {
    newton.solve_once();
  }

  template <int dim>
  bool
  NoContactStrategy<dim>::update_rule(const unsigned int,
                                      const ContactNode<dim> &,
                                      const double,
                                      const double) const
  {
    return false;
  }

  template <int dim>
  void
  NoContactStrategy<dim>::linearise(
    const ContactSurface<dim> &surface,
    ContactLinearisation<dim> &linearisation) const
  {
    linearisation.key = {surface.active_set_signature(), 0.};
  }

  template <int dim>
  double
  NoContactStrategy<dim>::complementarity_force(const unsigned int,
                                                const ContactNode<dim> &,
                                                const double force,
                                                const double,
                                                const double) const
  {
    return force;
  }

  template class NoContactStrategy<2>;
  template class NoContactStrategy<3>;
} // namespace signorini
