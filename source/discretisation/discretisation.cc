#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/distributed/tria.h>
#include <deal.II/dofs/dof_renumbering.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_simplex_p.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/mapping_q.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/numerics/vector_tools.h>

#include <signorini/base/owned_values.h>
#include <signorini/discretisation/discretisation.h>
#include <signorini/discretisation/simplex_mapping.h>
#include <signorini/discretisation/vertex_values.h>
#include <signorini/input/input_error.h>
#include <signorini/input/parsed_function.h>

#include <algorithm>
#include <cstring>

namespace signorini
{
  using namespace dealii;

  namespace
  {
    /** The rule of the lumped contact masses at degree 2: points at the
     * nodes of a face, with positive weights. Quadrilateral faces and
     * edges: Gauss-Lobatto (1/6, 4/6, 1/6 along an edge, their tensor
     * products on a square). A triangle's P2 nodes have no positive rule
     * exact to degree 2 (its vertex weights vanish), so a triangle is
     * lumped as the four triangles its mid-nodes cut it into, each P1
     * lumped: a twelfth of the area at a vertex, a quarter at a mid-node
     * (exact to degree 1). Degree 1: the face's Gauss rule. */
    template <int dim>
    Quadrature<dim - 1>
    contact_nodes_rule(const ReferenceCell       &cell_type,
                       const unsigned int         degree,
                       const Quadrature<dim - 1> &face_rule)
    {
      if (degree == 1)
        return face_rule;
      if (dim == 2 || cell_type.is_hyper_cube())
        return QGaussLobatto<dim - 1>(degree + 1);
      std::vector<Point<dim - 1>>                points(6);
      std::vector<double>                        weights(6);
      const std::array<std::array<double, 2>, 6> at = {{{{0., 0.}},
                                                        {{1., 0.}},
                                                        {{0., 1.}},
                                                        {{.5, 0.}},
                                                        {{.5, .5}},
                                                        {{0., .5}}}};
      for (unsigned int i = 0; i < 6; ++i)
        {
          for (unsigned int d = 0; d < dim - 1; ++d)
            points[i][d] = at[i][d];
          // The reference triangle's area is 1/2.
          weights[i] = i < 3 ? 0.5 / 12 : 0.5 / 4;
        }
      return Quadrature<dim - 1>(points, weights);
    }
  } // namespace

  template <int dim>
  Discretisation<dim>::Discretisation(
    const Geometry<dim>           &geometry,
    const AdaptationFactory       &adaptation,
    const BoundaryConditions<dim> &boundary_conditions,
    const MPI_Comm                 mpi_communicator,
    const bool                     axisymmetric)
    : geometry(geometry)
    , adaptation_factory(adaptation)
    , boundary_conditions(boundary_conditions)
    , communicator(mpi_communicator)
    , axisymmetric_model(axisymmetric)
  {
  }

  // Defined here, where MeshAdaptation is a complete type.
  template <int dim>
  Discretisation<dim>::~Discretisation()
  {
    dofs.clear();
  }

  template <int dim>
  void
  Discretisation<dim>::make_grid(const BoundaryIdUse &boundary_ids)
  {
    Triangulation<dim> coarse_mesh;
    geometry.create_coarse_mesh(coarse_mesh, communicator);
    if (coarse_mesh.get_reference_cells().size() > 1)
      throw InputError("Geometry/Mesh file",
                       "the mesh mixes cell types; it must hold only "
                       "quadrilaterals/hexahedra or only triangles/tetrahedra");
    simplex_cells       = !coarse_mesh.all_reference_cells_are_hyper_cube();
    const auto mesh_ids = coarse_mesh.get_boundary_ids();
    for (const auto &[entry, ids] : boundary_ids)
      for (const auto id : ids)
        if (std::find(mesh_ids.begin(), mesh_ids.end(), id) == mesh_ids.end())
          {
            std::string known;
            for (const auto mesh_id : mesh_ids)
              known += (known.empty() ? "" : ", ") + std::to_string(mesh_id);
            throw InputError(entry,
                             "boundary id " + std::to_string(id) +
                               " is not on the mesh, whose boundary ids are " +
                               known);
          }
    // The same on every process: the coarse mesh is complete on each.
    const auto corners =
      GridTools::compute_bounding_box(coarse_mesh).get_boundary_points();
    diagonal = corners.first.distance(corners.second);
    if (axisymmetric_model)
      axisymmetry::check_side_of_axis(coarse_mesh,
                                      geometry,
                                      axisymmetry::axis_tolerance(diagonal));

    mesh_adaptation = adaptation_factory(simplex_cells);
    mesh            = mesh_adaptation->create_mesh(coarse_mesh);

    const ReferenceCell cell_type = mesh->get_reference_cells()[0];
    const unsigned int  degree    = geometry.element_degree;
    if (simplex_cells)
      element = std::make_unique<FESystem<dim>>(FE_SimplexP<dim>(degree), dim);
    else
      element = std::make_unique<FESystem<dim>>(FE_Q<dim>(degree), dim);
    linear_mapping = &cell_type.template get_default_linear_mapping<dim>();
    // Degree 2: the cells follow the manifolds of curved boundaries (the
    // generated shapes' spheres, a .geo's curves) with their mid-nodes.
    if (degree > 1 && simplex_cells)
      curved_mapping = std::make_unique<SimplexMapping<dim>>();
    else if (degree > 1)
      curved_mapping = std::make_unique<MappingQ<dim>>(degree);
    cell_rule = cell_type.template get_gauss_type_quadrature<dim>(degree + 1);
    face_rule = cell_type.face_reference_cell(0)
                  .template get_gauss_type_quadrature<dim - 1>(degree + 1);
    contact_face_rule = contact_nodes_rule<dim>(cell_type, degree, face_rule);
    setup_dofs();
  }

