#include <deal.II/base/exceptions.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/manifold_lib.h>

#include <signorini/base/memory.h>
#include <signorini/base/text.h>
#include <signorini/discretisation/geometry.h>
#include <signorini/discretisation/gmsh_geometry.h>
#include <signorini/input/entry_text.h>
#include <signorini/input/input_error.h>
#include <signorini/input/text_check.h>

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <optional>
#include <set>
#include <sstream>

namespace signorini
{
  using namespace dealii;

  namespace
  {

    /** Coordinates [mm] beyond this are not a body the program can mesh:
     * its areas and energies overflow, and round-off of its size exceeds
     * its cells (a body of 1e300 mm was said to be free to rotate). */
    constexpr double largest_coordinate = 1e9;

    /** Throws an InputError naming @p entry if a coordinate of @p point is
     * beyond largest_coordinate. */
    template <int dim>
    void
    check_size(const Point<dim> &point, const std::string &entry)
    {
      for (unsigned int d = 0; d < dim; ++d)
        if (std::abs(point[d]) > largest_coordinate)
          throw InputError(entry,
                           number(point[d]) +
                             " mm is beyond 1e9 mm (1000 km), more than "
                             "the program can mesh: lengths are in mm; is "
                             "the unit right?");
    }
    template <int dim>
    const Choices<typename Geometry<dim>::Type> shape_types{
      {Geometry<dim>::Type::rectangle, "rectangle"},
      {Geometry<dim>::Type::half_ball, "half ball"},
      {Geometry<dim>::Type::quarter_disk, "quarter disk"},
      {Geometry<dim>::Type::quarter_ball, "quarter ball"},
      {Geometry<dim>::Type::gmsh, "gmsh"}};

    const Choices<GmshOptions::CellType> cell_types{
      {GmshOptions::CellType::automatic, "automatic"},
      {GmshOptions::CellType::quadrilateral, "quadrilateral"},
      {GmshOptions::CellType::simplex, "simplex"}};

    /** Why @p bytes, the content of a .msh file, cannot be a whole ASCII
     * Gmsh mesh, if they cannot: not text (binary), or a section without
     * its end (a truncated file), or a section missing. */
    std::optional<std::string>
    msh_problem(const std::string &bytes)
    {
      std::istringstream in(bytes);
      std::string        line, version;
      int                file_type = 0;
      // "$MeshFormat" and "VERSION FILE-TYPE DATA-SIZE": file-type 1 is
      // binary.
      if (std::getline(in, line) && line.rfind("$MeshFormat", 0) == 0 &&
          (in >> version >> file_type) && file_type == 1)
        return std::string("is a binary .msh file; save it as ASCII (Gmsh: "
                           "File > Export, without 'Save in binary format')");
      if (const auto problem = text_check::first_non_text(bytes))
        return "is not a mesh: line " + std::to_string(problem->line) +
               ", column " + std::to_string(problem->column) + ": " +
               problem->what;

      in.clear();
      in.seekg(0);
      std::string           open;
      unsigned int          number = 0, opened_at = 0, items = 0, listed = 0;
      std::set<std::string> sections;
      const auto            at = [&](const unsigned int n) {
        return "line " + std::to_string(n) + ": ";
      };
      while (std::getline(in, line))
        {
          ++number;
          line = Utilities::trim(line);
          if (line.empty())
            continue;
          if (line[0] != '$')
            {
              if (!open.empty() && ++items == 1)
                listed = std::atoi(line.c_str());
              continue;
            }
          if (line.rfind("$End", 0) == 0)
            {
              if (line.substr(4) != open)
                return "is damaged: " + at(number) + line +
                       (open.empty() ? " ends no section" :
                                       " in the $" + open + " section");
              // In format 2, $Nodes and $Elements begin with their count.
              if ((open == "Nodes" || open == "Elements") &&
                  version.rfind("2", 0) == 0 && items != listed + 1)
                return "is damaged: its $" + open + " section (line " +
                       std::to_string(opened_at) + ") lists " +
                       std::to_string(listed) + " items on " +
                       std::to_string(items > 0 ? items - 1 : 0) + " lines";
              open.clear();
              continue;
            }
          if (!open.empty())
            return "is damaged: " + at(number) + line + " begins before $End" +
                   open + " of line " + std::to_string(opened_at);
          open      = line.substr(1);
          opened_at = number;
          items     = 0;
          sections.insert(open);
        }
      if (!open.empty())
        return "is truncated: it ends at line " + std::to_string(number) +
               " inside its $" + open + " section (line " +
               std::to_string(opened_at) + "), before $End" + open;
      for (const std::string section : {"MeshFormat", "Nodes", "Elements"})
        if (sections.count(section) == 0)
          return (section == "MeshFormat" ?
                    std::string("is not a Gmsh .msh file: ") :
                    std::string("is truncated or damaged: ")) +
                 "it has no $" + section + " section";
      return {};
    }

