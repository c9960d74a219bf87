#include <deal.II/base/function.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/lac/full_matrix.h>

#include <signorini/problem/contact_problem.h>

namespace signorini
{
  using namespace dealii;

  template <int dim>
  void
  ContactProblem<dim>::assemble_cell_load(
    const typename DoFHandler<dim>::active_cell_iterator &cell,
    FEValues<dim>                                        &fe_values,
    FEFaceValues<dim>                                    &fe_face_values,
    Vector<double>                                       &cell_load) const
  {
    const auto        &bc = parameters.boundary_conditions;
    const unsigned int n  = fe->n_dofs_per_cell();
    Vector<double>     value(dim);
    cell_load = 0;

    // Adds the integral of the vector function f times the shape functions.
    const auto integrate = [&](const auto &values, const Function<dim> &f) {
      for (const unsigned int q : values.quadrature_point_indices())
        {
          f.vector_value(values.quadrature_point(q), value);
          for (unsigned int i = 0; i < n; ++i)
            cell_load(i) += values.shape_value(i, q) *
                            value(fe->system_to_component_index(i).first) *
                            values.JxW(q);
        }
    };

    fe_values.reinit(cell);
    integrate(fe_values, *bc.body_force);
    for (const unsigned int f : cell->face_indices())
      if (cell->face(f)->at_boundary() &&
          bc.traction_ids.count(cell->face(f)->boundary_id()))
        {
          fe_face_values.reinit(cell, f);
          integrate(fe_face_values, *traction);
        }
  }

