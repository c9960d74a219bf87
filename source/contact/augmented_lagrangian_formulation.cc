#include <deal.II/base/mpi.h>

#include <signorini/base/failures.h>
#include <signorini/base/text.h>
#include <signorini/contact/augmented_lagrangian_formulation.h>
#include <signorini/contact/condition_enforcement.h>
#include <signorini/contact/newton_driver.h>
#include <signorini/contact/penalty_formulation.h>

#include <algorithm>
#include <cmath>

namespace signorini
{
  using namespace dealii;

  namespace
  {
    /** The obstacle's shear traction [MPa] on @p node of @p newton's
     * state. */
    template <int dim>
    Tensor<1, dim>
    shear(const NewtonDriver<dim> &newton, const ContactNode<dim> &node)
    {
      Tensor<1, dim> q;
      for (unsigned int d = 0; d < dim; ++d)
        q[d] = newton.tangential_traction()(node.dofs[d]);
      return q;
    }
  } // namespace

  template <int dim>
  AugmentedLagrangianFormulation<dim>::AugmentedLagrangianFormulation(
    const ContactParameters &parameters,
    const double             young_modulus,
    ConditionalOStream      &pcout)
    : parameters(parameters)
    , young_modulus(young_modulus)
    , pcout(pcout)
  {
  }

  template <int dim>
  std::string
  AugmentedLagrangianFormulation<dim>::name() const
  {
    return "augmented lagrangian";
  }

  template <int dim>
  void
  AugmentedLagrangianFormulation<dim>::solve(NewtonDriver<dim> &newton,
                                             const unsigned int cycle)
  {
    epsilon            = penalty_compliance(parameters,
                                 newton.minimal_cell_diameter(),
                                 young_modulus);
    touching_tolerance = newton.contact_surface().touching_tolerance();
    multiplier_updates = 0;
    // The multipliers start from the previous cycle's pressure (zero on
    // cycle 0).
    const auto &nodes = newton.contact_surface().nodes();
    multipliers.assign(nodes.size(), 0.);
    for (unsigned int i = 0; i < nodes.size(); ++i)
      if (nodes[i].owned)
        multipliers[i] =
          std::max(0.,
                   static_cast<double>(newton.pressure()(nodes[i].scalar_dof)));
    // With friction, the shear tractions from the last load step's (zero
    // on a new mesh).
    tangential_multipliers.clear();
    if (newton.tangential_traction().size() > 0)
      {
        tangential_multipliers.assign(nodes.size(), Tensor<1, dim>());
        for (unsigned int i = 0; i < nodes.size(); ++i)
          if (nodes[i].owned)
            tangential_multipliers[i] = shear(newton, nodes[i]);
      }
    newton.initialize_active_set();
    double previous_change = 0.;
    for (;;)
      {
        newton.iterate(cycle);
        const double change = update_multipliers(newton);
        ++multiplier_updates;
        if (newton.verbose_output())
          pcout << "   multiplier update " << multiplier_updates
                << ": relative change " << number(change) << std::endl;
        if (change <= parameters.multiplier_tolerance)
          return;
        if (multiplier_updates >= parameters.max_updates)
          throw SolverFailure(
            exit_status::multipliers_slow,
            "contact solver (augmented lagrangian): the multipliers still "
            "change by " +
              number(change) + " after " + std::to_string(multiplier_updates) +
              " updates on cycle " + std::to_string(cycle) +
              " (Contact/Maximum updates; a smaller Contact/Penalty "
              "parameter converges faster)");
        // The multipliers converge by about r / (1 + r) per update, r =
        // epsilon E / h: if they shrink by less than half, the penalty is too
        // soft for this mesh. Stiffen it tenfold (one more factorisation).
        const double rate = previous_change > 0 ? change / previous_change : 0;
        previous_change   = change;
        if (parameters.remedies && rate > 0.5)
          {
            epsilon /= 10.;
            previous_change = 0.;
            pcout << "   remedy: the multipliers change by a factor of "
                  << number(rate) << " per update on update "
                  << multiplier_updates
                  << "; penalty stiffened to epsilon = " << number(epsilon)
                  << std::endl;
          }
      }
  }


