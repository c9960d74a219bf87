#include <signorini/contact/cad_obstacle.h>
#include <signorini/input/input_error.h>

#include <BRepAdaptor_Curve.hxx>
#include <BRepBndLib.hxx>
#include <BRepBuilderAPI_Copy.hxx>
#include <BRepBuilderAPI_MakeVertex.hxx>
#include <BRepClass3d_SolidClassifier.hxx>
#include <BRepClass_FaceClassifier.hxx>
#include <BRepExtrema_DistShapeShape.hxx>
#include <BRepGProp_Face.hxx>
#include <BRepMesh_IncrementalMesh.hxx>
#include <BRepTools.hxx>
#include <BRep_Builder.hxx>
#include <BRep_Tool.hxx>
#include <Bnd_Box.hxx>
#include <Extrema_ExtPC.hxx>
#include <GeomAPI_ProjectPointOnSurf.hxx>
#include <Poly_Triangulation.hxx>
#include <STEPControl_Reader.hxx>
#include <Standard_Failure.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopTools_IndexedDataMapOfShapeListOfShape.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Compound.hxx>
#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <gmsh.h>
#include <iostream>
#include <limits>
#include <mutex>
#include <unistd.h>
#include <vector>

namespace signorini
{
  using namespace dealii;

  namespace
  {
    /** Gmsh turns the .geo file @p geo into a temporary .brep file, whose
     * name it returns; throws InputError naming @p entry with Gmsh's
     * errors. */
    std::string
    brep_from_geo(const std::string &geo, const std::string &entry)
    {
      static unsigned int counter = 0;
      const auto          brep    = std::filesystem::temp_directory_path() /
                        ("signorini-" + std::to_string(getpid()) + "-tool-" +
                         std::to_string(counter++) + ".brep");
      gmsh::initialize(0, nullptr, /*readConfigFiles=*/false);
      gmsh::option::setNumber("General.Terminal", 0);
      gmsh::option::setNumber("General.AbortOnError", 0);
      gmsh::logger::start();
      gmsh::open(geo);
      gmsh::write(brep.string());
      std::vector<std::string> log;
      gmsh::logger::get(log);
      gmsh::logger::stop();
      gmsh::finalize();
      std::string errors;
      for (const auto &line : log)
        if (line.rfind("Error: ", 0) == 0)
          errors += (errors.empty() ? "" : "; ") + line.substr(7);
      if (!errors.empty())
        {
          std::error_code ignored;
          std::filesystem::remove(brep, ignored);
          throw InputError(entry,
                           "Gmsh cannot read '" + geo + "': " + errors +
                             (errors.find("OpenCASCADE") != std::string::npos ?
                                " (does the .geo begin with "
                                "SetFactory(\"OpenCASCADE\")?)" :
                                ""));
        }
      return brep.string();
    }

    std::string
    lower_case_extension(const std::string &file)
    {
      std::string extension = std::filesystem::path(file).extension();
      for (auto &c : extension)
        c = std::tolower(static_cast<unsigned char>(c));
      return extension;
    }

    /** Standard output silenced while it lives: OpenCASCADE's readers
     * print their progress and complaints there. */
    struct QuietStandardOutput
    {
      QuietStandardOutput()
        : saved(std::cout.rdbuf(nullptr))
      {
      }
      ~QuietStandardOutput()
      {
        std::cout.rdbuf(saved);
      }
      std::streambuf *saved;
    };

