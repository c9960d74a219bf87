#include <signorini/contact/contact_law.h>
#include <signorini/contact/frictionless_law.h>

namespace signorini
{
  template <int dim>
  std::unique_ptr<ContactLaw<dim>>
  create_contact_law(const ContactParameters &)
  {
    return std::make_unique<FrictionlessLaw<dim>>();
  }

  template std::unique_ptr<ContactLaw<2>>
  create_contact_law(const ContactParameters &);
  template std::unique_ptr<ContactLaw<3>>
  create_contact_law(const ContactParameters &);
} // namespace signorini