    /**
     * Throws, on every process of @p comm, an InputError naming the entry
     * that makes the initial mesh too large for the memory the processes
     * have: the initial refinement if there is one, else the subdivisions
     * of a rectangle or the mesh file. The mesh has @p n_coarse_cells
     * (simplices if @p simplex), refined as often as `Initial refinement`
     * says if @p refined. Each unknown takes 2 kB at least (README:
     * 2.3 kB per dof in 3D, more in 2D with the direct solver).
     */
    template <int dim>
    void
    refuse_oversized_mesh(const Geometry<dim> &geometry,
                          const double         n_coarse_cells,
                          const bool           simplex,
                          const bool           refined,
                          const MPI_Comm       comm)
    {
      const unsigned int k = refined ? geometry.initial_refinement : 0;
      const double n_cells = n_coarse_cells * std::pow(2., double(dim * k));
      const double vertices_per_cell = simplex ? (dim == 2 ? 0.5 : 1. / 6) : 1.;
      const double bytes_per_cell    = 2e3 * dim * vertices_per_cell;
      const double n_dofs            = dim * vertices_per_cell * n_cells;
      const double needed            = bytes_per_cell * n_cells;
      const double available         = available_memory(comm);
      if (needed <= available)
        return;
      // The refinements, unless the coarse mesh is too large already.
      std::string entry = "Geometry/Mesh file", cause;
      if (k > 0 && bytes_per_cell * n_coarse_cells <= available)
        {
          entry = "Geometry/Initial refinement";
          cause = std::to_string(k) + " refinement" + (k > 1 ? "s" : "") +
                  " of " + number(n_coarse_cells) + " coarse cells make ";
        }
      else if (geometry.type == Geometry<dim>::Type::rectangle)
        {
          entry = "Geometry/Subdivisions";
          cause = "'" + entry_text::of(geometry.subdivisions) + "'" +
                  (k > 0 ? " refined " + std::to_string(k) + " times" : "") +
                  " make ";
        }
      throw InputError(entry,
                       cause + number(n_cells) + " cells, about " +
                         number(n_dofs) + " unknowns, which need at least " +
                         number(needed / 1e9) + " GB of memory; " +
                         number(available / 1e9) + " GB are available");
    }
  } // namespace

