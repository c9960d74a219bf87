#include <signorini/base/text.h>
#include <signorini/discretisation/axisymmetry.h>
#include <signorini/input/input_error.h>

namespace signorini
{
  using namespace dealii;

  namespace axisymmetry
  {
    template <int dim>
    void
    add_axis_constraints(const DoFHandler<dim>     &dofs,
                         const IndexSet            &relevant_dofs,
                         const double               tolerance,
                         AffineConstraints<double> &constraints)
    {
      for (const auto &cell : dofs.active_cell_iterators())
        if (!cell->is_artificial())
          for (const unsigned int v : cell->vertex_indices())
            if (std::abs(cell->vertex(v)[0]) <= tolerance)
              {
                const auto radial = cell->vertex_dof_index(v, 0);
                if (relevant_dofs.is_element(radial) &&
                    !constraints.is_constrained(radial))
                  constraints.add_line(radial);
              }
      // Degree 2: the mid-nodes of the faces that lie on the axis.
      const auto &fe = dofs.get_fe();
      if (fe.degree == 1)
        return;
      std::vector<types::global_dof_index> face_dofs(fe.n_dofs_per_face());
      for (const auto &cell : dofs.active_cell_iterators())
        if (!cell->is_artificial())
          for (const auto &face : cell->face_iterators())
            {
              bool on_axis = true;
              for (const unsigned int v : face->vertex_indices())
                on_axis = on_axis && std::abs(face->vertex(v)[0]) <= tolerance;
              if (!on_axis)
                continue;
              face->get_dof_indices(face_dofs);
              for (unsigned int i = 0; i < face_dofs.size(); ++i)
                if (fe.face_system_to_component_index(i).first == 0 &&
                    relevant_dofs.is_element(face_dofs[i]) &&
                    !constraints.is_constrained(face_dofs[i]))
                  constraints.add_line(face_dofs[i]);
            }
    }

    template <int dim>
    void
    check_side_of_axis(const Triangulation<dim> &coarse_mesh,
                       const Geometry<dim>      &geometry,
                       const double              tolerance)
    {
      double r_min = 0.;
      for (const auto &vertex : coarse_mesh.get_vertices())
        r_min = std::min(r_min, vertex[0]);
      if (r_min >= -tolerance)
        return;
      using Type        = typename Geometry<dim>::Type;
      std::string entry = "Geometry/Mesh file";
      if (geometry.type == Type::rectangle)
        entry = "Geometry/Lower left corner";
      else if (geometry.type != Type::gmsh)
        entry = "Geometry/Center";
      throw InputError(entry,
                       "the body reaches x = " + number(r_min) +
                         " mm; an axisymmetric body (Material/Plane state) "
                         "lies at x = r >= 0, its axis at x = 0");
    }

    template <int dim>
    void
    check_off_axis(const Triangulation<dim>           &mesh,
                   const std::set<types::boundary_id> &ids,
                   const std::string                  &entry,
                   const double                        tolerance)
    {
      std::set<types::boundary_id> off_axis;
      for (const auto &cell : mesh.cell_iterators_on_level(0))
        for (const auto &face : cell->face_iterators())
          if (face->at_boundary() && ids.count(face->boundary_id()))
            for (const unsigned int v : face->vertex_indices())
              if (std::abs(face->vertex(v)[0]) > tolerance)
                off_axis.insert(face->boundary_id());
      for (const auto id : ids)
        if (!off_axis.count(id))
          throw InputError(entry,
                           "boundary id " + std::to_string(id) +
                             " lies on the axis of revolution (r = x = 0), "
                             "where it has no area: a traction there acts "
                             "on nothing; load a boundary off the axis");
    }

    template void
    add_axis_constraints(const DoFHandler<2> &,
                         const IndexSet &,
                         double,
                         AffineConstraints<double> &);
    template void
    add_axis_constraints(const DoFHandler<3> &,
                         const IndexSet &,
                         double,
                         AffineConstraints<double> &);
    template void
    check_off_axis(const Triangulation<2> &,
                   const std::set<types::boundary_id> &,
                   const std::string &,
                   double);
    template void
    check_off_axis(const Triangulation<3> &,
                   const std::set<types::boundary_id> &,
                   const std::string &,
                   double);
    template void
    check_side_of_axis(const Triangulation<2> &, const Geometry<2> &, double);
    template void
    check_side_of_axis(const Triangulation<3> &, const Geometry<3> &, double);
  } // namespace axisymmetry
} // namespace signorini
