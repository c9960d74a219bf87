#include <signorini/contact/frictionless_law.h>

#include <algorithm>

namespace signorini
{
  template <int dim>
  std::string
  FrictionlessLaw<dim>::name() const
  {
    return "frictionless";
  }

  template <int dim>
  NodeState
  FrictionlessLaw<dim>::state(const ContactNode<dim> &,
                              const NodeTraction<dim> &traction) const
  {
    return traction.sigma > 0 ? NodeState::closed : NodeState::open;
  }

  template <int dim>
  double
  FrictionlessLaw<dim>::complementarity_force(
    const ContactNode<dim>  &node,
    const NodeTraction<dim> &traction) const
  {
    return node.mass * std::max(0., traction.sigma);
  }

  template <int dim>
  void
  FrictionlessLaw<dim>::conditions(const ContactNode<dim> &node,
                                   const NodeTraction<dim> &,
                                   std::vector<NodeCondition<dim>> &conditions,
                                   std::vector<NodeEquation<dim>> &) const
  {
    if (!node.in_contact())
      return;
    unsigned int along = 0;
    while (node.dofs[along] != node.scalar_dof)
      ++along;
    conditions.push_back({node.normal, -node.gap, along});
  }

  template class FrictionlessLaw<2>;
  template class FrictionlessLaw<3>;
} // namespace signorini
