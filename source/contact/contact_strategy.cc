#include <signorini/contact/active_set_strategy.h>
#include <signorini/contact/augmented_lagrangian_strategy.h>
#include <signorini/contact/contact_strategy.h>
#include <signorini/contact/no_contact_strategy.h>
#include <signorini/contact/penalty_strategy.h>

namespace signorini
{
  template <int dim>
  std::unique_ptr<ContactStrategy<dim>>
  create_contact_strategy(const ContactParameters    &parameters,
                          const double                young_modulus,
                          dealii::ConditionalOStream &pcout)
  {
    switch (parameters.method)
      {
        case ContactParameters::Method::active_set:
          return std::make_unique<ActiveSetStrategy<dim>>(parameters,
                                                          young_modulus);
        case ContactParameters::Method::penalty:
          return std::make_unique<PenaltyStrategy<dim>>(parameters,
                                                        young_modulus,
                                                        pcout);
        case ContactParameters::Method::augmented_lagrangian:
          return std::make_unique<AugmentedLagrangianStrategy<dim>>(
            parameters, young_modulus, pcout);
        case ContactParameters::Method::none:
          return std::make_unique<NoContactStrategy<dim>>();
      }
    return nullptr;
  }

  template std::unique_ptr<ContactStrategy<2>>
  create_contact_strategy(const ContactParameters &,
                          const double,
                          dealii::ConditionalOStream &);
  template std::unique_ptr<ContactStrategy<3>>
  create_contact_strategy(const ContactParameters &,
                          const double,
                          dealii::ConditionalOStream &);
} // namespace signorini
