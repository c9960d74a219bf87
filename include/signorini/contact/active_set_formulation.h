#ifndef signorini_contact_active_set_formulation_h
#define signorini_contact_active_set_formulation_h

#include <signorini/contact/contact_formulation.h>

namespace signorini
{
  /**
   * Contact/Method = active set: the primal-dual active set method
   * (semismooth Newton) with a lumped contact-boundary mass. The law's
   * conditions on the nodes in contact are held exactly (constraint lines:
   * exact non-penetration); the law decides from the augmented pressure
   * pressure - c x gap. Remedy for cycling: the c-free update (release
   * where the pressure is negative, add where the gap is).
   */
  template <int dim>
  class ActiveSetFormulation : public ContactFormulation<dim>
  {
  public:
    ActiveSetFormulation(const ContactParameters &parameters,
                         const double             young_modulus);

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

    dealii::Tensor<1, dim>
    tangential_traction(const unsigned int            i,
                        const ContactNode<dim>       &node,
                        const dealii::Tensor<1, dim> &slip,
                        const dealii::Tensor<1, dim> &traction) const override;

    double
    tangential_stiffness(const unsigned int i) const override;

    std::string
    break_cycle() override;

    bool
    cycle_broken() const override;

  private:
    const ContactParameters &parameters;
    const double             young_modulus;
    /** c [MPa/mm] of this cycle's mesh. */
    double complementarity_constant = 0.;
    /** Gaps below this count as touching [mm]. */
    double touching_tolerance = 0.;
    /** Cycle breaking: update by the signs of pressure and gap alone, for
     * the rest of the cycle. */
    bool sign_rule = false;
  };
} // namespace signorini

#endif