  template <int dim>
  void
  Geometry<dim>::declare_parameters(ParameterHandler &prm)
  {
    const Geometry<dim> defaults;
    prm.enter_subsection("Geometry");
    prm.declare_entry("Type",
                      shape_types<dim>.name(defaults.type),
                      shape_types<dim>.pattern(),
                      "Shape of the body: a rectangle (box in 3D); a half ball "
                      "(half-disk in 2D) with its curved face down (boundary "
                      "id 0) and its flat face up (id 1); a quarter disk (2D "
                      "only), the half of a half-disk at x >= Center x, with "
                      "the curved face down (id 0), the flat face up (id 1) "
                      "and the symmetry line x = Center x (id 2); a quarter "
                      "ball (3D only), the quarter x >= Center x, y >= "
                      "Center y of a half ball: curved face down (id 0), "
                      "flat face up (id 1), symmetry planes x = Center x "
                      "(id 2) and y = Center y (id 3); or a Gmsh mesh file.");
    prm.declare_entry("Lower left corner",
                      entry_text::of(defaults.lower_left),
                      Patterns::Anything(),
                      "rectangle: corner with the smallest coordinates [mm], "
                      "e.g. '0, 0' (2D) or '0, 0, 0' (3D).");
    prm.declare_entry("Upper right corner",
                      entry_text::of(defaults.upper_right),
                      Patterns::Anything(),
                      "rectangle: corner with the largest coordinates [mm].");
    prm.declare_entry("Subdivisions",
                      entry_text::of(defaults.subdivisions),
                      Patterns::Anything(),
                      "rectangle: number of cells in x, y[, z] on the coarse "
                      "mesh.");
    prm.declare_entry(
      "Cell type",
      cell_types.name(defaults.cell_type),
      cell_types.pattern(),
      "quadrilateral: quadrilateral/hexahedral cells with Q1 "
      "elements (Q2 with Element degree = 2); simplex: "
      "triangles/tetrahedra with P1 elements (P2). rectangle: simplex splits "
      "each "
      "quadrilateral into 8 triangles (hexahedron into 24 "
      "tetrahedra); automatic is quadrilateral. gmsh with a "
      ".geo: Gmsh makes triangles/tetrahedra, or recombined "
      "quadrilaterals (hexahedra: tetrahedra split into "
      "four); automatic is what the .geo says (Gmsh's "
      "default: simplices).");
    prm.declare_entry("Mesh size",
                      entry_text::of(defaults.mesh_size),
                      Patterns::Double(0.),
                      "gmsh with a .geo: target cell size [mm] everywhere; 0 "
                      "keeps the sizes the .geo gives.");
    prm.declare_entry("Center",
                      entry_text::of(defaults.center),
                      Patterns::Anything(),
                      "half ball, quarter disk, quarter ball: center of the "
                      "flat face [mm].");
    prm.declare_entry("Radius",
                      entry_text::of(defaults.radius),
                      Patterns::Double(0.),
                      "half ball, quarter disk, quarter ball: radius [mm].");
    prm.declare_entry("Mesh file",
                      entry_text::of(defaults.mesh_file),
                      Patterns::Anything(),
                      "gmsh: a .msh mesh, or a .geo geometry that Gmsh "
                      "meshes when the run starts (and remeshes for kelly "
                      "cycles on simplices), relative to the folder of the "
                      "parameter file. Physical groups of boundary lines "
                      "(faces in 3D) give the boundary ids.");
    prm.declare_entry("Initial refinement",
                      entry_text::of(defaults.initial_refinement),
                      Patterns::Integer(0, 12),
                      "Global refinements of the coarse mesh before cycle 0 "
                      "(a .geo: Gmsh's sizes divided by 2^k).");
    prm.declare_entry("Element degree",
                      entry_text::of(defaults.element_degree),
                      Patterns::Integer(1, 2),
                      "Polynomial degree of the displacement: 1 (Q1, P1) or "
                      "2 (Q2 on quadrilaterals/hexahedra, P2 on "
                      "triangles/tetrahedra; the cells follow curved "
                      "boundaries by a mapping of degree 2, and contact "
                      "holds at every node of the contact faces, vertices "
                      "and mid-nodes).");
    prm.leave_subsection();
  }

