#include <signorini/contact/cad_obstacle.h>
#include <signorini/contact/obstacle_parameters.h>
#include <signorini/input/entry_text.h>
#include <signorini/input/input_error.h>
#include <signorini/input/parsed_function.h>

#include <cmath>
#include <fstream>
#include <map>

namespace signorini
{
  using namespace dealii;

  namespace
  {
    template <int dim>
    using ObstacleType = typename ObstacleDescription<dim>::Type;

    template <int dim>
    const Choices<ObstacleType<dim>> obstacle_types{
      {ObstacleType<dim>::none, "none"},
      {ObstacleType<dim>::height, "height"},
      {ObstacleType<dim>::plane, "plane"},
      {ObstacleType<dim>::sphere, "sphere"},
      {ObstacleType<dim>::cylinder, "cylinder"},
      {ObstacleType<dim>::punch, "punch"},
      {ObstacleType<dim>::signed_distance, "signed distance"},
      {ObstacleType<dim>::geometry_file, "geometry file"}};

    const Choices<bool> body_sides{{false, "outside"}, {true, "inside"}};

    std::string
    obstacle_section(const unsigned int number)
    {
      return number == 1 ? "Obstacle" : "Obstacle " + std::to_string(number);
    }

    /** The entries of one obstacle, with their defaults: an entry whose
     * text differs from its default is given. */
    template <int dim>
    std::map<std::string, std::string>
    obstacle_entry_defaults(const unsigned int number)
    {
      const ObstacleDescription<dim> defaults;
      return {{"Type",
               obstacle_types<dim>.name(number == 1 ? defaults.type :
                                                      ObstacleType<dim>::none)},
              {"Height", defaults.height_expression},
              {"Point", ""},
              {"Normal", ""},
              {"Center", ""},
              {"Axis", ""},
              {"Radius", ""},
              {"Body", body_sides.name(defaults.body_inside)},
              {"Signed distance", ""},
              {"Geometry file", ""},
              {"Displacement", ""}};
    }

    template <int dim>
    void
    declare_obstacle_entries(ParameterHandler &prm, const unsigned int number)
    {
      auto defaults = obstacle_entry_defaults<dim>(number);
      prm.declare_entry(
        "Type",
        defaults["Type"],
        obstacle_types<dim>.pattern(),
        "The kind of obstacle: height (the graph of Height, below the body), "
        "plane (Point, Normal), sphere (Center, Radius, Body; a circle in "
        "2D), cylinder (Center, Axis in 3D, Radius, Body; a circle in 2D), "
        "punch (Center of its flat end, Normal from the punch towards the "
        "body, Radius; a flat-ended punch, a strip in 2D), signed distance (an "
        "expression), geometry file (the solid of a "
        "CAD or Gmsh file, Body)" +
          std::string(number == 1 ?
                        "." :
                        "; none: no such obstacle (the entries below must "
                        "then be left as they are)."));
      prm.declare_entry("Height",
                        defaults["Height"],
                        Patterns::Anything(),
                        "height: surface of the rigid obstacle [mm], y = "
                        "psi(x) in 2D, z = psi(x, y) in 3D, a muparser "
                        "expression, e.g. '-0.15' (flat) or '-sqrt(4 - x^2)' "
                        "(cylinder); the body lies above it.");
      prm.declare_entry("Point",
                        defaults["Point"],
                        Patterns::Anything(),
                        "plane: a point of the plane [mm], e.g. '0, -0.15'.");
      prm.declare_entry("Normal",
                        defaults["Normal"],
                        Patterns::Anything(),
                        "plane: the outward normal, pointing from the "
                        "obstacle towards the body (any length but zero), "
                        "e.g. '0, 1' for a floor, '0, -1' for a plate "
                        "pressing from above; punch: the outward normal of "
                        "its flat end, '0, -1' for a punch from above in "
                        "2D.");
      prm.declare_entry("Center",
                        defaults["Center"],
                        Patterns::Anything(),
                        "sphere: its center; cylinder: a point of its axis; "
                        "punch: the center of its flat end (on the axis "
                        "r = 0 in an axisymmetric model) [mm].");
      prm.declare_entry("Axis",
                        defaults["Axis"],
                        Patterns::Anything(),
                        "cylinder in 3D: the direction of its axis (any "
                        "length but zero). Not in 2D, where a cylinder is a "
                        "circle.");
      prm.declare_entry("Radius",
                        defaults["Radius"],
                        Patterns::Anything(),
                        "sphere, cylinder: radius [mm]; punch: the radius "
                        "of its flat end (in plane 2D the half-width of a "
                        "strip) [mm].");
      prm.declare_entry("Body",
                        defaults["Body"],
                        body_sides.pattern(),
                        "sphere, cylinder, geometry file: where the body "
                        "lies, outside the obstacle's surface (a ball on a "
                        "ball) or inside it (a shaft in a bore, a ball in a "
                        "cup).");
      prm.declare_entry("Signed distance",
                        defaults["Signed distance"],
                        Patterns::Anything(),
                        "signed distance: a muparser expression of x, y[, z] "
                        "[mm], positive on the body's side, negative inside "
                        "the obstacle, zero on its surface; the gap is the "
                        "expression divided by the length of its gradient "
                        "and the normal is the gradient's direction, so "
                        "near the surface any smooth level-set function will "
                        "do, e.g. 'y - 0.1*x^2' or 'sqrt(x^2 + (y-2)^2) - "
                        "1'.");
      prm.declare_entry("Geometry file",
                        defaults["Geometry file"],
                        Patterns::Anything(),
                        "geometry file: a rigid solid from a .step/.stp, "
                        ".brep or .geo file (a .geo with SetFactory"
                        "(\"OpenCASCADE\")), relative to the folder of the "
                        "parameter file, in mm: a volume in 3D, a surface in "
                        "the plane z = 0 in 2D. Gap and normal come from "
                        "OpenCASCADE's projection onto its boundary.");
      prm.declare_entry("Displacement",
                        defaults["Displacement"],
                        Patterns::Anything(),
                        "A rigid translation of the obstacle from where its "
                        "entries put it [mm], e.g. '0, -0.01': a tool pressed "
                        "into the body. Each component a number or a muparser "
                        "expression of the pseudo-time t (Load history), e.g. "
                        "'0, -0.01*t' for a tool pressed in step by step, '0, "
                        "-0.01*min(t, 1)' (a ',' inside parentheses belongs to "
                        "the expression). The body must not start inside the "
                        "obstacle before it moves (except a height). Empty: "
                        "none.");
    }