  template <int dim>
  void
  ContactProblem<dim>::assemble_load()
  {
    TimerOutput::Scope t(timer, "Assembly: load");
    load     = 0;
    traction = nullptr;

    FEValues<dim>                        fe_values(*mapping,
                            *fe,
                            quadrature,
                            update_values | update_quadrature_points |
                              update_JxW_values);
    FEFaceValues<dim>                    fe_face_values(*mapping,
                                     *fe,
                                     face_quadrature,
                                     update_values | update_quadrature_points |
                                       update_JxW_values);
    Vector<double>                       cell_load(fe->n_dofs_per_cell());
    std::vector<types::global_dof_index> dof_indices(fe->n_dofs_per_cell());

    // A load by a force: the uniform traction of that resultant on the
    // traction boundaries of this mesh.
    const auto &bc = parameters.boundary_conditions;
    traction       = bc.traction.get();
    if (bc.traction_resultant)
      {
        double area = 0.;
        for (const auto &cell : dof_handler.active_cell_iterators())
          if (cell->is_locally_owned())
            for (const unsigned int f : cell->face_indices())
              if (cell->face(f)->at_boundary() &&
                  bc.traction_ids.count(cell->face(f)->boundary_id()))
                {
                  fe_face_values.reinit(cell, f);
                  for (const unsigned int q :
                       fe_face_values.quadrature_point_indices())
                    area += fe_face_values.JxW(q);
                }
        area = Utilities::MPI::sum(area, mpi_communicator);
        Vector<double> value(dim);
        for (unsigned int d = 0; d < dim; ++d)
          value(d) = (*bc.traction_resultant)[d] / area;
        uniform_traction =
          std::make_unique<Functions::ConstantFunction<dim>>(value);
        traction = uniform_traction.get();
      }

    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          assemble_cell_load(cell, fe_values, fe_face_values, cell_load);
          cell->get_dof_indices(dof_indices);
          fixed_constraints.distribute_local_to_global(cell_load,
                                                       dof_indices,
                                                       load);
        }
    load.compress(VectorOperation::add);
  }

  template <int dim>
  void
  ContactProblem<dim>::assemble_newton_system()
  {
    TimerOutput::Scope t(timer, "Assembly: Newton system");
    const bool         active_set_method =
      parameters.contact.method == ContactParameters::Method::active_set;
    const bool penalty_method =
      parameters.contact.method == ContactParameters::Method::penalty ||
      parameters.contact.method ==
        ContactParameters::Method::augmented_lagrangian;

    // The matrix depends on the active set (and on epsilon): while they
    // stay, it and its factorisation are kept, and only the augmented
    // Lagrangian multipliers change the right-hand side.
    const auto key = std::make_pair(active_set_signature(), penalty_parameter);
    if (!matrix_assembled || key != assembled_for)
      {
        // An active-set update changes a few rows and columns only.
        linear_system_solver.matrix_changed(matrix_assembled &&
                                            active_set_method &&
                                            key.second == assembled_for.second);
        // Active contact nodes sit on the obstacle: u_n = -gap.
        constraints.clear();
        constraints.reinit(locally_relevant_dofs);
        if (active_set_method)
          for (const auto &node : contact_nodes)
            if (node.active)
              {
                constraints.add_line(node.dofs[dim - 1]);
                constraints.set_inhomogeneity(node.dofs[dim - 1], -node.gap);
              }
        constraints.merge(fixed_constraints,
                          AffineConstraints<double>::left_object_wins);
        constraints.close();
        assemble_matrix(penalty_method);
        base_rhs         = system_rhs;
        assembled_for    = key;
        matrix_assembled = true;
      }
    else
      system_rhs = base_rhs;

    if (parameters.contact.method ==
        ContactParameters::Method::augmented_lagrangian)
      {
        for (const auto &node : contact_nodes)
          if (node.owned && node.active)
            system_rhs(node.dofs[dim - 1]) += node.mass * node.multiplier;
        system_rhs.compress(VectorOperation::add);
      }
  }

  template <int dim>
  void
  ContactProblem<dim>::assemble_matrix(const bool penalty_method)
  {
    system_matrix = 0;
    system_rhs    = 0;
    FEValues<dim>      fe_values(*mapping,
                            *fe,
                            quadrature,
                            update_gradients | update_JxW_values);
    const unsigned int n = fe->n_dofs_per_cell();
    // The right-hand side gets only the lifting of inhomogeneous
    // constraints here; the load vector is added below.
    Vector<double>                       cell_rhs(n);
    std::vector<types::global_dof_index> dof_indices(n);

    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          const auto &cell_matrix = cell_stiffness.matrix(cell, fe_values);
          cell->get_dof_indices(dof_indices);
          constraints.distribute_local_to_global(
            cell_matrix, cell_rhs, dof_indices, system_matrix, system_rhs);
        }
    system_matrix.compress(VectorOperation::add);
    system_rhs.compress(VectorOperation::add);
    system_rhs += load;

    // Penalty: the obstacle pushes back with p = penetration / epsilon on
    // the penetrating nodes, p_i m_i = -(u_i + gap_i) m_i / epsilon; the
    // augmented Lagrangian adds the multiplier, p = lambda - (u + gap) / eps
    // (its share is added by the caller).
    if (penalty_method)
      {
        const double epsilon = penalty_parameter;
        for (const auto &node : contact_nodes)
          if (node.owned && node.active)
            {
              const auto i = node.dofs[dim - 1];
              system_matrix.add(i, i, node.mass / epsilon);
              system_rhs(i) -= node.mass * node.gap / epsilon;
            }
        system_matrix.compress(VectorOperation::add);
        system_rhs.compress(VectorOperation::add);
      }
  }

  template <int dim>
  double
  ContactProblem<dim>::assemble_cell_internal_force(
    const FEValues<dim> &fe_values,
    Vector<double>      &internal) const
  {
    const FEValuesExtractors::Vector     displacement(0);
    std::vector<SymmetricTensor<2, dim>> strain(fe_values.n_quadrature_points);
    fe_values[displacement].get_function_symmetric_gradients(solution, strain);
    internal             = 0;
    double strain_energy = 0.;
    for (const unsigned int q : fe_values.quadrature_point_indices())
      {
        const auto stress = parameters.material.template stress<dim>(strain[q]);
        strain_energy += 0.5 * (strain[q] * stress) * fe_values.JxW(q);
        for (unsigned int i = 0; i < internal.size(); ++i)
          internal(i) += fe_values[displacement].symmetric_gradient(i, q) *
                         stress * fe_values.JxW(q);
      }
    return strain_energy;
  }

  template <int dim>
  void
  ContactProblem<dim>::assemble_residual()
  {
    TimerOutput::Scope t(timer, "Assembly: residual");
    residual = 0;
    FEValues<dim>                        fe_values(*mapping,
                            *fe,
                            quadrature,
                            update_gradients | update_JxW_values);
    const unsigned int                   n = fe->n_dofs_per_cell();
    Vector<double>                       cell_residual(n), cell_solution(n);
    std::vector<types::global_dof_index> dof_indices(n);

    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          // The internal force K_cell u_cell; from the stresses where the
          // cell's matrix is not cached (curved meshes), which costs an
          // eighth of computing the matrix in 3D.
          if (const auto *matrix = cell_stiffness.cached(cell))
            {
              cell->get_dof_values(solution, cell_solution);
              matrix->vmult(cell_residual, cell_solution);
            }
          else
            {
              fe_values.reinit(cell);
              assemble_cell_internal_force(fe_values, cell_residual);
            }
          cell->get_dof_indices(dof_indices);
          fixed_constraints.distribute_local_to_global(cell_residual,
                                                       dof_indices,
                                                       residual);
        }
    residual.compress(VectorOperation::add);
    residual -= load;
  }

  template void
  ContactProblem<2>::assemble_cell_load(
    const DoFHandler<2>::active_cell_iterator &,
    FEValues<2> &,
    FEFaceValues<2> &,
    Vector<double> &) const;
  template void
  ContactProblem<3>::assemble_cell_load(
    const DoFHandler<3>::active_cell_iterator &,
    FEValues<3> &,
    FEFaceValues<3> &,
    Vector<double> &) const;
  template double
  ContactProblem<2>::assemble_cell_internal_force(const FEValues<2> &,
                                                  Vector<double> &) const;
  template double
  ContactProblem<3>::assemble_cell_internal_force(const FEValues<3> &,
                                                  Vector<double> &) const;
  template void
  ContactProblem<2>::assemble_load();
  template void
  ContactProblem<3>::assemble_load();
  template void
  ContactProblem<2>::assemble_newton_system();
  template void
  ContactProblem<3>::assemble_newton_system();
  template void
  ContactProblem<2>::assemble_matrix(bool);
  template void
  ContactProblem<3>::assemble_matrix(bool);
  template void
  ContactProblem<2>::assemble_residual();
  template void
  ContactProblem<3>::assemble_residual();
} // namespace signorini
