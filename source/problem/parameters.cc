#include <signorini/input/entry_text.h>
#include <signorini/input/input_error.h>
#include <signorini/problem/parameters.h>

#include <sstream>

namespace signorini
{
  using namespace dealii;

  namespace
  {
    void
    declare_dimension(ParameterHandler &prm)
    {
      prm.declare_entry(
        "Dimension",
        entry_text::of(default_dimension),
        Patterns::Integer(2, 3),
        "Space dimension: 2 (plane strain, plane stress or axisymmetric: "
        "Material/Plane state) or 3.");
    }

    /** @p text, ShortPRM output of a ParameterHandler, with the value of
     * @p entry in the top-level subsection @p section replaced by
     * @p value. */
    std::string
    with_value(const std::string &text,
               const std::string &section,
               const std::string &entry,
               const std::string &value)
    {
      std::istringstream in(text);
      std::string        result, line;
      unsigned int       depth      = 0;
      bool               in_section = false;
      while (std::getline(in, line))
        {
          const auto start = line.find_first_not_of(' ');
          const auto content =
            start == std::string::npos ? std::string() : line.substr(start);
          if (content.rfind("subsection ", 0) == 0)
            {
              ++depth;
              if (depth == 1)
                in_section = content == "subsection " + section;
            }
          else if (content == "end")
            --depth;
          else if (depth == 1 && in_section &&
                   content.rfind("set " + entry + " ", 0) == 0 &&
                   line.find("= ") != std::string::npos)
            line = line.substr(0, line.find("= ") + 2) + value;
          result += line + '\n';
        }
      return result;
    }
  } // namespace

  void
  declare_parameters(ParameterHandler &prm, const unsigned int dim)
  {
    declare_dimension(prm);
    if (dim == 2)
      {
        Geometry<2>::declare_parameters(prm);
        Material::declare_parameters(prm);
        BoundaryConditions<2>::declare_parameters(prm);
        ObstacleParameters<2>::declare_parameters(prm);
      }
    else
      {
        Geometry<3>::declare_parameters(prm);
        Material::declare_parameters(prm);
        BoundaryConditions<3>::declare_parameters(prm);
        ObstacleParameters<3>::declare_parameters(prm);
      }
    FrictionParameters::declare_parameters(prm);
    ContactParameters::declare_parameters(prm);
    LinearSolverParameters::declare_parameters(prm);
    Refinement::declare_parameters(prm);
    LoadHistory::declare_parameters(prm);
    if (dim == 2)
      {
        OutputParameters<2>::declare_parameters(prm);
        Reference<2>::declare_parameters(prm);
      }
    else
      {
        OutputParameters<3>::declare_parameters(prm);
        Reference<3>::declare_parameters(prm);
      }
    CheckpointParameters::declare_parameters(prm);
  }

  unsigned int
  read_dimension(const ParameterFile &input)
  {
    ParameterHandler prm;
    declare_dimension(prm);
    try
      {
        input.parse(prm, /*skip_undefined=*/true);
      }
    catch (const InputError &)
      {
        // An error before it in the file may be one that reading
        // `Dimension` alone skips (an entry that does not match its
        // pattern, say): reading every entry throws the first one.
        ParameterHandler all;
        declare_parameters(all, default_dimension);
        input.parse(all);
        throw;
      }
    return prm.get_integer("Dimension");
  }

  template <int dim>
  void
  Parameters<dim>::parse_parameters(ParameterHandler               &prm,
                                    const std::vector<std::string> &folders)
  {
    geometry.parse_parameters(prm, folders);
    material.parse_parameters(prm);
    boundary_conditions.parse_parameters(prm);
    obstacle.parse_parameters(prm, folders);
    contact.parse_parameters(prm);
    friction.parse_parameters(prm);
    linear_solver.parse_parameters(prm);
    refinement.parse_parameters(prm);
    load_history.parse_parameters(prm);
    output.parse_parameters(prm);
    reference.parse_parameters(prm);
    checkpoint.parse_parameters(prm);
    std::vector<unsigned int> obstacle_numbers;
    for (const auto &description : obstacle.obstacles)
      obstacle_numbers.push_back(description.number);
    friction.check(obstacle_numbers,
                   ContactParameters::methods().name(contact.method),
                   contact.method != ContactParameters::Method::none);
    if (material.axisymmetric())
      {
        if (dim != 2)
          throw InputError("Material/Plane state",
                           "axisymmetric is a 2D model in (r, z) = (x, y); "
                           "set Dimension = 2");
        if (boundary_conditions.traction_resultant &&
            boundary_conditions.traction_resultant->constant_component(0) != 0.)
          throw InputError("Boundary conditions/Traction resultant",
                           "an axisymmetric body's resultant is axial: its "
                           "first (radial) component must be 0");
      }
    if (linear_solver.type == LinearSolverParameters::Type::matrix_free)
      {
        if (material.axisymmetric())
          throw InputError("Linear solver/Type",
                           "matrix-free evaluates plane strain, plane stress "
                           "and 3D; an axisymmetric model (Material/Plane "
                           "state) needs amg cg or direct");
        if (material.mean_dilatation<dim>(false))
          throw InputError("Linear solver/Type",
                           "matrix-free takes the volumetric strain at every "
                           "point; the cell mean (Material/Volumetric strain, "
                           "automatic from Poisson's ratio 0.4 on) needs amg "
                           "cg or direct");
      }

    std::ostringstream printed;
    prm.print_parameters(printed, ParameterHandler::ShortPRM);
    text = printed.str();
    // To run again from anywhere: the mesh file by its absolute path.
    if (geometry.type == Geometry<dim>::Type::gmsh)
      text = with_value(text, "Geometry", "Mesh file", geometry.mesh_file);
  }

  template struct Parameters<2>;
  template struct Parameters<3>;
} // namespace signorini
