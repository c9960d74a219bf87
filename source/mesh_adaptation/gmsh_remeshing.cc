#include <deal.II/base/mpi.h>
#include <deal.II/distributed/fully_distributed_tria.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/tria_description.h>

#include <signorini/discretisation/gmsh_geometry.h>
#include <signorini/discretisation/gmsh_mesher.h>
#include <signorini/mesh_adaptation/gmsh_remeshing.h>
#include <signorini/mesh_adaptation/node_transfer.h>
#include <signorini/mesh_adaptation/size_field.h>

#include <cmath>

namespace signorini
{
  using namespace dealii;

  template <int dim>
  GmshRemeshing<dim>::GmshRemeshing(const Geometry<dim> &geometry,
                                    const Refinement    &refinement,
                                    const MPI_Comm       comm)
    : geometry(geometry)
    , refinement(refinement)
    , comm(comm)
  {
  }

  template <int dim>
  std::unique_ptr<Triangulation<dim>>
  GmshRemeshing<dim>::create_mesh(const Triangulation<dim> &coarse_mesh)
  {
    serial.copy_triangulation(coarse_mesh);
    // A .geo was meshed with its initial refinement already.
    if (!geometry.from_geometry_file())
      serial.refine_global(geometry.initial_refinement);
    return distribute();
  }

  template <int dim>
  std::vector<typename GmshRemeshing<dim>::VectorType>
  GmshRemeshing<dim>::adapt(std::unique_ptr<Triangulation<dim>> &triangulation,
                            const DoFHandler<dim>               &dof_handler,
                            const Vector<float>                 &indicators,
                            const std::function<void()>         &setup_system,
                            const std::vector<const VectorType *> &vectors)
  {
    const NodeTransfer<dim> transfer(serial, dof_handler, vectors, comm);

    // The indicators of every cell of the serial mesh, on every process:
    // the cells of a fully distributed triangulation are the serial mesh's
    // coarse cells.
    std::vector<double> eta(serial.n_active_cells(), 0.);
    const bool          distributed = Utilities::MPI::n_mpi_processes(comm) > 1;
    for (const auto &cell : triangulation->active_cell_iterators())
      if (cell->is_locally_owned())
        eta[distributed ? cell->id().get_coarse_cell_id() :
                          cell->active_cell_index()] =
          indicators[cell->active_cell_index()];
    Utilities::MPI::sum(eta, comm, eta);

    Triangulation<dim> next;
    if (!geometry.from_geometry_file())
      {
        next.copy_triangulation(serial);
        next.refine_global(1);
      }
    else
      {
        GmshOptions                     options = geometry.gmsh_options();
        std::unique_ptr<SizeField<dim>> field;
        if (refinement.strategy == Refinement::Strategy::global)
          options.size_factor *= std::pow(0.5, ++level);
        else if (Utilities::MPI::this_mpi_process(comm) == 0)
          {
            const double d = dim;
            const double growth =
              1. + (std::pow(2., d) - 1.) * refinement.refine_fraction -
              (1. - std::pow(2., -d)) * refinement.coarsen_fraction;
            const auto corners =
              GridTools::compute_bounding_box(serial).get_boundary_points();
            field =
              std::make_unique<SizeField<dim>>(serial,
                                               eta,
                                               growth,
                                               1e-5 * corners.first.distance(
                                                        corners.second));
            options.size        = 0.;
            options.size_factor = 1.;
            options.min_size    = field->smallest;
            options.max_size    = field->largest;
            options.size_field  = [&field](const Point<3> &p) {
              return (*field)(p);
            };
          }
        mesh_geometry_file(geometry.mesh_file, options, next, comm);
        // P2's mid-nodes on the .geo's curves.
        if (geometry.element_degree > 1)
          attach_gmsh_geometry(next, geometry.mesh_file, comm);
      }
    serial.clear();
    serial.copy_triangulation(next);

    // The new mesh replaces the old one once the dofs live on it.
    auto old = distribute();
    std::swap(triangulation, old);
    setup_system();
    return transfer.interpolate(dof_handler);
  }

  template <int dim>
  std::unique_ptr<Triangulation<dim>>
  GmshRemeshing<dim>::distribute() const
  {
    const unsigned int n_processes = Utilities::MPI::n_mpi_processes(comm);
    if (n_processes == 1)
      {
        auto triangulation = std::make_unique<Triangulation<dim>>();
        triangulation->copy_triangulation(serial);
        return triangulation;
      }
    // The first process partitions; all take its partition.
    Triangulation<dim> partitioned;
    partitioned.copy_triangulation(serial);
    std::vector<unsigned int> owner(partitioned.n_active_cells());
    if (Utilities::MPI::this_mpi_process(comm) == 0)
      {
        GridTools::partition_triangulation(n_processes, partitioned);
        for (const auto &cell : partitioned.active_cell_iterators())
          owner[cell->active_cell_index()] = cell->subdomain_id();
      }
    owner = Utilities::MPI::broadcast(comm, owner, 0);
    for (const auto &cell : partitioned.active_cell_iterators())
      cell->set_subdomain_id(owner[cell->active_cell_index()]);
    const auto description = TriangulationDescription::Utilities::
      create_description_from_triangulation(partitioned, comm);
    auto triangulation =
      std::make_unique<parallel::fullydistributed::Triangulation<dim>>(comm);
    for (const auto id : serial.get_manifold_ids())
      if (id != numbers::flat_manifold_id)
        triangulation->set_manifold(id, serial.get_manifold(id));
    triangulation->create_triangulation(description);
    return triangulation;
  }

  template class GmshRemeshing<2>;
  template class GmshRemeshing<3>;
} // namespace signorini
