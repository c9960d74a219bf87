#include <signorini/elasticity/material.h>
#include <signorini/input/entry_text.h>
#include <signorini/input/input_error.h>

namespace signorini
{
  using namespace dealii;

  namespace
  {
    const Choices<Material::PlaneState> plane_states{
      {Material::PlaneState::plane_strain, "plane strain"},
      {Material::PlaneState::plane_stress, "plane stress"},
      {Material::PlaneState::axisymmetric, "axisymmetric"}};
  } // namespace

  void
  Material::declare_parameters(ParameterHandler &prm)
  {
    const Material defaults;
    prm.enter_subsection("Material");
    prm.declare_entry("Young's modulus",
                      entry_text::of(defaults.young_modulus),
                      Patterns::Double(0.),
                      "Young's modulus E [MPa = N/mm^2].");
    prm.declare_entry(
      "Poisson's ratio",
      entry_text::of(defaults.poisson_ratio),
      Patterns::Double(-1., 0.5),
      "Poisson's ratio nu [-], between -1 and 0.5 (exclusive).");
    prm.declare_entry("Plane state",
                      plane_states.name(defaults.plane_state),
                      plane_states.pattern(),
                      "2D only: plane strain (thick body, eps_zz = 0), plane "
                      "stress (thin plate, sigma_zz = 0) or axisymmetric (a "
                      "body of revolution about the y axis: x is the radius r "
                      ">= 0 and y the axial coordinate z; the hoop strain is "
                      "u_r / r, nodes on the axis x = 0 get u_r = 0 by "
                      "themselves, and every force is that of the whole "
                      "revolution [N]).");
    prm.leave_subsection();
  }

  void
  Material::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Material");
    young_modulus = prm.get_double("Young's modulus");
    poisson_ratio = prm.get_double("Poisson's ratio");
    plane_state =
      plane_states.value(prm.get("Plane state"), "Material/Plane state");
    prm.leave_subsection();
    if (!(young_modulus > 0))
      throw InputError("Material/Young's modulus", "must be positive");
    if (!(poisson_ratio > -1.))
      throw InputError("Material/Poisson's ratio", "must be above -1");
    if (!(poisson_ratio < 0.5))
      throw InputError("Material/Poisson's ratio",
                       "must be below 0.5 (incompressible material)");
  }

  double
  Material::mu() const
  {
    return young_modulus / (2. * (1. + poisson_ratio));
  }

  template <int dim>
  double
  Material::lambda() const
  {
    const double lambda = young_modulus * poisson_ratio /
                          ((1. + poisson_ratio) * (1. - 2. * poisson_ratio));
    if (dim == 2 && plane_state == PlaneState::plane_stress)
      return 2. * lambda * mu() / (lambda + 2. * mu());
    return lambda;
  }

  template <int dim>
  SymmetricTensor<2, dim>
  Material::stress(const SymmetricTensor<2, dim> &strain) const
  {
    return lambda<dim>() * trace(strain) * unit_symmetric_tensor<dim>() +
           2. * mu() * strain;
  }

  template <int dim>
  double
  Material::out_of_plane_stress(const SymmetricTensor<2, dim> &strain) const
  {
    if (dim != 2 || plane_state == PlaneState::plane_stress)
      return 0.;
    return lambda<dim>() * trace(strain);
  }

  template double
  Material::lambda<2>() const;
  template double
  Material::lambda<3>() const;
  template SymmetricTensor<2, 2>
  Material::stress(const SymmetricTensor<2, 2> &) const;
  template SymmetricTensor<2, 3>
  Material::stress(const SymmetricTensor<2, 3> &) const;
  template double
  Material::out_of_plane_stress(const SymmetricTensor<2, 2> &) const;
  template double
  Material::out_of_plane_stress(const SymmetricTensor<2, 3> &) const;
} // namespace signorini
