#include <signorini/contact/active_set_formulation.h>
#include <signorini/contact/condition_enforcement.h>
#include <signorini/contact/newton_driver.h>

#include <algorithm>

namespace signorini
{
  using namespace dealii;

  template <int dim>
  ActiveSetFormulation<dim>::ActiveSetFormulation(
    const ContactParameters &parameters,
    const double             young_modulus)
    : parameters(parameters)
    , young_modulus(young_modulus)
  {
  }

  template <int dim>
  std::string
  ActiveSetFormulation<dim>::name() const
  {
    return "active set";
  }

  template <int dim>
  void
  ActiveSetFormulation<dim>::solve(NewtonDriver<dim> &newton,
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
  double
  ActiveSetFormulation<dim>::state_pressure(const unsigned int,
                                            const ContactNode<dim> &node,
                                            const double            gap,
                                            const double pressure) const
  {
    // The primal-dual rule pressure - c x gap, with a gap counted as
    // negative only beyond round-off, so that a node grazing the obstacle
    // does not flip; after cycle breaking, a node in contact stays while
    // its pressure is positive and one off it comes where its gap is
    // negative.
    const double shifted = gap + touching_tolerance;
    if (sign_rule)
      return node.in_contact() ? pressure : -shifted;
    return pressure - complementarity_constant * shifted;
  }

  template <int dim>
  double
  ActiveSetFormulation<dim>::residual_pressure(const unsigned int,
                                               const ContactNode<dim> &,
                                               const double gap,
                                               const double pressure) const
  {
    return pressure - complementarity_constant * gap;
  }

  template <int dim>
  void
  ActiveSetFormulation<dim>::linearise(
    const ContactSurface<dim>            &surface,
    const ContactLaw<dim>                &law,
    const std::vector<NodeTraction<dim>> &tractions,
    SystemAdditions<dim>                 &additions) const
  {
    condition_enforcement::add_constraints(surface, law, tractions, additions);
    additions.key           = {surface.active_set_signature(), 0.};
    additions.local_changes = true;
  }

  template <int dim>
  Tensor<1, dim>
  ActiveSetFormulation<dim>::tangential_traction(
    const unsigned int,
    const ContactNode<dim> &,
    const Tensor<1, dim> &slip,
    const Tensor<1, dim> &traction) const
  {
    // The primal-dual rule of the tangential traction, q - c_t s, with a
    // tenth of the normal's c: with c_t = c, a node that comes into
    // contact within a load step (its slip counted from the step's start)
    // flipped between stick and slip, and growing contact zones cycled
    // (the axisymmetric sphere with mu = 0.3 in 5 steps, cycle 6); the
    // converged solution does not depend on c_t.
    return traction - tangential_stiffness(0) * slip;
  }

  template <int dim>
  double
  ActiveSetFormulation<dim>::tangential_stiffness(const unsigned int) const
  {
    return 0.1 * complementarity_constant;
  }

  template <int dim>
  std::string
  ActiveSetFormulation<dim>::break_cycle()
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
  ActiveSetFormulation<dim>::cycle_broken() const
  {
    return sign_rule;
  }

  template class ActiveSetFormulation<2>;
  template class ActiveSetFormulation<3>;
} // namespace signorini
