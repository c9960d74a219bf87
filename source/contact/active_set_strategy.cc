#include <signorini/contact/active_set_strategy.h>
#include <signorini/contact/newton_driver.h>

#include <algorithm>

namespace signorini
{
  using namespace dealii;

  template <int dim>
  ActiveSetStrategy<dim>::ActiveSetStrategy(const ContactParameters &parameters,
                                            const double young_modulus)
    : parameters(parameters)
    , young_modulus(young_modulus)
  {
  }

  template <int dim>
  std::string
  ActiveSetStrategy<dim>::name() const
  {
    return "active set";
  }

  template <int dim>
  void
  ActiveSetStrategy<dim>::solve(NewtonDriver<dim> &newton,
                                const unsigned int cycle)
  {
    // c ~ E / h: the stiffness with which a node resists a local
    // penetration on this mesh.
    complementarity_constant = parameters.complementarity_constant > 0 ?
                                 parameters.complementarity_constant :
                                 young_modulus / newton.minimal_cell_diameter();
    touching_tolerance       = newton.contact_surface().touching_tolerance();
    sign_rule                = false;
    newton.initialize_active_set();
    newton.iterate(cycle);
  }

  template <int dim>
  bool
  ActiveSetStrategy<dim>::update_rule(const unsigned int,
                                      const ContactNode<dim> &node,
                                      const double            gap,
                                      const double            pressure) const
  {
    // The primal-dual rule pressure - c x gap > 0, with a gap counted as
    // negative only beyond round-off, so that a node grazing the obstacle
    // does not flip.
    const double shifted = gap + touching_tolerance;
    if (sign_rule)
      return node.active ? pressure > 0 : shifted < 0;
    return pressure - complementarity_constant * shifted > 0;
  }

  template <int dim>
  void
  ActiveSetStrategy<dim>::linearise(
    const ContactSurface<dim> &surface,
    ContactLinearisation<dim> &linearisation) const
  {
    for (const auto &node : surface.nodes())
      if (node.active)
        linearisation.held.push_back(&node);
    linearisation.key           = {surface.active_set_signature(), 0.};
    linearisation.local_changes = true;
  }

  template <int dim>
  double
  ActiveSetStrategy<dim>::complementarity_force(const unsigned int,
                                                const ContactNode<dim> &node,
                                                const double,
                                                const double pressure,
                                                const double gap) const
  {
    return node.mass * std::max(0., pressure - complementarity_constant * gap);
  }

  template <int dim>
  std::string
  ActiveSetStrategy<dim>::break_cycle()
  {
    // The rule with a c that lets round-off decide (too small: the noise of
    // the pressure; too large: the touching tolerance) gives way to the
    // signs alone.
    if (sign_rule)
      return "";
    sign_rule = true;
    return "the c-free update (release where the pressure is negative, add "
           "where the gap is)";
  }

  template <int dim>
  bool
  ActiveSetStrategy<dim>::cycle_broken() const
  {
    return sign_rule;
  }

  template class ActiveSetStrategy<2>;
  template class ActiveSetStrategy<3>;
} // namespace signorini
