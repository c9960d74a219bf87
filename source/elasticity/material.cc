#include <signorini/elasticity/material.h>
#include <signorini/input/entry_text.h>
#include <signorini/input/input_error.h>

namespace signorini
{
  using namespace dealii;

  namespace
  {
    const Choices<bool> plane_states{{false, "plane strain"},
                                     {true, "plane stress"}};
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
                      plane_states.name(defaults.plane_stress),
                      plane_states.pattern(),
                      "2D only: plane strain (thick body, eps_zz = 0) or plane "
                      "stress (thin plate, sigma_zz = 0).");
    prm.leave_subsection();
  }

  void
  Material::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Material");
    young_modulus = prm.get_double("Young's modulus");
    poisson_ratio = prm.get_double("Poisson's ratio");
    plane_stress =
      plane_states.value(prm.get("Plane state"), "Material/Plane state");
    prm.leave_subsection();
    parse::in_range(young_modulus,
                    parse::Range::positive(),
                    "Material/Young's modulus");
    parse::in_range(poisson_ratio,
                    parse::Range::open(-1., 0.5),
                    "Material/Poisson's ratio",
                    "0.5 is incompressible");
    if (poisson_ratio < 0)
      warn("Material/Poisson's ratio",
           "is negative, an auxetic material that thickens when stretched; "
           "is the sign right?");
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
    if (dim == 2 && plane_stress)
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
    if (dim != 2 || plane_stress)
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
