#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_simplex_p.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/lac/trilinos_sparsity_pattern.h>
#include <deal.II/numerics/vector_tools.h>

#include <signorini/base/memory.h>
#include <signorini/input/input_error.h>
#include <signorini/mesh_adaptation/mesh_adaptation.h>
#include <signorini/problem/contact_problem.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <set>
#include <sstream>

namespace signorini
{
  using namespace dealii;

  template <int dim>
  ContactProblem<dim>::ContactProblem(const Parameters<dim> &parameters,
                                      const std::string     &parameter_text,
                                      const MPI_Comm         mpi_communicator)
    : parameters(parameters)
    , parameter_text(parameter_text)
    , mpi_communicator(mpi_communicator)
    , pcout(std::cout, Utilities::MPI::this_mpi_process(mpi_communicator) == 0)
    , timer(mpi_communicator,
            pcout,
            parameters.output.print_timings ? TimerOutput::summary :
                                              TimerOutput::never,
            TimerOutput::wall_times)
    , cell_stiffness(parameters.material)
    , linear_system_solver(parameters.linear_solver,
                           parameters.contact.remedies,
                           pcout,
                           timer)
  {
  }

  // Defined here, where MeshAdaptation is a complete type.
  template <int dim>
  ContactProblem<dim>::~ContactProblem()
  {
  }

  template <int dim>
  void
  ContactProblem<dim>::make_grid()
  {
    TimerOutput::Scope t(timer, "Setup: grid");
    Triangulation<dim> coarse_mesh;
    parameters.geometry.create_coarse_mesh(coarse_mesh, mpi_communicator);
    if (coarse_mesh.get_reference_cells().size() > 1)
      throw InputError("Geometry/Mesh file",
                       "the mesh mixes cell types; it must hold only "
                       "quadrilaterals/hexahedra or only triangles/tetrahedra");
    simplex = !coarse_mesh.all_reference_cells_are_hyper_cube();
    check_boundary_ids(coarse_mesh.get_boundary_ids());
    // The same on every process: the coarse mesh is complete on each.
    const auto corners =
      GridTools::compute_bounding_box(coarse_mesh).get_boundary_points();
    touching_tolerance = 1e-12 * corners.first.distance(corners.second);

    mesh_adaptation = create_mesh_adaptation(parameters.geometry,
                                             parameters.refinement,
                                             simplex,
                                             mpi_communicator);
    triangulation   = mesh_adaptation->create_mesh(coarse_mesh);

    const ReferenceCell cell_type = triangulation->get_reference_cells()[0];
    if (simplex)
      fe = std::make_unique<FESystem<dim>>(FE_SimplexP<dim>(1), dim);
    else
      fe = std::make_unique<FESystem<dim>>(FE_Q<dim>(1), dim);
    mapping         = &cell_type.template get_default_linear_mapping<dim>();
    quadrature      = cell_type.template get_gauss_type_quadrature<dim>(2);
    face_quadrature = cell_type.face_reference_cell(0)
                        .template get_gauss_type_quadrature<dim - 1>(2);
  }

  template <int dim>
  void
  ContactProblem<dim>::check_boundary_ids(
    const std::vector<types::boundary_id> &mesh_ids) const
  {
    const auto check = [&](const std::string                  &entry,
                           const std::set<types::boundary_id> &ids) {
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
    };
    std::set<types::boundary_id> dirichlet_ids;
    for (const auto &[id, mask] : parameters.boundary_conditions.dirichlet)
      dirichlet_ids.insert(id);
    check("Boundary conditions/Dirichlet", dirichlet_ids);
    check("Boundary conditions/Traction boundary ids",
          parameters.boundary_conditions.traction_ids);
    check("Obstacle/Contact boundary ids", parameters.obstacle.contact_ids);
  }

  template <int dim>
  void
  ContactProblem<dim>::setup_system()
  {
    TimerOutput::Scope t(timer, "Setup: system");
    dof_handler.reinit(*triangulation);
    dof_handler.distribute_dofs(*fe);
    locally_owned_dofs = dof_handler.locally_owned_dofs();
    DoFTools::extract_locally_relevant_dofs(dof_handler, locally_relevant_dofs);

    fixed_constraints.clear();
    fixed_constraints.reinit(locally_relevant_dofs);
    DoFTools::make_hanging_node_constraints(dof_handler, fixed_constraints);
    for (const auto &[id, mask] : parameters.boundary_conditions.dirichlet)
      VectorTools::interpolate_boundary_values(
        *mapping,
        dof_handler,
        id,
        *parameters.boundary_conditions.prescribed_displacement,
        fixed_constraints,
        mask);
    fixed_constraints.close();

    // The supported dofs, where the support reactions act.
    support_dofs.clear();
    support_dofs.set_size(dof_handler.n_dofs());
    for (const auto &[id, mask] : parameters.boundary_conditions.dirichlet)
      support_dofs.add_indices(
        DoFTools::extract_boundary_dofs(dof_handler, mask, {id}));

    TrilinosWrappers::SparsityPattern sparsity(locally_owned_dofs,
                                               locally_owned_dofs,
                                               locally_relevant_dofs,
                                               mpi_communicator);
    DoFTools::make_sparsity_pattern(dof_handler,
                                    sparsity,
                                    fixed_constraints,
                                    false,
                                    Utilities::MPI::this_mpi_process(
                                      mpi_communicator));
    sparsity.compress();
    // The pattern's construction left much of the heap free.
    release_free_memory();
    // The solver's factorisation refers to the old matrix: drop it first.
    linear_system_solver.reset();
    system_matrix.reinit(sparsity);
    cell_stiffness.clear();
    matrix_assembled = false;
    sparsity.clear();

    system_rhs.reinit(locally_owned_dofs, mpi_communicator);
    base_rhs.reinit(locally_owned_dofs, mpi_communicator);
    residual.reinit(locally_owned_dofs, mpi_communicator);
    load.reinit(locally_owned_dofs, mpi_communicator);
    solution.reinit(locally_owned_dofs,
                    locally_relevant_dofs,
                    mpi_communicator);
    pressure.reinit(locally_owned_dofs,
                    locally_relevant_dofs,
                    mpi_communicator);

    // c ~ E / h: the stiffness with which a node resists a local
    // penetration on this mesh.
    if (parameters.contact.complementarity_constant > 0)
      complementarity_constant = parameters.contact.complementarity_constant;
    else
      complementarity_constant =
        parameters.material.young_modulus /
        GridTools::minimal_cell_diameter(*triangulation);

    setup_contact_nodes();
  }

