#ifndef signorini_contact_augmented_lagrangian_formulation_h
#define signorini_contact_augmented_lagrangian_formulation_h

#include <signorini/contact/contact_formulation.h>

#include <vector>

namespace signorini
{
  /**
   * Contact/Method = augmented lagrangian: Uzawa updates of a multiplier
   * lambda (the contact pressure) around a penalty of compliance epsilon.
   * Each inner problem has the pressure [lambda - gap / epsilon]_+ and is
   * solved by semismooth Newton; lambda then takes that pressure. At
   * convergence the penetration vanishes, without the penalty's
   * ill-conditioning. Remedy: multipliers that shrink by less than half per
   * update get a ten times stiffer penalty.
   */
  template <int dim>
  class AugmentedLagrangianFormulation : public ContactFormulation<dim>
  {
  public:
    AugmentedLagrangianFormulation(const ContactParameters    &parameters,
                                   const double                young_modulus,
                                   dealii::ConditionalOStream &pcout);

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

    std::string
    failure_hint() const override;

    void
    report(StatisticsRow              &row,
           dealii::ConditionalOStream &pcout) const override;

  private:
    /** Sets the multipliers to the current pressure; returns the largest
     * change relative to the largest pressure. */
    double
    update_multipliers(const NewtonDriver<dim> &newton);

    const ContactParameters    &parameters;
    const double                young_modulus;
    dealii::ConditionalOStream &pcout;
    /** epsilon in use [mm/MPa]. */
    double epsilon = 0.;
    /** Gaps below this count as touching [mm]. */
    double touching_tolerance = 0.;
    /** lambda [MPa] of each contact node (owned nodes; zero elsewhere). */
    std::vector<double> multipliers;
    unsigned int        multiplier_updates = 0;
  };
} // namespace signorini

#endif
