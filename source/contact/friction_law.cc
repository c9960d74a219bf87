#include <signorini/contact/friction_law.h>

#include <algorithm>
#include <cmath>

namespace signorini
{
  using namespace dealii;

  namespace
  {
    /** Whether the supports hold @p node along the unit direction @p v
     * (its part along the node's free components is none). */
    template <int dim>
    bool
    held_by_supports(const ContactNode<dim> &node, const Tensor<1, dim> &v)
    {
      return ContactSurface<dim>::free_part(v, node.free) <
             ContactSurface<dim>::fixed_along_normal;
    }
  } // namespace

  template <int dim>
  FrictionLaw<dim>::FrictionLaw(const std::vector<double> &coefficient,
                                const std::vector<double> &slip_bound)
    : coefficient(coefficient)
    , slip_bound(slip_bound)
  {
  }

  template <int dim>
  std::string
  FrictionLaw<dim>::name() const
  {
    return "friction";
  }

  template <int dim>
  bool
  FrictionLaw<dim>::path_dependent() const
  {
    return true;
  }

  template <int dim>
  NodeState
  FrictionLaw<dim>::contact_state() const
  {
    return NodeState::stick;
  }

  template <int dim>
  bool
  FrictionLaw<dim>::frictional(const ContactNode<dim> &node) const
  {
    if (node.corner != numbers::invalid_unsigned_int ||
        !(coefficient[node.obstacle] > 0 || slip_bound[node.obstacle] > 0))
      return false;
    // A tangent that a support holds in part (the apex of a wedge on its
    // symmetry line, against an inclined wall) leaves the node no slip
    // along the obstacle that friction could resist: it is frictionless,
    // as at a corner. (A tangent held whole, or free, is friction's.)
    for (const auto &t : node.tangents)
      {
        const double free = ContactSurface<dim>::free_part(t, node.free);
        if (free >= ContactSurface<dim>::fixed_along_normal && free < 1. - 1e-8)
          return false;
      }
    return true;
  }

  template <int dim>
  double
  FrictionLaw<dim>::bound(const ContactNode<dim> &node,
                          const double            sigma) const
  {
    return slip_bound[node.obstacle] > 0 ?
             slip_bound[node.obstacle] :
             coefficient[node.obstacle] * std::max(0., sigma);
  }

  template <int dim>
  NodeState
  FrictionLaw<dim>::state(const ContactNode<dim>  &node,
                          const NodeTraction<dim> &traction) const
  {
    if (!(traction.sigma > 0) || !frictional(node))
      return FrictionlessLaw<dim>::state(node, traction);
    // A node at its bound to round-off (a slipping node at a step's start,
    // its shear mu p from the same nodal forces as p) slips.
    return traction.tangential.norm() <
               (1. - 1e-8) * bound(node, traction.bound_sigma) ?
             NodeState::stick :
             NodeState::slip;
  }

  template <int dim>
  std::optional<Tensor<1, dim>>
  FrictionLaw<dim>::tangential_force(const ContactNode<dim>  &node,
                                     const NodeTraction<dim> &traction) const
  {
    if (!frictional(node))
      return std::nullopt;
    const double b    = bound(node, traction.bound_sigma);
    const double zeta = traction.tangential.norm();
    if (!(traction.sigma > 0) || zeta == 0.)
      return Tensor<1, dim>();
    return node.mass * b / std::max(b, zeta) * traction.tangential;
  }

  template <int dim>
  void
  FrictionLaw<dim>::conditions(const ContactNode<dim>          &node,
                               const NodeTraction<dim>         &traction,
                               std::vector<NodeCondition<dim>> &conditions,
                               std::vector<NodeEquation<dim>>  &equations) const
  {
    // n.u = -gap in contact, then the tangential part of the state.
    FrictionlessLaw<dim>::conditions(node, traction, conditions, equations);
    if (conditions.empty())
      return;
    const unsigned int along = conditions.front().component;
    // Tangents the supports hold need no condition (and have no equation).
    if (node.state == NodeState::stick)
      {
        // As many conditions as the node has free components.
        unsigned int free = 0;
        for (unsigned int d = 0; d < dim; ++d)
          free += node.free[d] ? 1 : 0;
        for (const auto &t : node.tangents)
          if (conditions.size() < free && !held_by_supports(node, t))
            conditions.push_back({t, t * node.reference, along});
      }
    else if (node.state == NodeState::slip && traction.shear_weight == 0.)
      add_regularised_slip_equations(node, traction, equations);
    else if (node.state == NodeState::slip && dim == 3 &&
             traction.shear.norm() >= 0.99 * bound(node, traction.bound_sigma))
      add_slip_equations(node, traction, equations);
    else if (node.state == NodeState::slip)
      {
        const double zeta = traction.tangential.norm();
        const auto d = zeta > 0 ? traction.tangential / zeta : Tensor<1, dim>();
        const double mu = coefficient[node.obstacle];
        const double s  = slip_bound[node.obstacle];
        for (const auto &t : node.tangents)
          if (!held_by_supports(node, t))
            {
              if (s > 0)
                equations.push_back({t, node.mass * s * (t * d)});
              else
                equations.push_back({t - mu * (t * d) * node.normal, 0.});
            }
      }
  }

