#ifndef signorini_contact_contact_strategy_h
#define signorini_contact_contact_strategy_h

#include <deal.II/base/conditional_ostream.h>

#include <signorini/contact/contact_linearisation.h>
#include <signorini/contact/contact_parameters.h>
#include <signorini/contact/contact_surface.h>
#include <signorini/output/run_record.h>

#include <memory>
#include <string>

namespace signorini
{
  template <int dim>
  class NewtonDriver;

  /**
   * How contact is enforced: one implementation per Contact/Method (active
   * set, penalty, augmented Lagrangian, none). A strategy owns its state and
   * parameters and decides, for the semismooth Newton iteration of
   * NewtonDriver, which nodes are active, what the active nodes add to the
   * elastic operator, and what contact force complementarity asks of each
   * node; around the iteration it applies its remedies, and it adds its
   * columns to the statistics.
   */
  template <int dim>
  class ContactStrategy
  {
  public:
    virtual ~ContactStrategy() = default;

    /** The method's name in messages: "active set", "penalty", ... */
    virtual std::string
    name() const = 0;

    /** Solves the contact problem of cycle @p cycle by Newton iterations of
     * @p newton (whose state is the displacement of the previous cycle or
     * zero), with the strategy's remedies. Throws SolverFailure. */
    virtual void
    solve(NewtonDriver<dim> &newton, const unsigned int cycle) = 0;

    /** Whether node @p i, @p node, with the deformed gap @p gap [mm] and
     * the contact pressure @p pressure [MPa], is active. */
    virtual bool
    update_rule(const unsigned int      i,
                const ContactNode<dim> &node,
                const double            gap,
                const double            pressure) const = 0;

    /** What the active nodes of @p surface add to the elastic operator. */
    virtual void
    linearise(const ContactSurface<dim> &surface,
              ContactLinearisation<dim> &linearisation) const = 0;

    /** The nodal contact force [N] that complementarity asks of the owned
     * node @p i with the deformed gap @p gap and the pressure @p pressure;
     * the Newton residual is its difference to the actual force. */
    virtual double
    complementarity_force(const unsigned int      i,
                          const ContactNode<dim> &node,
                          const double            force,
                          const double            pressure,
                          const double            gap) const = 0;

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

    /** Adds the strategy's columns to a statistics row, after the active
     * set's size, and prints them on @p pcout. */
    virtual void
    report(StatisticsRow &row, dealii::ConditionalOStream &pcout) const
    {
      (void)row;
      (void)pcout;
    }
  };

  /** The strategy of Contact/Method, for the mesh sizes and material of a
   * run: @p young_modulus [MPa]. */
  template <int dim>
  std::unique_ptr<ContactStrategy<dim>>
  create_contact_strategy(const ContactParameters    &parameters,
                          const double                young_modulus,
                          dealii::ConditionalOStream &pcout);
} // namespace signorini

#endif