  template <int dim>
  void
  Geometry<dim>::parse_parameters(ParameterHandler               &prm,
                                  const std::vector<std::string> &folders)
  {
    prm.enter_subsection("Geometry");
    type = shape_types<dim>.value(prm.get("Type"), "Geometry/Type");
    if (type == Type::quarter_disk && dim != 2)
      throw InputError("Geometry/Type",
                       "quarter disk is a two-dimensional shape; use half "
                       "ball in 3D");
    if (type == Type::quarter_ball && dim != 3)
      throw InputError("Geometry/Type",
                       "quarter ball is a three-dimensional shape; use "
                       "quarter disk in 2D");
    if (type == Type::rectangle)
      {
        lower_left   = parse::point<dim>(prm.get("Lower left corner"),
                                       "Geometry/Lower left corner");
        upper_right  = parse::point<dim>(prm.get("Upper right corner"),
                                        "Geometry/Upper right corner");
        subdivisions = parse::unsigned_list(prm.get("Subdivisions"),
                                            dim,
                                            "Geometry/Subdivisions");
        for (unsigned int d = 0; d < dim; ++d)
          if (!(lower_left[d] < upper_right[d]))
            throw InputError("Geometry/Upper right corner",
                             "must exceed the lower left corner in every "
                             "coordinate");
        check_size(lower_left, "Geometry/Lower left corner");
        check_size(upper_right, "Geometry/Upper right corner");
      }
    cell_type = cell_types.value(prm.get("Cell type"), "Geometry/Cell type");
    mesh_size = prm.get_double("Mesh size");
    if (type == Type::half_ball || type == Type::quarter_disk ||
        type == Type::quarter_ball)
      {
        center = parse::point<dim>(prm.get("Center"), "Geometry/Center");
        radius = prm.get_double("Radius");
        if (!(radius > 0))
          throw InputError("Geometry/Radius", "must be positive");
        check_size(center, "Geometry/Center");
        Point<dim> far;
        far[0] = radius;
        check_size(far, "Geometry/Radius");
      }
    if (type == Type::gmsh)
      {
        mesh_file = prm.get("Mesh file");
        if (mesh_file.empty())
          throw InputError("Geometry/Mesh file", "is required for Type = gmsh");
        if (mesh_file[0] != '/')
          {
            // The first folder that holds it (else the first, for the
            // error below).
            const std::string name = mesh_file;
            mesh_file              = folders.front() + "/" + name;
            for (const auto &folder : folders)
              if (std::ifstream(folder + "/" + name))
                {
                  mesh_file = folder + "/" + name;
                  break;
                }
          }
        std::error_code error;
        if (std::filesystem::is_directory(mesh_file, error))
          throw InputError("Geometry/Mesh file",
                           "'" + mesh_file + "' is a directory, not a mesh");
        if (!std::ifstream(mesh_file))
          throw InputError("Geometry/Mesh file",
                           "cannot open '" + mesh_file + "'" +
                             (errno != ENOENT ?
                                std::string(": ") + std::strerror(errno) :
                                std::string()));
      }
    initial_refinement = prm.get_integer("Initial refinement");
    element_degree     = prm.get_integer("Element degree");
    prm.leave_subsection();
  }

  template <int dim>
  Point<dim>
  Geometry<dim>::point_with(const double coordinate, const double last)
  {
    Point<dim> p;
    for (unsigned int d = 0; d + 1 < dim; ++d)
      p[d] = coordinate;
    p[dim - 1] = last;
    return p;
  }

  template <int dim>
  bool
  Geometry<dim>::from_geometry_file() const
  {
    return type == Type::gmsh && mesh_file.size() > 4 &&
           mesh_file.substr(mesh_file.size() - 4) == ".geo";
  }

  template <int dim>
  GmshOptions
  Geometry<dim>::gmsh_options() const
  {
    GmshOptions options;
    options.cell_type   = cell_type;
    options.size        = mesh_size;
    options.size_factor = std::pow(0.5, initial_refinement);
    return options;
  }