  template <int dim>
  void
  Discretisation<dim>::setup_dofs()
  {
    dofs.reinit(*mesh);
    dofs.distribute_dofs(*element);
    // The numbering deal.II gives follows the order in which the cells
    // were made, so that a mesh loaded from a checkpoint is numbered unlike
    // the same mesh refined cycle by cycle, and the iterative solvers'
    // digits differ. The order of the cell hierarchy (from each coarse
    // cell down) depends on the mesh alone: a resumed run repeats the
    // uninterrupted one.
    if (saves_mesh())
      DoFRenumbering::hierarchical(dofs);
    owned_dofs = dofs.locally_owned_dofs();
    DoFTools::extract_locally_relevant_dofs(dofs, relevant_dofs);

    hanging_nodes.clear();
    hanging_nodes.reinit(relevant_dofs);
    DoFTools::make_hanging_node_constraints(dofs, hanging_nodes);
    hanging_nodes.close();

    make_fixed_constraints();

    supported_dofs.clear();
    supported_dofs.set_size(dofs.n_dofs());
    for (const auto &[id, mask] : boundary_conditions.dirichlet)
      supported_dofs.add_indices(
        DoFTools::extract_boundary_dofs(dofs, mask, {id}));
  }

  template <int dim>
  void
  Discretisation<dim>::set_time(const double t)
  {
    boundary_conditions.prescribed_displacement->set_time(t);
    if (mesh && dofs.has_active_dofs())
      make_fixed_constraints();
  }

  template <int dim>
  void
  Discretisation<dim>::make_fixed_constraints()
  {
    // The hanging nodes' lines, already closed (merged faster than made
    // anew), then the Dirichlet lines of the dofs they leave free.
    fixed_constraints.clear();
    fixed_constraints.reinit(relevant_dofs);
    fixed_constraints.merge(hanging_nodes);
    for (const auto &[id, mask] : boundary_conditions.dirichlet)
      VectorTools::interpolate_boundary_values(
        mapping(),
        dofs,
        id,
        *boundary_conditions.prescribed_displacement,
        fixed_constraints,
        mask);
    check_finite(*boundary_conditions.prescribed_displacement, communicator);
    if (axisymmetric_model)
      axisymmetry::add_axis_constraints(dofs,
                                        relevant_dofs,
                                        axisymmetry::axis_tolerance(diagonal),
                                        fixed_constraints);
    fixed_constraints.close();
  }

  template <int dim>
  std::vector<typename Discretisation<dim>::VectorType>
  Discretisation<dim>::refine(const Vector<float>                   &indicators,
                              const std::vector<const VectorType *> &vectors)
  {
    auto carried = mesh_adaptation->adapt(
      mesh, dofs, indicators, [this]() { setup_dofs(); }, vectors);
    if (!carried.empty())
      fixed_constraints.distribute(carried[0]);
    return carried;
  }

  template <int dim>
  bool
  Discretisation<dim>::saves_mesh() const
  {
    return dynamic_cast<const parallel::distributed::Triangulation<dim> *>(
             mesh.get()) != nullptr;
  }

  template <int dim>
  void
  Discretisation<dim>::save(const std::string                     &file,
                            const std::vector<const VectorType *> &vectors,
                            const Vector<float> &cell_data) const
  {
    auto &distributed =
      dynamic_cast<parallel::distributed::Triangulation<dim> &>(*mesh);
    // The vectors (variable-size data), then the cell values (fixed-size);
    // load() unpacks them in that order.
    VertexValues<dim>::attach(dofs, vectors);
    distributed.register_data_attach(
      [&cell_data](const auto &cell, const auto) {
        const float       value = cell_data(cell->active_cell_index());
        std::vector<char> data(sizeof(value));
        std::memcpy(data.data(), &value, sizeof(value));
        return data;
      },
      false);
    distributed.save(file);
  }