    /** A vector entry: @p dim numbers. */
    template <int dim>
    Tensor<1, dim>
    vector_entry(const std::string &text, const std::string &entry)
    {
      return parse::point<dim>(text, entry);
    }

    /** A direction: a vector entry that is not zero, made a unit vector. */
    template <int dim>
    Tensor<1, dim>
    direction_entry(const std::string &text, const std::string &entry)
    {
      const Tensor<1, dim> v      = vector_entry<dim>(text, entry);
      const double         length = v.norm();
      if (!(length > 0) || !std::isfinite(length))
        throw InputError(entry,
                         "'" + text +
                           "' is not a direction (zero or not a "
                           "finite vector)");
      return v / length;
    }

    template <int dim>
    ObstacleDescription<dim>
    parse_obstacle(ParameterHandler               &prm,
                   const unsigned int              number,
                   const std::vector<std::string> &folders)
    {
      using Type = ObstacleType<dim>;
      ObstacleDescription<dim> d;
      d.number            = number;
      d.section           = obstacle_section(number);
      const auto defaults = obstacle_entry_defaults<dim>(number);
      d.type = obstacle_types<dim>.value(prm.get("Type"), d.entry("Type"));

      // What each kind reads; every other entry must keep its default.
      std::set<std::string> required, optional = {"Displacement"};
      switch (d.type)
        {
          case Type::none:
            optional.clear();
            break;
          case Type::height:
            optional.insert("Height");
            break;
          case Type::plane:
            required = {"Point", "Normal"};
            break;
          case Type::sphere:
            required = {"Center", "Radius"};
            optional.insert("Body");
            break;
          case Type::cylinder:
            required = {"Center", "Radius"};
            if (dim == 3)
              required.insert("Axis");
            optional.insert("Body");
            break;
          case Type::punch:
            required = {"Center", "Normal", "Radius"};
            break;
          case Type::signed_distance:
            required = {"Signed distance"};
            break;
          case Type::geometry_file:
            required = {"Geometry file"};
            optional.insert("Body");
            break;
        }
      const std::string type_name = obstacle_types<dim>.name(d.type);
      for (const auto &[name, default_text] : defaults)
        {
          if (name == "Type")
            continue;
          const bool given = prm.get(name) != default_text;
          if (given && !required.count(name) && !optional.count(name))
            throw InputError(d.entry(name),
                             "does not apply to Type = " + type_name +
                               (d.type == Type::cylinder && name == "Axis" ?
                                  " in 2D (a cylinder is a circle there)" :
                                  "") +
                               (d.type == Type::none ?
                                  " (set the Type of this obstacle)" :
                                  ""));
          if (!given && required.count(name))
            throw InputError(d.entry(name),
                             "is required for Type = " + type_name);
        }

      d.height_expression = prm.get("Height");
      if (d.type == Type::height)
        d.height =
          parse_function<dim - 1>(d.height_expression, 1, d.entry("Height"));
      if (required.count("Point"))
        d.point = parse::point<dim>(prm.get("Point"), d.entry("Point"));
      if (required.count("Normal"))
        d.normal = direction_entry<dim>(prm.get("Normal"), d.entry("Normal"));
      if (required.count("Center"))
        d.center = parse::point<dim>(prm.get("Center"), d.entry("Center"));
      if (required.count("Axis"))
        d.axis = direction_entry<dim>(prm.get("Axis"), d.entry("Axis"));
      if (required.count("Radius"))
        {
          const std::string text = prm.get("Radius");
          std::size_t       end  = 0;
          try
            {
              d.radius = std::stod(text, &end);
            }
          catch (const std::exception &)
            {
              end = 0;
            }
          if (end == 0 ||
              text.find_first_not_of(" \t", end) != std::string::npos)
            throw InputError(d.entry("Radius"),
                             "'" + text + "' is not a number");
          if (!(d.radius > 0) || !std::isfinite(d.radius))
            throw InputError(d.entry("Radius"), "must be positive");
        }
      d.body_inside = body_sides.value(prm.get("Body"), d.entry("Body"));
      if (required.count("Signed distance"))
        {
          d.distance_expression = prm.get("Signed distance");
          d.distance            = parse_function<dim>(d.distance_expression,
                                           1,
                                           d.entry("Signed distance"));
        }
      if (required.count("Geometry file"))
        {
          // The first folder that holds it (else the first, for the error).
          const std::string name = prm.get("Geometry file");
          d.geometry_file =
            name[0] == '/' ? name : folders.front() + "/" + name;
          if (name[0] != '/')
            for (const auto &folder : folders)
              if (std::ifstream(folder + "/" + name))
                {
                  d.geometry_file = folder + "/" + name;
                  break;
                }
          if (!std::ifstream(d.geometry_file))
            throw InputError(d.entry("Geometry file"),
                             "cannot open '" + d.geometry_file + "'");
          // Read now, so that a file OpenCASCADE cannot read is bad input.
          CadObstacle<dim>(d.geometry_file,
                           body_sides.value(prm.get("Body"), d.entry("Body")),
                           d.entry("Geometry file"));
        }
      if (prm.get("Displacement") != defaults.at("Displacement"))
        d.displacement =
          TimeVector<dim>(prm.get("Displacement"), d.entry("Displacement"));
      return d;
    }
  } // namespace