  template <int dim>
  void
  FrictionLaw<dim>::add_regularised_slip_equations(
    const ContactNode<dim>         &node,
    const NodeTraction<dim>        &traction,
    std::vector<NodeEquation<dim>> &equations) const
  {
    // The obstacle's tangential force f_T = B z, along z = zeta / |zeta|
    // with zeta = -c s, of the size B = mu n.f (Coulomb) or m s (Tresca).
    // Linearised about the present slip, z turns by -P c ds / |zeta|
    // (P = I - z z^T, none in 2D, where z is a sign), and P s = 0:
    //   t_i.f - mu z_i n.f + (B c / |zeta|) sum_j P_ij t_j.(u - u_ref) = 0
    // (Tresca: without the n.f term, = m s z_i), B at the present state.
    const double zeta = traction.tangential.norm();
    if (!(zeta > 0))
      return;
    const Tensor<1, dim> z      = traction.tangential / zeta;
    const double         mu     = coefficient[node.obstacle];
    const bool           tresca = slip_bound[node.obstacle] > 0;
    const double         size   = node.mass * bound(node, traction.bound_sigma);
    const double         turn   = size * traction.stiffness / zeta;
    for (const auto &t : node.tangents)
      if (!held_by_supports(node, t))
        {
          NodeEquation<dim> equation;
          equation.direction = t;
          if (!tresca)
            equation.direction -= mu * (t * z) * node.normal;
          // In 2D z is a sign: nothing turns.
          for (const auto &t_j : node.tangents)
            if (dim == 3)
              equation.displacement +=
                turn * ((&t_j == &t ? 1. : 0.) - (t * z) * (t_j * z)) * t_j;
          equation.value = (tresca ? size * (t * z) : 0.) +
                           equation.displacement * node.reference;
          equations.push_back(equation);
        }
  }

  template <int dim>
  void
  FrictionLaw<dim>::add_slip_equations(
    const ContactNode<dim>         &node,
    const NodeTraction<dim>        &traction,
    std::vector<NodeEquation<dim>> &equations) const
  {
    // The semismooth Newton step of max(b, |zeta|) q - b zeta = 0 on a
    // slipping node (Hueber, Stadler and Wohlmuth 2008, with q projected
    // onto the disk |q| <= b where it is outside), in the node's tangent
    // coordinates, per unit mass:
    //   [(|zeta| - b) I + q~ zeta^T / |zeta|] q+
    //     - c [q~ zeta^T / |zeta| - b I] s+ - mu zeta p+
    //   = q~ |zeta| - mu zeta p            (Coulomb; Tresca: b fixed,
    //                                       no p terms: = q~ |zeta|),
    // with q+ = T^T f / m, p+ = n.f / m, s+ = T^T (u - u_reference): the
    // slip direction turns with the iteration, so that it converges
    // superlinearly where a frozen direction would converge linearly.
    constexpr unsigned int n      = dim - 1;
    const double           mu     = coefficient[node.obstacle];
    const bool             tresca = slip_bound[node.obstacle] > 0;
    const double           b      = bound(node, traction.bound_sigma);
    const double           m      = node.mass;
    const double           c      = traction.stiffness;
    Tensor<1, n>           zeta, q;
    for (unsigned int i = 0; i < n; ++i)
      {
        zeta[i] = node.tangents[i] * traction.tangential;
        q[i]    = node.tangents[i] * traction.shear;
      }
    const double length = zeta.norm();
    if (!(length > 0))
      return;
    if (q.norm() > b)
      q *= b / q.norm();
    for (unsigned int i = 0; i < n; ++i)
      {
        if (held_by_supports(node, node.tangents[i]))
          continue;
        NodeEquation<dim> equation;
        double            value = q[i] * length;
        if (!tresca)
          {
            equation.direction -= mu * zeta[i] * node.normal;
            value -= mu * zeta[i] * traction.pressure;
          }
        for (unsigned int j = 0; j < n; ++j)
          {
            const double qz = q[i] * zeta[j] / length;
            const double a  = qz + (i == j ? length - b : 0.);
            const double s  = -c * (qz - (i == j ? b : 0.));
            equation.direction += a * node.tangents[j];
            equation.displacement += m * s * node.tangents[j];
          }
        equation.value = m * value + equation.displacement * node.reference;
        equations.push_back(equation);
      }
  }

  template class FrictionLaw<2>;
  template class FrictionLaw<3>;
} // namespace signorini
