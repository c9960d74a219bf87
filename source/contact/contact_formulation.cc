#include <signorini/contact/active_set_formulation.h>
#include <signorini/contact/augmented_lagrangian_formulation.h>
#include <signorini/contact/contact_formulation.h>
#include <signorini/contact/no_contact_formulation.h>
#include <signorini/contact/penalty_formulation.h>

namespace signorini
{
  template <int dim>
  std::unique_ptr<ContactFormulation<dim>>
  create_contact_formulation(const ContactParameters    &parameters,
                             const double                young_modulus,
                             dealii::ConditionalOStream &pcout)
  {
    switch (parameters.method)
      {
        case ContactParameters::Method::active_set:
          return std::make_unique<ActiveSetFormulation<dim>>(parameters,
                                                             young_modulus);
        case ContactParameters::Method::penalty:
          return std::make_unique<PenaltyFormulation<dim>>(parameters,
                                                           young_modulus,
                                                           pcout);
        case ContactParameters::Method::augmented_lagrangian:
          return std::make_unique<AugmentedLagrangianFormulation<dim>>(
            parameters, young_modulus, pcout);
        case ContactParameters::Method::none:
          return std::make_unique<NoContactFormulation<dim>>();
      }
    return nullptr;
  }

  template std::unique_ptr<ContactFormulation<2>>
  create_contact_formulation(const ContactParameters &,
                             const double,
                             dealii::ConditionalOStream &);
  template std::unique_ptr<ContactFormulation<3>>
  create_contact_formulation(const ContactParameters &,
                             const double,
                             dealii::ConditionalOStream &);
} // namespace signorini