  template <int dim>
  std::string
  ObstacleDescription<dim>::entry(const std::string &name) const
  {
    return section + "/" + name;
  }

  template <int dim>
  std::string
  ObstacleDescription<dim>::placing_entry() const
  {
    switch (type)
      {
        case Type::height:
          return entry("Height");
        case Type::plane:
          return entry("Point");
        case Type::sphere:
        case Type::cylinder:
        case Type::punch:
          return entry("Center");
        case Type::signed_distance:
          return entry("Signed distance");
        case Type::geometry_file:
          return entry("Geometry file");
        case Type::none:
          break;
      }
    return entry("Type");
  }

  template <int dim>
  bool
  ObstacleDescription<dim>::may_start_inside() const
  {
    return type == Type::height;
  }

  template <int dim>
  void
  ObstacleParameters<dim>::declare_parameters(ParameterHandler &prm)
  {
    const ObstacleParameters<dim> defaults;
    for (unsigned int number = 1; number <= max_obstacles; ++number)
      {
        prm.enter_subsection(obstacle_section(number));
        declare_obstacle_entries<dim>(prm, number);
        if (number == 1)
          prm.declare_entry(
            "Contact boundary ids",
            entry_text::of(std::vector<unsigned int>(
              defaults.contact_ids.begin(), defaults.contact_ids.end())),
            Patterns::Anything(),
            "Boundary ids (','-separated) that may touch the obstacles; a "
            "node of these faces touches the obstacle nearest to it, and up "
            "to dim obstacles at once where their normals differ.");
        prm.leave_subsection();
      }
  }

  template <int dim>
  void
  ObstacleParameters<dim>::parse_parameters(
    ParameterHandler               &prm,
    const std::vector<std::string> &folders)
  {
    obstacles.clear();
    for (unsigned int number = 1; number <= max_obstacles; ++number)
      {
        prm.enter_subsection(obstacle_section(number));
        auto description = parse_obstacle<dim>(prm, number, folders);
        if (number == 1)
          contact_ids = parse::boundary_ids(prm.get("Contact boundary ids"),
                                            "Obstacle/Contact boundary ids");
        prm.leave_subsection();
        if (description.type != ObstacleDescription<dim>::Type::none)
          obstacles.push_back(std::move(description));
      }
    if (obstacles.empty())
      throw InputError("Obstacle/Type",
                       "is none, and so are the other obstacles: there is "
                       "no obstacle");
  }

  template struct ObstacleDescription<2>;
  template struct ObstacleDescription<3>;
  template struct ObstacleParameters<2>;
  template struct ObstacleParameters<3>;
} // namespace signorini
