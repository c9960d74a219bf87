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
   * ill-conditioning. With friction, a tangential multiplier lambda_t
   * (the shear traction) beside it: a node's augmented shear traction is
   * lambda_t - s / epsilon for its slip s, and lambda_t takes the shear of
   * the inner solution, so that the stick becomes exact as the updates
   * converge. Remedy: multipliers that shrink by less than half per
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

    dealii::Tensor<1, dim>
    tangential_traction(const unsigned int            i,
                        const ContactNode<dim>       &node,
                        const dealii::Tensor<1, dim> &slip,
                        const dealii::Tensor<1, dim> &traction) const override;

    double
    tangential_stiffness(const unsigned int i) const override;

    double
    shear_weight() const override;

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
    /** Sets the multipliers to the current pressure (and shear traction);
     * returns the largest change relative to the largest pressure. */
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
    /** lambda_t [MPa] of each contact node, with friction (else empty). */
    std::vector<dealii::Tensor<1, dim>> tangential_multipliers;
    unsigned int                        multiplier_updates = 0;
  };
} // namespace signorini

#endif