    /** The shape in @p file (.step/.stp, .brep/.brp, .geo). */
    TopoDS_Shape
    read_shape(const std::string &file, const std::string &entry)
    {
      const QuietStandardOutput quiet;
      const std::string         extension = lower_case_extension(file);
      TopoDS_Shape              shape;
      if (extension == ".step" || extension == ".stp")
        {
          STEPControl_Reader reader;
          if (reader.ReadFile(file.c_str()) != IFSelect_RetDone ||
              reader.TransferRoots() == 0)
            throw InputError(entry, "cannot read '" + file + "' as STEP");
          shape = reader.OneShape();
        }
      else if (extension == ".brep" || extension == ".brp" ||
               extension == ".geo")
        {
          const std::string brep =
            extension == ".geo" ? brep_from_geo(file, entry) : file;
          BRep_Builder builder;
          const bool   read = BRepTools::Read(shape, brep.c_str(), builder);
          if (extension == ".geo")
            {
              std::error_code ignored;
              std::filesystem::remove(brep, ignored);
            }
          if (!read)
            throw InputError(
              entry,
              "cannot read '" + file +
                (extension == ".geo" ?
                   "': Gmsh wrote no OpenCASCADE shape (does "
                   "it begin with SetFactory(\"OpenCASCADE\")?)" :
                   "' as BREP"));
        }
      else
        throw InputError(entry,
                         "'" + file +
                           "' is not a .step, .stp, .brep or .geo file");
      return shape;
    }

    gp_Pnt
    occ_point(const double *x, const unsigned int dim)
    {
      return gp_Pnt(x[0], x[1], dim == 3 ? x[2] : 0.);
    }
  } // namespace

  template <int dim>
  struct CadObstacle<dim>::Geometry
  {
    /** Volumes (3D) or surfaces in z = 0 (2D). */
    std::vector<TopoDS_Shape> parts;
    /** Their boundary: faces (3D) or edges (2D), as one compound. */
    TopoDS_Compound boundary;
    /** Faces (3D) or edges (2D) adjacent to each edge and corner. */
    TopTools_IndexedDataMapOfShapeListOfShape edge_neighbours,
      vertex_neighbours;
    /** The diagonal of the shape's bounding box [mm]. */
    double size = 1.;
    /** OpenCASCADE's queries one at a time (output evaluates gaps on
     * several threads). */
    std::mutex mutex;

    /** Whether @p p lies inside a part. */
    bool
    inside(const gp_Pnt &p) const
    {
      const double tolerance = 1e-9 * size;
      for (const auto &part : parts)
        if (dim == 3)
          {
            BRepClass3d_SolidClassifier classifier(part, p, tolerance);
            if (classifier.State() == TopAbs_IN)
              return true;
          }
        else
          {
            BRepClass_FaceClassifier classifier(TopoDS::Face(part),
                                                p,
                                                tolerance);
            if (classifier.State() == TopAbs_IN)
              return true;
          }
      return false;
    }

    /** The outward normal of the face (3D) or edge (2D) @p support at the
     * point @p q of it. */
    gp_Vec
    support_normal(const TopoDS_Shape &support, const gp_Pnt &q) const
    {
      gp_Vec normal;
      if (dim == 3)
        {
          const TopoDS_Face         &face = TopoDS::Face(support);
          GeomAPI_ProjectPointOnSurf projection(q, BRep_Tool::Surface(face));
          if (projection.NbPoints() == 0)
            return gp_Vec();
          double u, v;
          projection.LowerDistanceParameters(u, v);
          gp_Pnt point;
          BRepGProp_Face(face).Normal(u, v, point, normal);
        }
      else
        {
          const TopoDS_Edge &edge = TopoDS::Edge(support);
          BRepAdaptor_Curve  curve(edge);
          Extrema_ExtPC      projection(q, curve);
          double             t       = curve.FirstParameter();
          double             nearest = std::numeric_limits<double>::max();
          if (projection.IsDone())
            for (int i = 1; i <= projection.NbExt(); ++i)
              if (projection.SquareDistance(i) < nearest)
                {
                  nearest = projection.SquareDistance(i);
                  t       = projection.Point(i).Parameter();
                }
          gp_Pnt point;
          gp_Vec tangent;
          curve.D1(t, point, tangent);
          normal = gp_Vec(tangent.Y(), -tangent.X(), 0.);
        }
      if (normal.Magnitude() == 0)
        return normal;
      normal.Normalize();
      // Away from the part whatever the orientation of the face or edge.
      if (inside(q.Translated(1e-6 * size * normal)))
        normal.Reverse();
      return normal;
    }
  };

