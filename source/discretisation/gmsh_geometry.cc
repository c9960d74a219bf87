#include <deal.II/grid/manifold.h>

#include <signorini/discretisation/gmsh_geometry.h>

#include <algorithm>
#include <gmsh.h>
#include <limits>
#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

namespace signorini
{
  using namespace dealii;

  namespace
  {
    /** The .geo whose model Gmsh holds for the manifolds, opened anew where
     * another user of Gmsh (the mesher, a CAD obstacle) finalised it or
     * opened another model. */
    class GeoModel
    {
    public:
      explicit GeoModel(const std::string &geo_file)
        : geo_file(geo_file)
      {
        std::lock_guard<std::mutex> lock(mutex);
        ensure_open();
      }

      /** The point of entity (@p entity_dim, @p tag) closest to @p p. */
      template <int dim>
      Point<dim>
      closest_point(const int         entity_dim,
                    const int         tag,
                    const Point<dim> &p) const
      {
        std::lock_guard<std::mutex> lock(mutex);
        ensure_open();
        std::vector<double> coordinates = {p[0], p[1], dim == 3 ? p[2] : 0.};
        std::vector<double> closest, parameters;
        gmsh::model::getClosestPoint(
          entity_dim, tag, coordinates, closest, parameters);
        Point<dim> q;
        for (unsigned int d = 0; d < dim; ++d)
          q[d] = closest[d];
        return q;
      }

    private:
      /** Opens the .geo in Gmsh unless its model is the current one. */
      void
      ensure_open() const
      {
        std::string current;
        try
          {
            gmsh::model::getCurrent(current);
          }
        catch (...)
          {
            current.clear();
          }
        if (!model_name.empty() && current == model_name)
          return;
        // (Harmless where Gmsh is initialised: it keeps its state.)
        gmsh::initialize(0, nullptr, /*readConfigFiles=*/false);
        gmsh::option::setNumber("General.Terminal", 0);
        gmsh::option::setNumber("General.AbortOnError", 0);
        gmsh::open(geo_file);
        gmsh::model::getCurrent(model_name);
      }

      const std::string   geo_file;
      mutable std::string model_name;
      mutable std::mutex  mutex;
    };

    /** A flat manifold whose new points go to the closest point of a Gmsh
     * entity. */
    template <int dim>
    class GmshEntityManifold : public FlatManifold<dim>
    {
    public:
      GmshEntityManifold(const std::shared_ptr<const GeoModel> &model,
                         const int                              entity_dim,
                         const int                              tag)
        : model(model)
        , entity_dim(entity_dim)
        , tag(tag)
      {
      }

      std::unique_ptr<Manifold<dim>>
      clone() const override
      {
        return std::make_unique<GmshEntityManifold<dim>>(model,
                                                         entity_dim,
                                                         tag);
      }

      Point<dim>
      project_to_manifold(const ArrayView<const Point<dim>> &,
                          const Point<dim> &candidate) const override
      {
        return model->template closest_point<dim>(entity_dim, tag, candidate);
      }

    private:
      const std::shared_ptr<const GeoModel> model;
      const int                             entity_dim;
      const int                             tag;
    };
  } // namespace

  template <int dim>
  void
  attach_gmsh_geometry(Triangulation<dim> &coarse_mesh,
                       const std::string  &geo_file,
                       const MPI_Comm)
  {
    const auto model = std::make_shared<const GeoModel>(geo_file);
    // The boundary entities: curves in 2D, surfaces in 3D; which of them
    // are straight (flat).
    gmsh::vectorpair entities;
    gmsh::model::getEntities(entities, dim - 1);
    std::map<int, bool> curved;
    for (const auto &[entity_dim, tag] : entities)
      {
        std::string type;
        gmsh::model::getType(entity_dim, tag, type);
        curved[tag] = type != "Line" && type != "Plane";
      }
    if (std::none_of(curved.begin(), curved.end(), [](const auto &entry) {
          return entry.second;
        }))
      return;

    // Each boundary face lies on the entity that holds its vertices and
    // comes closest to its center (a chord of a circle is not on it).
    double size = 0.;
    for (const auto &cell : coarse_mesh.active_cell_iterators())
      size = std::max(size, cell->diameter());
    const double                      tolerance = 1e-8 * size;
    std::map<int, types::manifold_id> manifold_of;
    for (const auto &cell : coarse_mesh.active_cell_iterators())
      for (const auto &face : cell->face_iterators())
        {
          if (!face->at_boundary())
            continue;
          int    best          = -1;
          double best_distance = std::numeric_limits<double>::max();
          for (const auto &[tag, is_curved] : curved)
            {
              bool holds = true;
              for (const unsigned int v : face->vertex_indices())
                if (model
                      ->template closest_point<dim>(dim - 1,
                                                    tag,
                                                    face->vertex(v))
                      .distance(face->vertex(v)) > tolerance)
                  {
                    holds = false;
                    break;
                  }
              if (!holds)
                continue;
              const Point<dim> center = face->center();
              const double     distance =
                model->template closest_point<dim>(dim - 1, tag, center)
                  .distance(center);
              if (distance < best_distance)
                {
                  best          = tag;
                  best_distance = distance;
                }
            }
          if (best < 0 || !curved[best])
            continue;
          const auto [entry, inserted] =
            manifold_of.emplace(best, 1000 + manifold_of.size());
          if (inserted)
            coarse_mesh.set_manifold(
              entry->second, GmshEntityManifold<dim>(model, dim - 1, best));
          face->set_manifold_id(entry->second);
          // In 3D the face's edges too (new points on an edge, a mapping's
          // mid-nodes on it, come from the edge's manifold), unless another
          // curved face has one for them.
          if (dim == 3)
            for (unsigned int l = 0; l < face->n_lines(); ++l)
              if (face->line(l)->manifold_id() == numbers::flat_manifold_id)
                face->line(l)->set_manifold_id(entry->second);
        }
  }

  template void
  attach_gmsh_geometry(Triangulation<2> &, const std::string &, MPI_Comm);
  template void
  attach_gmsh_geometry(Triangulation<3> &, const std::string &, MPI_Comm);
} // namespace signorini
