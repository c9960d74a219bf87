#include <signorini/problem/contact_problem.h>

#include <cmath>
#include <cstdint>
#include <limits>

namespace signorini
{
  using namespace dealii;

  template <int dim>
  double
  ContactProblem<dim>::deformed_gap(const ContactNode<dim> &node) const
  {
    return solution(node.dofs[dim - 1]) + node.gap;
  }

  template <int dim>
  bool
  ContactProblem<dim>::update_rule(const ContactNode<dim> &node) const
  {
    // Penalty: the penetrating nodes. Augmented Lagrangian: where the
    // pressure multiplier - gap / epsilon is positive. Active set: the
    // primal-dual rule pressure - c x gap > 0. Each way, a gap counts as
    // negative only beyond round-off, so that a node grazing the obstacle
    // does not flip.
    const double gap = deformed_gap(node) + touching_tolerance;
    if (parameters.contact.method == ContactParameters::Method::penalty)
      return (sign_rule ? deformed_gap(node) : gap) < 0;
    if (parameters.contact.method ==
        ContactParameters::Method::augmented_lagrangian)
      return gap < penalty_parameter * node.multiplier;
    if (sign_rule)
      return node.active ? pressure(node.dofs[dim - 1]) > 0 : gap < 0;
    return pressure(node.dofs[dim - 1]) - complementarity_constant * gap > 0;
  }

  template <int dim>
  void
  ContactProblem<dim>::initialize_active_set()
  {
    // From the previous cycle's displacement and pressure (zero on cycle 0),
    // with the touching and penetrating nodes active from the start, so that
    // a body held only by the obstacle is supported in the first solve.
    for (auto &node : contact_nodes)
      node.active =
        deformed_gap(node) <= touching_tolerance || update_rule(node);
  }

  template <int dim>
  unsigned int
  ContactProblem<dim>::activate_first_contact()
  {
    // After a solve with no contact at all, the displacement is proportional
    // to the load: scaled by theta_i = gap_i / (-u_i), node i just touches.
    // The nodes with the smallest theta are where contact begins; starting
    // from them, rather than from every penetrating node, spares the
    // iteration from releasing the wrongly active ones one by one.
    double theta_min = std::numeric_limits<double>::max();
    for (const auto &node : contact_nodes)
      {
        const double u = solution(node.dofs[dim - 1]);
        if (u < 0)
          theta_min = std::min(theta_min, node.gap / -u);
      }
    theta_min = Utilities::MPI::min(theta_min, mpi_communicator);
    if (theta_min >= 1.)
      return 0; // nothing penetrates: the contact-free solution stands

    unsigned int changes = 0;
    for (auto &node : contact_nodes)
      {
        const double u = solution(node.dofs[dim - 1]);
        node.active    = u < 0 && node.gap / -u <= theta_min * (1. + 1e-6);
        changes += node.owned && node.active ? 1 : 0;
      }
    return Utilities::MPI::sum(changes, mpi_communicator);
  }

  template <int dim>
  double
  ContactProblem<dim>::compute_contact_forces()
  {
    TimerOutput::Scope t(timer, "Active set: contact forces");
    assemble_residual();

    // The residual K u - f at a free vertical contact dof is the obstacle's
    // nodal force lambda_i; the pressure is lambda_i / m_i. The nonlinear
    // residual combines the force balance at all other free dofs with the
    // complementarity function of the method at the contact dofs.
    const auto method = parameters.contact.method;
    const bool penalty =
      method == ContactParameters::Method::penalty ||
      method == ContactParameters::Method::augmented_lagrangian;
    const double epsilon = penalty_parameter;

    TrilinosWrappers::MPI::Vector owned_pressure(locally_owned_dofs,
                                                 mpi_communicator);
    TrilinosWrappers::MPI::Vector balance(residual);
    double                        complementarity = 0., contact_force = 0.;
    for (const auto &node : contact_nodes)
      if (node.owned)
        {
          const auto   i      = node.dofs[dim - 1];
          const double lambda = residual(i);
          const double p      = node.mass > 0 ? lambda / node.mass : 0.;
          const double s      = deformed_gap(node);
          const double expected =
            method == ContactParameters::Method::none ?
              lambda :
            penalty ?
              node.mass * std::max(0., node.multiplier - s / epsilon) :
              node.mass * std::max(0., p - complementarity_constant * s);
          owned_pressure(i) = p;
          balance(i)        = 0.;
          complementarity += (lambda - expected) * (lambda - expected);
          contact_force += lambda * lambda;
        }
    owned_pressure.compress(VectorOperation::insert);
    balance.compress(VectorOperation::insert);
    pressure = owned_pressure;

    const double balance_norm = balance.l2_norm();
    complementarity    = Utilities::MPI::sum(complementarity, mpi_communicator);
    contact_force      = Utilities::MPI::sum(contact_force, mpi_communicator);
    const double scale = load.l2_norm() + std::sqrt(contact_force);
    return std::sqrt(balance_norm * balance_norm + complementarity) /
           (scale > 0 ? scale : 1.);
  }

