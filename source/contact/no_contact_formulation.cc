#include <signorini/contact/newton_driver.h>
#include <signorini/contact/no_contact_formulation.h>

#include <limits>

namespace signorini
{
  template <int dim>
  std::string
  NoContactFormulation<dim>::name() const
  {
    return "none";
  }

  template <int dim>
  void
  NoContactFormulation<dim>::solve(NewtonDriver<dim> &newton,
                                   const unsigned int)
  {
    newton.solve_once();
  }

  template <int dim>
  double
  NoContactFormulation<dim>::state_pressure(const unsigned int,
                                            const ContactNode<dim> &,
                                            const double,
                                            const double) const
  {
    // No node comes into contact.
    return -std::numeric_limits<double>::infinity();
  }

  template <int dim>
  double
  NoContactFormulation<dim>::residual_pressure(const unsigned int,
                                               const ContactNode<dim> &,
                                               const double,
                                               const double pressure) const
  {
    // Nothing is asked: the one solve's residual is not used.
    return pressure;
  }

  template <int dim>
  void
  NoContactFormulation<dim>::linearise(const ContactSurface<dim> &surface,
                                       const ContactLaw<dim> &,
                                       const std::vector<NodeTraction<dim>> &,
                                       SystemAdditions<dim> &additions) const
  {
    additions.key = {surface.active_set_signature(), 0.};
  }

  template class NoContactFormulation<2>;
  template class NoContactFormulation<3>;
} // namespace signorini
