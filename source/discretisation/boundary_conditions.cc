#include <signorini/discretisation/boundary_conditions.h>
#include <signorini/input/input_error.h>
#include <signorini/input/parsed_function.h>

namespace signorini
{
  using namespace dealii;

  template <int dim>
  void
  BoundaryConditions<dim>::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Boundary conditions");
    prm.declare_entry("Dirichlet",
                      "0: all",
                      Patterns::Anything(),
                      "Supports as a ';'-separated list of 'boundary id: "
                      "components', components being letters of x, y, z or "
                      "'all'. '0: all' clamps boundary 0, '1: y' is a roller "
                      "that moves along x. Empty: no Dirichlet boundary.");
    prm.declare_entry("Prescribed displacement",
                      "0",
                      Patterns::Anything(),
                      "Displacement [mm] imposed on the Dirichlet components: "
                      "'ux; uy[; uz]' as functions of x, y[, z] and the "
                      "pseudo-time t (Load history), or one expression for "
                      "all components.");
    prm.declare_entry("Traction boundary ids",
                      "",
                      Patterns::Anything(),
                      "Boundary ids (','-separated) loaded by the traction.");
    prm.declare_entry("Traction",
                      "0",
                      Patterns::Anything(),
                      "Surface load [MPa = N/mm^2] on the traction boundaries: "
                      "'tx; ty[; tz]' as functions of x, y[, z] and the "
                      "pseudo-time t (Load history).");
    prm.declare_entry("Traction resultant",
                      "",
                      Patterns::Anything(),
                      "If set, e.g. '0, 0, -0.375': the force [N] that the "
                      "traction adds up to. The traction boundaries then "
                      "carry this force as a uniform traction, the force over "
                      "their area on each mesh, and Traction is ignored: a "
                      "load by a force, exact on every mesh. Each component "
                      "a number or an expression of the pseudo-time t (Load "
                      "history), e.g. '0, -1.5*t'.");
    prm.declare_entry("Body force",
                      "0",
                      Patterns::Anything(),
                      "Volume load [N/mm^3]: 'bx; by[; bz]' as functions of "
                      "x, y[, z] and the pseudo-time t (Load history).");
    prm.leave_subsection();
  }

  template <int dim>
  void
  BoundaryConditions<dim>::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Boundary conditions");
    const std::string entry = "Boundary conditions/Dirichlet";
    dirichlet.clear();
    std::set<types::boundary_id> seen;
    for (const auto &item : parse::split(prm.get("Dirichlet"), ';'))
      {
        const auto parts = parse::split(item, ':');
        if (parts.size() != 2)
          throw InputError(entry,
                           "'" + item +
                             "' is not of the form 'id: components'");
        const auto ids = parse::boundary_ids(parts[0], entry);
        if (ids.size() != 1 || !seen.insert(*ids.begin()).second)
          throw InputError(entry,
                           "'" + parts[0] +
                             "' is not one boundary id listed once");
        dirichlet.emplace_back(
          *ids.begin(), ComponentMask(parse::components(parts[1], dim, entry)));
      }
    prescribed_displacement =
      parse_function<dim>(prm.get("Prescribed displacement"),
                          dim,
                          "Boundary conditions/Prescribed displacement",
                          {},
                          true);
    traction_ids = parse::boundary_ids(prm.get("Traction boundary ids"),
                                       "Boundary conditions/Traction boundary "
                                       "ids");
    traction     = parse_function<dim>(
      prm.get("Traction"), dim, "Boundary conditions/Traction", {}, true);
    traction_resultant.reset();
    if (!prm.get("Traction resultant").empty())
      {
        traction_resultant.emplace(prm.get("Traction resultant"),
                                   "Boundary conditions/Traction resultant");
        if (traction_ids.empty())
          throw InputError("Boundary conditions/Traction resultant",
                           "needs Traction boundary ids");
      }
    body_force = parse_function<dim>(
      prm.get("Body force"), dim, "Boundary conditions/Body force", {}, true);
    prm.leave_subsection();
  }

  template struct BoundaryConditions<2>;
  template struct BoundaryConditions<3>;
} // namespace signorini