  template <int dim>
  double
  ContactProblem<dim>::update_multipliers()
  {
    // Uzawa: the multiplier takes the pressure of the inner solution,
    // [lambda - gap / epsilon]_+, which differs from lambda by the
    // penetration / epsilon.
    double change = 0., largest = 0.;
    for (auto &node : contact_nodes)
      if (node.owned)
        {
          const double p =
            std::max(0., static_cast<double>(pressure(node.dofs[dim - 1])));
          change          = std::max(change, std::abs(p - node.multiplier));
          largest         = std::max(largest, p);
          node.multiplier = p;
        }
    change  = Utilities::MPI::max(change, mpi_communicator);
    largest = Utilities::MPI::max(largest, mpi_communicator);
    return largest > 0 ? change / largest : 0.;
  }

  template <int dim>
  unsigned int
  ContactProblem<dim>::update_active_set()
  {
    TimerOutput::Scope t(timer, "Active set: update");
    unsigned int       changes = 0;
    for (auto &node : contact_nodes)
      {
        const bool active = update_rule(node);
        if (node.owned && active != node.active)
          ++changes;
        node.active = active;
      }
    return Utilities::MPI::sum(changes, mpi_communicator);
  }

  template <int dim>
  std::pair<unsigned int, std::size_t>
  ContactProblem<dim>::active_set_signature() const
  {
    unsigned int  count = 0;
    std::uint64_t hash  = 0;
    for (const auto &node : contact_nodes)
      if (node.owned && node.active)
        {
          ++count;
          std::uint64_t z = node.dofs[dim - 1] + 0x9e3779b97f4a7c15ULL;
          z               = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
          z               = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
          hash += z ^ (z >> 31);
        }
    // Sums of per-process hashes: the same on every process.
    return {Utilities::MPI::sum(count, mpi_communicator),
            static_cast<std::size_t>(Utilities::MPI::sum(
              static_cast<unsigned long>(hash), mpi_communicator))};
  }

  template double
  ContactProblem<2>::deformed_gap(const ContactNode<2> &) const;
  template double
  ContactProblem<3>::deformed_gap(const ContactNode<3> &) const;
  template bool
  ContactProblem<2>::update_rule(const ContactNode<2> &) const;
  template bool
  ContactProblem<3>::update_rule(const ContactNode<3> &) const;
  template unsigned int
  ContactProblem<2>::activate_first_contact();
  template unsigned int
  ContactProblem<3>::activate_first_contact();
  template void
  ContactProblem<2>::initialize_active_set();
  template void
  ContactProblem<3>::initialize_active_set();
  template double
  ContactProblem<2>::compute_contact_forces();
  template double
  ContactProblem<3>::compute_contact_forces();
  template double
  ContactProblem<2>::update_multipliers();
  template double
  ContactProblem<3>::update_multipliers();
  template unsigned int
  ContactProblem<2>::update_active_set();
  template unsigned int
  ContactProblem<3>::update_active_set();
  template std::pair<unsigned int, std::size_t>
  ContactProblem<2>::active_set_signature() const;
  template std::pair<unsigned int, std::size_t>
  ContactProblem<3>::active_set_signature() const;
} // namespace signorini
