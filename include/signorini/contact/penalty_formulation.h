#ifndef signorini_contact_penalty_formulation_h
#define signorini_contact_penalty_formulation_h

#include <signorini/contact/contact_formulation.h>


namespace signorini
{
  /** The penalty compliance epsilon [mm/MPa] of Contact/Penalty parameter,
   * or, for 0, h_min / (10 E): a penalty ten times as stiff as the finest
   * cell. */
  double
  penalty_compliance(const ContactParameters &parameters,
                     const double             minimal_cell_diameter,
                     const double             young_modulus);

  /**
   * Contact/Method = penalty: the contact pressure is p = [penetration]_+ /
   * epsilon, the obstacle a Winkler layer of compliance epsilon [mm/MPa];
   * the penetration is epsilon times the local pressure. The law's
   * conditions on the nodes in contact (penetrating ones) become springs of
   * stiffness m / epsilon (condition_enforcement::add_springs). With
   * friction the stick is regularised as well: a sticking node is held to
   * its place at the step's start by tangential springs of the same
   * stiffness, its shear traction -s / epsilon for its slip s, and it
   * slips where that exceeds the friction bound (mu times its penalty
   * pressure, or Tresca's s). Remedies:
   * cycle breaking (every negative gap counts as penetrating), then penalty
   * continuation from a 1000 times softer penalty.
   */
  template <int dim>
  class PenaltyFormulation : public ContactFormulation<dim>
  {
  public:
    PenaltyFormulation(const ContactParameters    &parameters,
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
    break_cycle() override;

    bool
    cycle_broken() const override;

    std::string
    failure_hint() const override;

    std::string
    stall_hint() const override;

    void
    report(StatisticsRow              &row,
           dealii::ConditionalOStream &pcout) const override;

  private:
    const ContactParameters    &parameters;
    const double                young_modulus;
    dealii::ConditionalOStream &pcout;
    /** epsilon in use [mm/MPa]. */
    double epsilon = 0.;
    /** Gaps below this count as touching [mm]. */
    double touching_tolerance = 0.;
    /** Cycle breaking: every negative gap is penetrating. */
    bool sign_rule = false;
  };
} // namespace signorini

#endif
