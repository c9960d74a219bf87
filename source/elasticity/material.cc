#include <signorini/base/text.h>
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
    const Choices<Material::VolumetricStrain> volumetric_strains{
      {Material::VolumetricStrain::automatic, "automatic"},
      {Material::VolumetricStrain::pointwise, "pointwise"},
      {Material::VolumetricStrain::cell_mean, "cell mean"}};
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
    prm.declare_entry(
      "Volumetric strain",
      volumetric_strains.name(defaults.volumetric_strain),
      volumetric_strains.pattern(),
      "How Q1 cells (quadrilaterals, hexahedra) take the volumetric strain "
      "div u in the stiffness, the internal forces, the energy and the "
      "stress output. pointwise: the standard displacement element, which "
      "locks (is far too stiff) as nu -> 0.5. cell mean: div u replaced by "
      "its mean over the cell (mean dilatation, B-bar), free of locking. "
      "automatic: cell mean from nu = 0.4 on in plane strain, axisymmetric "
      "models and 3D, pointwise otherwise. P1 triangles and tetrahedra "
      "always take it pointwise and lock as nu -> 0.5: a warning says so "
      "from nu = 0.4 on. In an axisymmetric model div u includes the hoop "
      "strain and the mean is over the revolved cell.");
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
    volumetric_strain = volumetric_strains.value(prm.get("Volumetric strain"),
                                                 "Material/Volumetric strain");
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
    if (dim == 2 && plane_state == PlaneState::plane_stress)
      return 2. * lambda * mu() / (lambda + 2. * mu());
    return lambda;
  }

  std::string
  Material::check_element(const bool simplex) const
  {
    if (!simplex)
      return "";
    if (volumetric_strain == VolumetricStrain::cell_mean)
      throw InputError("Material/Volumetric strain",
                       "'cell mean' needs quadrilaterals or hexahedra; this "
                       "mesh has triangles or tetrahedra");
    if (poisson_ratio < nearly_incompressible ||
        plane_state == PlaneState::plane_stress)
      return "";
    return "Material/Poisson's ratio = " + number(poisson_ratio) +
           ": triangles and tetrahedra lock as nu -> 0.5 (the body comes out "
           "too stiff; P1 more than P2); mesh with quadrilaterals or "
           "hexahedra for the mean dilatation";
  }

  template <int dim>
  bool
  Material::mean_dilatation(const bool simplex) const
  {
    if (simplex)
      return false;
    switch (volumetric_strain)
      {
        case VolumetricStrain::pointwise:
          return false;
        case VolumetricStrain::cell_mean:
          return true;
        case VolumetricStrain::automatic:
          break;
      }
    return poisson_ratio >= nearly_incompressible &&
           !(dim == 2 && plane_state == PlaneState::plane_stress);
  }

  template <int dim>
  SymmetricTensor<2, dim>
  Material::stress(const SymmetricTensor<2, dim> &strain) const
  {
    return stress<dim>(strain, trace(strain));
  }

  template <int dim>
  SymmetricTensor<2, dim>
  Material::stress(const SymmetricTensor<2, dim> &strain,
                   const double                   volumetric) const
  {
    return lambda<dim>() * volumetric * unit_symmetric_tensor<dim>() +
           2. * mu() * strain;
  }

  template <int dim>
  double
  Material::out_of_plane_stress(const SymmetricTensor<2, dim> &strain) const
  {
    return out_of_plane_stress<dim>(trace(strain));
  }

  template <int dim>
  double
  Material::out_of_plane_stress(const double volumetric) const
  {
    if (dim != 2 || plane_state == PlaneState::plane_stress)
      return 0.;
    return lambda<dim>() * volumetric;
  }

  template double
  Material::lambda<2>() const;
  template double
  Material::lambda<3>() const;
  template bool
  Material::mean_dilatation<2>(const bool) const;
  template bool
  Material::mean_dilatation<3>(const bool) const;
  template SymmetricTensor<2, 2>
  Material::stress(const SymmetricTensor<2, 2> &, const double) const;
  template SymmetricTensor<2, 3>
  Material::stress(const SymmetricTensor<2, 3> &, const double) const;
  template double
  Material::out_of_plane_stress<2>(const double) const;
  template double
  Material::out_of_plane_stress<3>(const double) const;
  template SymmetricTensor<2, 2>
  Material::stress(const SymmetricTensor<2, 2> &) const;
  template SymmetricTensor<2, 3>
  Material::stress(const SymmetricTensor<2, 3> &) const;
  template double
  Material::out_of_plane_stress(const SymmetricTensor<2, 2> &) const;
  template double
  Material::out_of_plane_stress(const SymmetricTensor<2, 3> &) const;
} // namespace signorini