  template <int dim>
  void
  Geometry<dim>::create_coarse_mesh(Triangulation<dim> &coarse_mesh,
                                    const MPI_Comm      comm) const
  {
    const bool simplex = cell_type == GmshOptions::CellType::simplex;
    switch (type)
      {
        case Type::rectangle:
          {
            double n_cells = simplex ? (dim == 2 ? 8 : 24) : 1;
            for (const unsigned int n : subdivisions)
              n_cells *= n;
            refuse_oversized_mesh(*this, n_cells, simplex, true, comm);
            Triangulation<dim> quads;
            GridGenerator::subdivided_hyper_rectangle(simplex ? quads :
                                                                coarse_mesh,
                                                      subdivisions,
                                                      lower_left,
                                                      upper_right,
                                                      /*colorize=*/true);
            if (simplex)
              GridGenerator::convert_hypercube_to_simplex_mesh(quads,
                                                               coarse_mesh);
            break;
          }
        case Type::half_ball:
          {
            // deal.II's half ball lies at x >= 0; turn it so that the curved
            // face points down (-y in 2D, -z in 3D), then move it to Center.
            GridGenerator::half_hyper_ball(coarse_mesh, Point<dim>(), radius);
            const Point<dim> c = center;
            GridTools::transform(
              [c](const Point<dim> &p) {
                Point<dim> q = c;
                q[0] += p[dim - 1];
                if (dim == 3)
                  q[1] += p[1];
                q[dim - 1] -= p[0];
                return q;
              },
              coarse_mesh);
            coarse_mesh.set_manifold(0, SphericalManifold<dim>(center));
            break;
          }
        case Type::quarter_disk:
          {
            // deal.II's quarter disk lies at x, y >= 0; turn it by -90
            // degrees so that the curved face points down, move it to
            // Center, and give the symmetry line x = Center x its own id.
            GridGenerator::quarter_hyper_ball(coarse_mesh,
                                              Point<dim>(),
                                              radius);
            const Point<dim> c = center;
            GridTools::transform(
              [c](const Point<dim> &p) {
                Point<dim> q = c;
                q[0] += p[1];
                q[1] -= p[0];
                return q;
              },
              coarse_mesh);
            for (const auto &face : coarse_mesh.active_face_iterators())
              if (face->at_boundary() && face->boundary_id() == 1 &&
                  std::abs(face->center()[0] - c[0]) < 1e-10 * radius)
                face->set_boundary_id(2);
            coarse_mesh.set_manifold(0, SphericalManifold<dim>(center));
            break;
          }
        case Type::quarter_ball:
          {
            // deal.II's eighth of a ball lies at x, y, z >= 0; turn it about
            // y so that the curved face points down, move it to Center, and
            // give the symmetry planes x = Center x and y = Center y their
            // own ids (the third cut face is the flat top, id 1).
            GridGenerator::quarter_hyper_ball(coarse_mesh,
                                              Point<dim>(),
                                              radius);
            const Point<dim> c = center;
            GridTools::transform(
              [c](const Point<dim> &p) {
                Point<dim> q = c;
                q[0] += p[dim - 1];
                q[1] += p[1];
                q[dim - 1] -= p[0];
                return q;
              },
              coarse_mesh);
            for (const auto &face : coarse_mesh.active_face_iterators())
              if (face->at_boundary() && face->boundary_id() == 1)
                {
                  if (std::abs(face->center()[0] - c[0]) < 1e-10 * radius)
                    face->set_boundary_id(2);
                  else if (std::abs(face->center()[1] - c[1]) < 1e-10 * radius)
                    face->set_boundary_id(3);
                }
            coarse_mesh.set_manifold(0, SphericalManifold<dim>(center));
            break;
          }
        case Type::gmsh:
          {
            if (from_geometry_file())
              {
                mesh_geometry_file(mesh_file,
                                   gmsh_options(),
                                   coarse_mesh,
                                   comm);
                // Quadrilaterals and hexahedra are refined, not remeshed:
                // their new boundary vertices follow the .geo's curves.
                // Cells of degree 2 put their mid-nodes on them.
                if (coarse_mesh.all_reference_cells_are_hyper_cube() ||
                    element_degree > 1)
                  attach_gmsh_geometry(coarse_mesh, mesh_file, comm);
              }
            else
              {
                std::ifstream     file(mesh_file, std::ios::binary);
                const std::string bytes((std::istreambuf_iterator<char>(file)),
                                        std::istreambuf_iterator<char>());
                if (const auto problem = msh_problem(bytes))
                  throw InputError("Geometry/Mesh file",
                                   "'" + mesh_file + "' " + *problem);
                std::istringstream input(bytes);
                read_msh(input, mesh_file, coarse_mesh);
              }
            break;
          }
      }
    if (type != Type::rectangle)
      refuse_oversized_mesh(*this,
                            coarse_mesh.n_active_cells(),
                            !coarse_mesh.all_reference_cells_are_hyper_cube(),
                            !from_geometry_file(),
                            comm);
  }

  template struct Geometry<2>;
  template struct Geometry<3>;
} // namespace signorini
