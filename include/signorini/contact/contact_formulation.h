#ifndef signorini_contact_contact_formulation_h
#define signorini_contact_contact_formulation_h

#include <deal.II/base/conditional_ostream.h>

#include <signorini/base/statistics_row.h>
#include <signorini/contact/contact_law.h>
#include <signorini/contact/contact_parameters.h>
#include <signorini/contact/contact_surface.h>
#include <signorini/elasticity/system_additions.h>

#include <memory>
#include <string>
#include <vector>

namespace signorini
{
  template <int dim>
  class NewtonDriver;

  /**
   * How contact is enforced, whatever the ContactLaw: one implementation
   * per Contact/Method (active set, penalty, augmented Lagrangian, none).
   * A formulation owns its state and parameters, drives the semismooth
   * Newton iteration of NewtonDriver in its outer loop (continuation,
   * Uzawa, stiffening), gives the law each node's augmented normal
   * pressure, and turns the law's conditions into SystemAdditions
   * (constraint lines, or springs); around the iteration it applies its
   * remedies, and it adds its columns to the statistics.
   *
   * A new formulation is a file beside these and a line in
   * create_contact_formulation().
   */
  template <int dim>
  class ContactFormulation
  {
  public:
    virtual ~ContactFormulation() = default;

    /** The method's name in messages: "active set", "penalty", ... */
    virtual std::string
    name() const = 0;

    /** Solves the contact problem of cycle @p cycle by Newton iterations of
     * @p newton (whose state is the displacement of the previous cycle or
     * zero), with the formulation's remedies. Throws SolverFailure. */
    virtual void
    solve(NewtonDriver<dim> &newton, const unsigned int cycle) = 0;

    /** The augmented normal pressure [MPa] of node @p i, @p node, with the
     * deformed gap @p gap [mm] and the contact pressure @p pressure [MPa],
     * from which the law decides the node's state (with the formulation's
     * touching tolerance and cycle breaking). */
    virtual double
    state_pressure(const unsigned int      i,
                   const ContactNode<dim> &node,
                   const double            gap,
                   const double            pressure) const = 0;

    /** The augmented normal pressure [MPa] of node @p i from which the law
     * computes the force complementarity asks of it; the Newton residual
     * is that force's difference to the actual one. */
    virtual double
    residual_pressure(const unsigned int      i,
                      const ContactNode<dim> &node,
                      const double            gap,
                      const double            pressure) const = 0;

    /** The augmented tangential traction [MPa] of node @p i, @p node, from
     * its slip @p slip [mm] of the load step and the obstacle's tangential
     * traction @p traction [MPa] on it (vectors in its tangent plane), from
     * which a law with friction decides its state and its tangential
     * force. */
    virtual dealii::Tensor<1, dim>
    tangential_traction(const unsigned int            i,
                        const ContactNode<dim>       &node,
                        const dealii::Tensor<1, dim> &slip,
                        const dealii::Tensor<1, dim> &traction) const
    {
      (void)i;
      (void)node;
      (void)slip;
      return traction;
    }

    /** c [MPa/mm] in tangential_traction()'s zeta = q - c s of node @p i
     * (its derivative by the slip, for a law that linearises it). */
    virtual double
    tangential_stiffness(const unsigned int i) const
    {
      (void)i;
      return 0.;
    }

    /** The derivative of tangential_traction() by the obstacle's traction
     * q: 1 where zeta = q - c s, 0 where zeta = -c s (a penalty). */
    virtual double
    shear_weight() const
    {
      return 1.;
    }

    /** Adds the @p law's conditions and equations of the nodes of
     * @p surface in contact (with their @p tractions of the last state
     * update) to @p additions, as this formulation enforces them. */
    virtual void
    linearise(const ContactSurface<dim>            &surface,
              const ContactLaw<dim>                &law,
              const std::vector<NodeTraction<dim>> &tractions,
              SystemAdditions<dim>                 &additions) const = 0;

    /** Remedy for an active set that returned to an earlier one: changes
     * the update rule and describes the change, or returns an empty text
     * if there is no (further) remedy. */
    virtual std::string
    break_cycle()
    {
      return "";
    }

    /** Whether break_cycle() changed the rule on this cycle. */
    virtual bool
    cycle_broken() const
    {
      return false;
    }

    /** Appended to the message of a failed linear solve or a stalled
     * iteration: what the user may check about this method. */
    virtual std::string
    failure_hint() const
    {
      return "";
    }

    /** Inserted into the message of a stalled iteration before the
     * general questions. */
    virtual std::string
    stall_hint() const
    {
      return "";
    }

    /** Adds the formulation's columns to a statistics row, after the
     * active set's size, and prints them on @p pcout. */
    virtual void
    report(StatisticsRow &row, dealii::ConditionalOStream &pcout) const
    {
      (void)row;
      (void)pcout;
    }
  };

  /** The formulation of Contact/Method, for the mesh sizes and material of
   * a run: @p young_modulus [MPa]. */
  template <int dim>
  std::unique_ptr<ContactFormulation<dim>>
  create_contact_formulation(const ContactParameters    &parameters,
                             const double                young_modulus,
                             dealii::ConditionalOStream &pcout);
} // namespace signorini

#endif