  template <int dim>
  void
  Discretisation<dim>::load(const std::string               &file,
                            const std::vector<VectorType *> &vectors,
                            Vector<float>                   &cell_data)
  {
    // The saved mesh is loaded into its coarse mesh.
    Triangulation<dim> coarse_mesh;
    geometry.create_coarse_mesh(coarse_mesh, communicator);
    auto loaded = std::make_unique<parallel::distributed::Triangulation<dim>>(
      communicator, mesh->get_mesh_smoothing());
    loaded->copy_triangulation(coarse_mesh);
    loaded->load(file);
    dofs.reinit(*loaded);
    mesh = std::move(loaded);
    setup_dofs();

    for (auto *vector : vectors)
      vector->reinit(owned_dofs, communicator);
    VertexValues<dim>::restore(dofs, vectors);

    auto &distributed =
      dynamic_cast<parallel::distributed::Triangulation<dim> &>(*mesh);
    cell_data.reinit(mesh->n_active_cells());
    const unsigned int handle = distributed.register_data_attach(
      [](const auto &, const auto) { return std::vector<char>(); }, false);
    distributed.notify_ready_to_unpack(
      handle, [&cell_data](const auto &cell, const auto, const auto &data) {
        float value;
        std::memcpy(&value, &*data.begin(), sizeof(value));
        cell_data(cell->active_cell_index()) = value;
      });
  }

  template <int dim>
  void
  Discretisation<dim>::refine_globally(const unsigned int times)
  {
    mesh->refine_global(times);
    setup_dofs();
  }

  template <int dim>
  double
  Discretisation<dim>::minimal_cell_diameter() const
  {
    return GridTools::minimal_cell_diameter(*mesh);
  }

  template <int dim>
  double
  Discretisation<dim>::body_size() const
  {
    return diagonal;
  }

  template <int dim>
  bool
  Discretisation<dim>::simplex() const
  {
    return simplex_cells;
  }

  template <int dim>
  bool
  Discretisation<dim>::axisymmetric() const
  {
    return axisymmetric_model;
  }

  template <int dim>
  const Triangulation<dim> &
  Discretisation<dim>::triangulation() const
  {
    return *mesh;
  }

  template <int dim>
  const DoFHandler<dim> &
  Discretisation<dim>::dof_handler() const
  {
    return dofs;
  }

  template <int dim>
  const FiniteElement<dim> &
  Discretisation<dim>::fe() const
  {
    return *element;
  }

  template <int dim>
  const Mapping<dim> &
  Discretisation<dim>::mapping() const
  {
    return curved_mapping ? *curved_mapping : *linear_mapping;
  }

  template <int dim>
  unsigned int
  Discretisation<dim>::degree() const
  {
    return geometry.element_degree;
  }

  template <int dim>
  bool
  Discretisation<dim>::curved(
    const typename Triangulation<dim>::cell_iterator &cell) const
  {
    return curved_mapping && !on_flat_manifolds(cell);
  }

  template <int dim>
  const Quadrature<dim> &
  Discretisation<dim>::quadrature() const
  {
    return cell_rule;
  }

  template <int dim>
  const Quadrature<dim - 1> &
  Discretisation<dim>::face_quadrature() const
  {
    return face_rule;
  }

  template <int dim>
  const Quadrature<dim - 1> &
  Discretisation<dim>::contact_face_quadrature() const
  {
    return contact_face_rule;
  }

  template <int dim>
  Quadrature<dim - 1>
  Discretisation<dim>::fine_face_quadrature() const
  {
    if (simplex_cells && dim == 3)
      return QGaussSimplex<dim - 1>(4);
    return QGauss<dim - 1>(6);
  }

  template <int dim>
  const IndexSet &
  Discretisation<dim>::locally_owned_dofs() const
  {
    return owned_dofs;
  }

  template <int dim>
  const IndexSet &
  Discretisation<dim>::locally_relevant_dofs() const
  {
    return relevant_dofs;
  }

  template <int dim>
  const AffineConstraints<double> &
  Discretisation<dim>::hanging_node_constraints() const
  {
    return hanging_nodes;
  }

  template <int dim>
  const AffineConstraints<double> &
  Discretisation<dim>::constraints() const
  {
    return fixed_constraints;
  }

  template <int dim>
  const IndexSet &
  Discretisation<dim>::support_dofs() const
  {
    return supported_dofs;
  }

  template <int dim>
  MPI_Comm
  Discretisation<dim>::mpi_communicator() const
  {
    return communicator;
  }

  template <int dim>
  LinearAlgebra::distributed::Vector<double>
  Discretisation<dim>::relevant_copy(
    const TrilinosWrappers::MPI::Vector &vector) const
  {
    LinearAlgebra::distributed::Vector<double> copy(owned_dofs,
                                                    relevant_dofs,
                                                    communicator);
    copy_owned(vector, owned_dofs, copy);
    copy.update_ghost_values();
    return copy;
  }

  template class Discretisation<2>;
  template class Discretisation<3>;
} // namespace signorini