  template <int dim>
  void
  ContactProblem<dim>::setup_contact_nodes()
  {
    contact_nodes.clear();
    const auto &contact_ids = parameters.obstacle.contact_ids;
    std::vector<std::pair<types::global_dof_index, ContactNode<dim>>> found;
    std::optional<Point<dim>> non_finite;
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (!cell->is_artificial())
        for (const auto &face : cell->face_iterators())
          if (face->at_boundary() && contact_ids.count(face->boundary_id()))
            for (const unsigned int v : face->vertex_indices())
              {
                ContactNode<dim> node;
                for (unsigned int d = 0; d < dim; ++d)
                  node.dofs[d] = face->vertex_dof_index(v, d);
                if (fixed_constraints.is_constrained(node.dofs[dim - 1]))
                  continue;
                node.position = face->vertex(v);
                node.gap      = parameters.obstacle.gap(node.position);
                if (!std::isfinite(node.gap))
                  non_finite = face->vertex(v);
                node.owned = locally_owned_dofs.is_element(node.dofs[dim - 1]);
                found.emplace_back(node.dofs[dim - 1], node);
              }
    if (Utilities::MPI::max(non_finite ? 1U : 0U, mpi_communicator) > 0)
      {
        std::ostringstream where;
        if (non_finite)
          where << " at (" << *non_finite << ")";
        throw InputError("Obstacle/Height",
                         "is not a finite number on the contact boundary" +
                           where.str());
      }
    std::sort(found.begin(), found.end(), [](const auto &a, const auto &b) {
      return a.first < b.first;
    });
    for (unsigned int i = 0; i < found.size(); ++i)
      if (i == 0 || found[i].first != found[i - 1].first)
        contact_nodes.push_back(found[i].second);

    // Lumped contact-boundary mass: the integral of each vertical shape
    // function over the contact boundary, condensed onto the free nodes.
    TrilinosWrappers::MPI::Vector mass(locally_owned_dofs, mpi_communicator);
    FEFaceValues<dim>             fe_face_values(*mapping,
                                     *fe,
                                     face_quadrature,
                                     update_values | update_JxW_values);
    Vector<double>                cell_mass(fe->n_dofs_per_cell());
    std::vector<types::global_dof_index> dof_indices(fe->n_dofs_per_cell());
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        for (const unsigned int f : cell->face_indices())
          if (cell->face(f)->at_boundary() &&
              contact_ids.count(cell->face(f)->boundary_id()))
            {
              fe_face_values.reinit(cell, f);
              cell_mass = 0;
              for (unsigned int i = 0; i < fe->n_dofs_per_cell(); ++i)
                if (fe->system_to_component_index(i).first == dim - 1)
                  for (const unsigned int q :
                       fe_face_values.quadrature_point_indices())
                    cell_mass(i) +=
                      fe_face_values.shape_value(i, q) * fe_face_values.JxW(q);
              cell->get_dof_indices(dof_indices);
              fixed_constraints.distribute_local_to_global(cell_mass,
                                                           dof_indices,
                                                           mass);
            }
    mass.compress(VectorOperation::add);
    for (auto &node : contact_nodes)
      if (node.owned)
        node.mass = mass(node.dofs[dim - 1]);
  }

  template ContactProblem<2>::ContactProblem(const Parameters<2> &,
                                             const std::string &,
                                             MPI_Comm);
  template ContactProblem<3>::ContactProblem(const Parameters<3> &,
                                             const std::string &,
                                             MPI_Comm);
  template ContactProblem<2>::~ContactProblem();
  template ContactProblem<3>::~ContactProblem();
  template void
  ContactProblem<2>::make_grid();
  template void
  ContactProblem<3>::make_grid();
  template void
  ContactProblem<2>::setup_system();
  template void
  ContactProblem<3>::setup_system();
  template void
  ContactProblem<2>::setup_contact_nodes();
  template void
  ContactProblem<3>::setup_contact_nodes();
} // namespace signorini