  template <int dim>
  CadObstacle<dim>::CadObstacle(const std::string &file,
                                const bool         body_inside,
                                const std::string &entry)
    : geometry(std::make_unique<Geometry>())
    , body_inside(body_inside)
    , file_entry(entry)
  {
    try
      {
        const TopoDS_Shape shape = read_shape(file, entry);
        BRep_Builder       builder;
        builder.MakeCompound(geometry->boundary);
        const TopAbs_ShapeEnum part_type =
                                 dim == 3 ? TopAbs_SOLID : TopAbs_FACE,
                               side_type = dim == 3 ? TopAbs_FACE : TopAbs_EDGE;
        for (TopExp_Explorer part(shape, part_type); part.More(); part.Next())
          {
            geometry->parts.push_back(part.Current());
            for (TopExp_Explorer side(part.Current(), side_type); side.More();
                 side.Next())
              builder.Add(geometry->boundary, side.Current());
            if (dim == 3)
              TopExp::MapShapesAndAncestors(part.Current(),
                                            TopAbs_EDGE,
                                            TopAbs_FACE,
                                            geometry->edge_neighbours);
            TopExp::MapShapesAndAncestors(part.Current(),
                                          TopAbs_VERTEX,
                                          side_type,
                                          geometry->vertex_neighbours);
          }
        if (geometry->parts.empty())
          throw InputError(entry,
                           "'" + file + "' holds no " +
                             (dim == 3 ? "volume" :
                                         "surface (in the plane z = 0)"));
        Bnd_Box box;
        BRepBndLib::Add(shape, box);
        double x0, y0, z0, x1, y1, z1;
        box.Get(x0, y0, z0, x1, y1, z1);
        geometry->size =
          std::max(std::sqrt((x1 - x0) * (x1 - x0) + (y1 - y0) * (y1 - y0) +
                             (z1 - z0) * (z1 - z0)),
                   1e-300);
        // A 2D scene's obstacle is a surface in z = 0: a solid's faces in
        // space are not (its section would be taken for the obstacle).
        if (dim == 2 && (TopExp_Explorer(shape, TopAbs_SOLID).More() ||
                         std::max(std::abs(z0), std::abs(z1)) >
                           box.GetGap() + 1e-9 * geometry->size))
          throw InputError(entry,
                           "'" + file +
                             "' holds a solid or surfaces outside the plane "
                             "z = 0 (a 3D geometry); a 2D scene's obstacle "
                             "is a surface in the plane z = 0");
      }
    catch (const Standard_Failure &failure)
      {
        throw InputError(entry,
                         "OpenCASCADE cannot read '" + file +
                           "': " + failure.GetMessageString());
      }
  }

  template <int dim>
  CadObstacle<dim>::~CadObstacle() = default;

