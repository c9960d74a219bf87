#include <signorini/contact/contact_law.h>
#include <signorini/contact/friction_law.h>
#include <signorini/contact/frictionless_law.h>

namespace signorini
{
  template <int dim>
  std::unique_ptr<ContactLaw<dim>>
  create_contact_law(const ContactParameters       &contact,
                     const FrictionParameters      &friction,
                     const ObstacleParameters<dim> &obstacles)
  {
    // The coefficients of the obstacles of the set, in its order (checked
    // by FrictionParameters::check()).
    (void)contact;
    if (!friction.any())
      return std::make_unique<FrictionlessLaw<dim>>();
    std::vector<double> coefficient, slip_bound;
    for (const auto &obstacle : obstacles.obstacles)
      {
        coefficient.push_back(friction.coefficient[obstacle.number - 1]);
        slip_bound.push_back(friction.slip_bound[obstacle.number - 1]);
      }
    return std::make_unique<FrictionLaw<dim>>(coefficient, slip_bound);
  }

  template std::unique_ptr<ContactLaw<2>>
  create_contact_law(const ContactParameters &,
                     const FrictionParameters &,
                     const ObstacleParameters<2> &);
  template std::unique_ptr<ContactLaw<3>>
  create_contact_law(const ContactParameters &,
                     const FrictionParameters &,
                     const ObstacleParameters<3> &);
} // namespace signorini
