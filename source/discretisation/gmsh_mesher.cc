#include <deal.II/base/exceptions.h>
#include <deal.II/base/mpi.h>
#include <deal.II/grid/grid_in.h>

#include <signorini/discretisation/gmsh_mesher.h>
#include <signorini/input/input_error.h>

#include <filesystem>
#include <fstream>
#include <gmsh.h>
#include <sstream>
#include <unistd.h>
#include <vector>

namespace signorini
{
  using namespace dealii;

  namespace
  {
    /** Gmsh's error messages since the last call, joined into one line. */
    std::string
    gmsh_errors()
    {
      std::vector<std::string> log;
      gmsh::logger::get(log);
      gmsh::logger::stop();
      gmsh::logger::start();
      std::string errors;
      for (const auto &line : log)
        if (line.rfind("Error: ", 0) == 0)
          {
            const std::string message = line.substr(7);
            if (message.find_first_not_of("- ") == std::string::npos ||
                message.find("error summary") != std::string::npos ||
                message.find("warnings") != std::string::npos ||
                message.find(" error") == 1 ||
                message.find("full log") != std::string::npos)
              continue;
            errors += (errors.empty() ? "" : "; ") + message;
          }
      return errors;
    }

    /**
     * Runs Gmsh on @p geo_file; returns the .msh text, or throws a
     * std::runtime_error with Gmsh's reason.
     */
    std::string
    run_gmsh(const std::string &geo_file,
             const GmshOptions &options,
             const int          dim)
    {
      // A fresh Gmsh session per mesh: its options start from their
      // defaults. Errors must not throw inside Gmsh (they would cross its
      // OpenMP regions and abort): they are read from its log instead.
      struct Session
      {
        Session()
        {
          gmsh::initialize(0, nullptr, /*readConfigFiles=*/false);
          gmsh::option::setNumber("General.Terminal", 0);
          gmsh::option::setNumber("General.AbortOnError", 0);
          gmsh::option::setNumber("General.NumThreads", 1);
          gmsh::logger::start();
        }
        ~Session()
        {
          gmsh::logger::stop();
          gmsh::finalize();
        }
      } session;
      gmsh::open(geo_file);
      std::string errors = gmsh_errors();
      if (!errors.empty())
        throw std::runtime_error(errors);

      gmsh::vectorpair entities;
      gmsh::model::getEntities(entities, dim);
      if (entities.empty())
        throw std::runtime_error(std::string("it defines no ") +
                                 (dim == 2 ? "surface" : "volume"));
      gmsh::vectorpair groups;
      gmsh::model::getPhysicalGroups(groups, dim);
      if (groups.empty())
        {
          std::vector<int> tags;
          for (const auto &entity : entities)
            tags.push_back(entity.second);
          gmsh::model::addPhysicalGroup(dim, tags);
        }

      using CellType = GmshOptions::CellType;
      if (options.cell_type == CellType::quadrilateral)
        {
          if (dim == 2)
            {
              gmsh::option::setNumber("Mesh.RecombineAll", 1);
              gmsh::option::setNumber("Mesh.Algorithm", 6);
              gmsh::option::setNumber("Mesh.RecombinationAlgorithm", 3);
            }
          else
            gmsh::option::setNumber("Mesh.SubdivisionAlgorithm", 2);
        }
      if (options.cell_type == CellType::simplex)
        {
          gmsh::option::setNumber("Mesh.RecombineAll", 0);
          gmsh::option::setNumber("Mesh.Recombine3DAll", 0);
          gmsh::option::setNumber("Mesh.SubdivisionAlgorithm", 0);
        }
      if (options.size > 0 || options.size_field)
        {
          gmsh::option::setNumber("Mesh.MeshSizeFromPoints", 0);
          gmsh::option::setNumber("Mesh.MeshSizeFromCurvature", 0);
          gmsh::option::setNumber("Mesh.MeshSizeExtendFromBoundary", 0);
        }
      if (options.size > 0)
        gmsh::option::setNumber("Mesh.MeshSizeMax", options.size);
      if (options.size_field)
        {
          const auto field = options.size_field;
          gmsh::model::mesh::setSizeCallback(
            [field](int, int, double x, double y, double z) {
              return field(Point<3>(x, y, z));
            });
        }
      if (options.min_size > 0)
        gmsh::option::setNumber("Mesh.MeshSizeMin", options.min_size);
      if (options.max_size > 0)
        gmsh::option::setNumber("Mesh.MeshSizeMax", options.max_size);
      gmsh::option::setNumber("Mesh.MeshSizeFactor", options.size_factor);

      gmsh::model::mesh::generate(dim);
      if (options.size_field)
        gmsh::model::mesh::removeSizeCallback();
      errors = gmsh_errors();
      if (!errors.empty())
        throw std::runtime_error(errors);
      std::vector<int> types;
      gmsh::model::mesh::getElementTypes(types, dim);
      if (types.empty())
        throw std::runtime_error("Gmsh made no cells");

      // Gmsh writes files only: go through a temporary one.
      static unsigned int counter = 0;
      const auto          msh     = std::filesystem::temp_directory_path() /
                       ("signorini-" + std::to_string(getpid()) + "-" +
                        std::to_string(counter++) + ".msh");
      gmsh::option::setNumber("Mesh.MshFileVersion", 2.2);
      gmsh::option::setNumber("Mesh.Binary", 0);
      gmsh::option::setNumber("Mesh.SaveAll", 0);
      gmsh::write(msh.string());
      errors = gmsh_errors();
      std::ifstream      input(msh);
      std::ostringstream text;
      text << input.rdbuf();
      std::error_code ignored;
      std::filesystem::remove(msh, ignored);
      if (!errors.empty() || text.str().empty())
        throw std::runtime_error(
          "cannot write the mesh to a temporary file" +
          (errors.empty() ? std::string() : ": " + errors));
      return text.str();
    }
  } // namespace