  template <int dim>
  double
  CadObstacle<dim>::gap(const Point<dim> &x, Tensor<1, dim> &normal) const
  {
    std::lock_guard<std::mutex> lock(geometry->mutex);
    double                      coordinates[3] = {0., 0., 0.};
    for (unsigned int d = 0; d < dim; ++d)
      coordinates[d] = x[d];
    const gp_Pnt               p = occ_point(coordinates, dim);
    BRepExtrema_DistShapeShape extrema(BRepBuilderAPI_MakeVertex(p).Vertex(),
                                       geometry->boundary,
                                       Extrema_ExtFlag_MIN);
    normal = Tensor<1, dim>();
    if (!extrema.IsDone() || extrema.NbSolution() == 0)
      return std::numeric_limits<double>::quiet_NaN();
    const gp_Pnt q        = extrema.PointOnShape2(1);
    const double distance = extrema.Value();
    const bool   inside   = geometry->inside(p);
    gp_Vec       n;
    if (distance > 1e-9 * geometry->size)
      {
        n = gp_Vec(q, p) / distance;
        if (inside)
          n.Reverse();
      }
    else
      {
        // On the boundary: the normal of the face (edge) there, or the
        // mean of the adjacent ones at an edge or corner of the solid.
        const TopoDS_Shape support = extrema.SupportOnShape2(1);
        const auto         type    = extrema.SupportTypeShape2(1);
        if (type == BRepExtrema_IsInFace ||
            (dim == 2 && type == BRepExtrema_IsOnEdge))
          n = geometry->support_normal(support, q);
        else
          {
            const auto &neighbours = type == BRepExtrema_IsOnEdge ?
                                       geometry->edge_neighbours :
                                       geometry->vertex_neighbours;
            if (neighbours.Contains(support))
              for (const auto &side : neighbours.FindFromKey(support))
                n += geometry->support_normal(side, q);
          }
        if (n.Magnitude() > 0)
          n.Normalize();
      }
    double gap = inside ? -distance : distance;
    if (body_inside)
      {
        gap = -gap;
        n.Reverse();
      }
    for (unsigned int d = 0; d < dim; ++d)
      normal[d] = n.Coord(d + 1);
    return gap;
  }

  template <int dim>
  std::string
  CadObstacle<dim>::entry() const
  {
    return file_entry;
  }

  template <int dim>
  SurfaceMesh<dim>
  CadObstacle<dim>::surface(const BoundingBox<dim> &) const
  {
    std::lock_guard<std::mutex> lock(geometry->mutex);
    SurfaceMesh<dim>            mesh;
    const auto                  add_point = [&](const gp_Pnt &p) {
      Point<dim> point;
      for (unsigned int d = 0; d < dim; ++d)
        point[d] = p.Coord(d + 1);
      mesh.points.push_back(point);
      return static_cast<unsigned int>(mesh.points.size() - 1);
    };
    if (dim == 3)
      {
        // Tessellate a copy: the queries' shape stays as it was read.
        const TopoDS_Shape copy =
          BRepBuilderAPI_Copy(geometry->boundary).Shape();
        BRepMesh_IncrementalMesh(copy, 1e-3 * geometry->size, false, 0.2);
        for (TopExp_Explorer face(copy, TopAbs_FACE); face.More(); face.Next())
          {
            TopLoc_Location location;
            const Handle(Poly_Triangulation) &triangulation =
              BRep_Tool::Triangulation(TopoDS::Face(face.Current()), location);
            if (triangulation.IsNull())
              continue;
            const unsigned int first = mesh.points.size();
            for (int i = 1; i <= triangulation->NbNodes(); ++i)
              add_point(
                triangulation->Node(i).Transformed(location.Transformation()));
            for (int i = 1; i <= triangulation->NbTriangles(); ++i)
              {
                int a, b, c;
                triangulation->Triangle(i).Get(a, b, c);
                mesh.cells.push_back(
                  {first + a - 1, first + b - 1, first + c - 1});
              }
          }
      }
    else
      for (TopExp_Explorer edge(geometry->boundary, TopAbs_EDGE); edge.More();
           edge.Next())
        {
          BRepAdaptor_Curve  curve(TopoDS::Edge(edge.Current()));
          const unsigned int n     = 100;
          const double       first = curve.FirstParameter(),
                       last        = curve.LastParameter();
          for (unsigned int i = 0; i <= n; ++i)
            {
              const unsigned int index =
                add_point(curve.Value(first + (last - first) * i / n));
              if (i > 0)
                mesh.cells.push_back({index - 1, index});
            }
        }
    return mesh;
  }

  template class CadObstacle<2>;
  template class CadObstacle<3>;
} // namespace signorini