  template <int dim>
  double
  AugmentedLagrangianFormulation<dim>::update_multipliers(
    const NewtonDriver<dim> &newton)
  {
    // Uzawa: the multiplier takes the pressure of the inner solution,
    // [lambda - gap / epsilon]_+, which differs from lambda by the
    // penetration / epsilon.
    double      change = 0., largest = 0.;
    const auto &nodes = newton.contact_surface().nodes();
    for (unsigned int i = 0; i < nodes.size(); ++i)
      if (nodes[i].owned)
        {
          const double p = std::max(
            0., static_cast<double>(newton.pressure()(nodes[i].scalar_dof)));
          change         = std::max(change, std::abs(p - multipliers[i]));
          largest        = std::max(largest, p);
          multipliers[i] = p;
          if (!tangential_multipliers.empty())
            {
              const auto q = shear(newton, nodes[i]);
              change = std::max(change, (q - tangential_multipliers[i]).norm());
              tangential_multipliers[i] = q;
            }
        }
    change  = Utilities::MPI::max(change, newton.mpi_communicator());
    largest = Utilities::MPI::max(largest, newton.mpi_communicator());
    return largest > 0 ? change / largest : 0.;
  }

  template <int dim>
  double
  AugmentedLagrangianFormulation<dim>::state_pressure(const unsigned int i,
                                                      const ContactNode<dim> &,
                                                      const double gap,
                                                      const double) const
  {
    // The pressure multiplier - gap / epsilon, a gap counting as negative
    // only beyond round-off.
    return multipliers[i] - (gap + touching_tolerance) / epsilon;
  }

  template <int dim>
  double
  AugmentedLagrangianFormulation<dim>::residual_pressure(
    const unsigned int i,
    const ContactNode<dim> &,
    const double gap,
    const double) const
  {
    return multipliers[i] - gap / epsilon;
  }

  template <int dim>
  void
  AugmentedLagrangianFormulation<dim>::linearise(
    const ContactSurface<dim>            &surface,
    const ContactLaw<dim>                &law,
    const std::vector<NodeTraction<dim>> &tractions,
    SystemAdditions<dim>                 &additions) const
  {
    condition_enforcement::add_springs(surface,
                                       law,
                                       tractions,
                                       epsilon,
                                       multipliers,
                                       tangential_multipliers,
                                       additions);
    additions.key = {surface.active_set_signature(), epsilon};
  }

  template <int dim>
  Tensor<1, dim>
  AugmentedLagrangianFormulation<dim>::tangential_traction(
    const unsigned int i,
    const ContactNode<dim> &,
    const Tensor<1, dim> &slip,
    const Tensor<1, dim> &) const
  {
    // The multiplier and the tangential springs' traction.
    return (tangential_multipliers.empty() ? Tensor<1, dim>() :
                                             tangential_multipliers[i]) -
           tangential_stiffness(i) * slip;
  }

  template <int dim>
  double
  AugmentedLagrangianFormulation<dim>::tangential_stiffness(
    const unsigned int) const
  {
    return 1. / epsilon;
  }

  template <int dim>
  double
  AugmentedLagrangianFormulation<dim>::shear_weight() const
  {
    return 0.;
  }

  template <int dim>
  std::string
  AugmentedLagrangianFormulation<dim>::failure_hint() const
  {
    return " is Contact/Penalty parameter too small?";
  }

  template <int dim>
  void
  AugmentedLagrangianFormulation<dim>::report(StatisticsRow      &row,
                                              ConditionalOStream &pcout) const
  {
    row.add_count("multiplier_updates", multiplier_updates);
    row.add("penalty_parameter", epsilon);
    pcout << "   " << multiplier_updates << " multiplier updates, "
          << "penalty parameter " << epsilon << std::endl;
  }

  template class AugmentedLagrangianFormulation<2>;
  template class AugmentedLagrangianFormulation<3>;
} // namespace signorini