  template <int dim>
  void
  mesh_geometry_file(const std::string  &geo_file,
                     const GmshOptions  &options,
                     Triangulation<dim> &mesh,
                     const MPI_Comm      comm)
  {
    // The first process meshes; every process learns whether it worked.
    std::string msh, error;
    if (Utilities::MPI::this_mpi_process(comm) == 0)
      try
        {
          msh = run_gmsh(geo_file, options, dim);
        }
      catch (const std::exception &failure)
        {
          error = failure.what();
        }
      catch (...)
        {
          error = "Gmsh failed";
        }
    error = Utilities::MPI::broadcast(comm, error, 0);
    if (!error.empty())
      throw InputError("Geometry/Mesh file",
                       "Gmsh cannot mesh '" + geo_file + "': " + error);
    msh = Utilities::MPI::broadcast(comm, msh, 0);
    std::istringstream input(msh);
    read_msh(input, geo_file, mesh);
  }

  template <int dim>
  void
  read_msh(std::istream       &input,
           const std::string  &file_name,
           Triangulation<dim> &mesh)
  {
    GridIn<dim> grid_in;
    grid_in.attach_triangulation(mesh);
    try
      {
        grid_in.read_msh(input);
      }
    catch (const ExceptionBase &error)
      {
        throw InputError("Geometry/Mesh file",
                         "cannot read '" + file_name + "': " + one_line(error));
      }
  }

  template void
  mesh_geometry_file(const std::string &,
                     const GmshOptions &,
                     Triangulation<2> &,
                     const MPI_Comm);
  template void
  mesh_geometry_file(const std::string &,
                     const GmshOptions &,
                     Triangulation<3> &,
                     const MPI_Comm);
  template void
  read_msh(std::istream &, const std::string &, Triangulation<2> &);
  template void
  read_msh(std::istream &, const std::string &, Triangulation<3> &);
} // namespace signorini
