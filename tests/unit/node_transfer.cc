// NodeTransfer between simplex meshes, on one process and on two (the
// meshes then fully distributed as GmshRemeshing does): two linear fields
// carried to a mesh that shares almost no vertex with the old one and sticks
// out of it (exact for P1, also outside), two quadratic fields carried so
// as P2 (exact at the vertices and mid-nodes, also outside), and a
// nonlinear field carried to
// the old mesh refined globally (old vertices keep their values, new ones
// take the mean of their edge's ends, as SolutionTransfer would give), and
// to the refined mesh with the new boundary vertices moved out (the linear
// extension of the old cell of their edge).

#include <deal.II/base/mpi.h>
#include <deal.II/distributed/fully_distributed_tria.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_simplex_p.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/tria.h>
#include <deal.II/grid/tria_description.h>
#include <deal.II/lac/trilinos_vector.h>

#include <signorini/mesh_adaptation/node_transfer.h>

#include "checks.h"
#include <algorithm>
#include <cmath>
#include <functional>
#include <iomanip>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

using namespace dealii;
using namespace signorini;
using checks::first_process;
using checks::report;

namespace
{
  using VectorType = TrilinosWrappers::MPI::Vector;
  using Field      = std::function<double(const Point<3> &, unsigned int)>;

  template <int dim>
  Point<3>
  to_3d(const Point<dim> &p)
  {
    Point<3> q;
    for (unsigned int d = 0; d < dim; ++d)
      q[d] = p[d];
    return q;
  }

  /** The mesh the dofs live on: a copy of @p serial on one process, a fully
   * distributed one partitioned by the first process on several (as
   * GmshRemeshing::distribute does). */
  template <int dim>
  std::unique_ptr<Triangulation<dim>>
  distribute(const Triangulation<dim> &serial)
  {
    const unsigned int n = Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD);
    if (n == 1)
      {
        auto copy = std::make_unique<Triangulation<dim>>();
        copy->copy_triangulation(serial);
        return copy;
      }
    Triangulation<dim> partitioned;
    partitioned.copy_triangulation(serial);
    std::vector<unsigned int> owner(partitioned.n_active_cells());
    if (first_process())
      {
        GridTools::partition_triangulation(n, partitioned);
        for (const auto &cell : partitioned.active_cell_iterators())
          owner[cell->active_cell_index()] = cell->subdomain_id();
      }
    owner = Utilities::MPI::broadcast(MPI_COMM_WORLD, owner, 0);
    for (const auto &cell : partitioned.active_cell_iterators())
      cell->set_subdomain_id(owner[cell->active_cell_index()]);
    auto mesh =
      std::make_unique<parallel::fullydistributed::Triangulation<dim>>(
        MPI_COMM_WORLD);
    mesh->create_triangulation(
      TriangulationDescription::Utilities::
        create_description_from_triangulation(partitioned, MPI_COMM_WORLD));
    return mesh;
  }

  /** The position of node @p b of a straight simplex @p cell: a vertex, or
   * the middle of an edge (P2). */
  template <typename Cell>
  auto
  node(const Cell &cell, const unsigned int b)
  {
    return b < cell->n_vertices() ?
             cell->vertex(b) :
             cell->line(b - cell->n_vertices())->center();
  }

  /** @p f(cell, node b, component d, dof i) for each locally owned dof i
   * of @p dof_handler's locally owned cells (once per cell it is in). */
  template <int dim, typename F>
  void
  for_each_owned_node(const DoFHandler<dim> &dof_handler, const F &f)
  {
    const IndexSet &owned = dof_handler.locally_owned_dofs();
    const auto     &fe    = dof_handler.get_fe();
    std::vector<types::global_dof_index> dofs(fe.n_dofs_per_cell());
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          cell->get_dof_indices(dofs);
          for (unsigned int b = 0; b < fe.base_element(0).n_dofs_per_cell();
               ++b)
            for (unsigned int d = 0; d < dim; ++d)
              {
                const auto i = dofs[fe.component_to_system_index(d, b)];
                if (owned.is_element(i))
                  f(cell, b, d, i);
              }
        }
  }

  /** The ghosted P1 or P2 vector of @p field's node values. */
  template <int dim>
  VectorType
  vertex_values(const DoFHandler<dim> &dof_handler, const Field &field)
  {
    IndexSet relevant;
    DoFTools::extract_locally_relevant_dofs(dof_handler, relevant);
    const IndexSet &owned = dof_handler.locally_owned_dofs();
    VectorType      values(owned, MPI_COMM_WORLD);
    for_each_owned_node(dof_handler,
                        [&](const auto        &cell,
                            const unsigned int b,
                            const unsigned int d,
                            const auto         i) {
                          values(i) = field(to_3d(node(cell, b)), d);
                        });
    values.compress(VectorOperation::insert);
    VectorType ghosted(owned, relevant, MPI_COMM_WORLD);
    ghosted = values;
    return ghosted;
  }

  /**
   * Carries @p fields from @p old_mesh to @p new_mesh and compares the
   * result on every owned dof with @p expected; prints the largest
   * differences and how many dofs were compared.
   */
  template <int dim>
  void
  transfer(
    const Triangulation<dim> &old_serial,
    const Triangulation<dim> &new_serial,
    const std::vector<Field> &fields,
    const std::function<double(const Point<dim> &, unsigned int, unsigned int)>
                      &expected,
    const unsigned int degree = 1)
  {
    const FESystem<dim> fe(FE_SimplexP<dim>(degree), dim);

    auto            old_mesh = distribute(old_serial);
    DoFHandler<dim> old_dofs(*old_mesh);
    old_dofs.distribute_dofs(fe);
    std::vector<VectorType>         old_vectors;
    std::vector<const VectorType *> pointers;
    for (const auto &field : fields)
      old_vectors.push_back(vertex_values(old_dofs, field));
    for (const auto &vector : old_vectors)
      pointers.push_back(&vector);

    const NodeTransfer<dim> transfer(old_serial,
                                     old_dofs,
                                     pointers,
                                     MPI_COMM_WORLD);

    auto            new_mesh = distribute(new_serial);
    DoFHandler<dim> new_dofs(*new_mesh);
    new_dofs.distribute_dofs(fe);
    const auto result = transfer.interpolate(new_dofs);

    std::vector<double> difference(fields.size(), 0.);
    std::vector<bool>   seen(new_dofs.n_dofs(), false);
    for_each_owned_node(new_dofs,
                        [&](const auto        &cell,
                            const unsigned int b,
                            const unsigned int d,
                            const auto         i) {
                          if (seen[i])
                            return;
                          seen[i] = true;
                          for (unsigned int k = 0; k < fields.size(); ++k)
                            difference[k] =
                              std::max(difference[k],
                                       std::abs(result[k](i) -
                                                expected(node(cell, b), d, k)));
                        });
    unsigned int compared = 0;
    for (const bool s : seen)
      compared += s;
    compared = Utilities::MPI::sum(compared, MPI_COMM_WORLD);
    // Every process owns a part of each mesh, none all of it.
    unsigned int old_owned = 0, new_owned = 0;
    for (const auto &cell : old_dofs.active_cell_iterators())
      old_owned += cell->is_locally_owned();
    for (const auto &cell : new_dofs.active_cell_iterators())
      new_owned += cell->is_locally_owned();
    const unsigned int n_processes =
      Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD);
    const bool shared =
      Utilities::MPI::min(std::min(old_owned, new_owned), MPI_COMM_WORLD) > 0 &&
      (n_processes == 1 || (Utilities::MPI::max(old_owned, MPI_COMM_WORLD) <
                              old_serial.n_active_cells() &&
                            Utilities::MPI::max(new_owned, MPI_COMM_WORLD) <
                              new_serial.n_active_cells()));
    if (first_process())
      std::cout << "  processes " << n_processes
                << ", each owns a part of both meshes: "
                << (shared ? "yes" : "no") << '\n';
    const auto owned_entries =
      Utilities::MPI::sum(result[0].locally_owned_size(), MPI_COMM_WORLD);
    if (first_process())
      std::cout << "  " << old_serial.n_active_cells() << " -> "
                << new_serial.n_active_cells() << " cells, dofs compared "
                << compared << " of " << new_dofs.n_dofs() << ", vectors "
                << result.size() << ", owned entries " << owned_entries << '\n';
    for (unsigned int k = 0; k < fields.size(); ++k)
      report("field " + std::to_string(k) + ": max |transferred - expected|",
             Utilities::MPI::max(difference[k], MPI_COMM_WORLD),
             1e-12);
  }

  /** Two linear fields u = A x + b, no component zero on the meshes. */
  std::vector<Field>
  linear_fields()
  {
    return {[](const Point<3> &x, unsigned int c) {
              const double A[3][3] = {{1.5, -0.5, 0.25},
                                      {0.75, 2., -1.},
                                      {-0.3, 0.1, 3.}};
              return 10. + c + A[c][0] * x[0] + A[c][1] * x[1] + A[c][2] * x[2];
            },
            [](const Point<3> &x, unsigned int c) {
              return -5. + (c + 1.) * (x[0] - 2. * x[1] + 0.5 * x[2]);
            }};
  }

  template <int dim>
  void
  linear_to_another_mesh()
  {
    if (first_process())
      std::cout << dim << "D, linear fields, [0, 1] in 3 -> [-0.05, 1.05] in "
                << (dim == 2 ? 5 : 3) << " subdivisions:\n";
    Triangulation<dim> old_mesh, new_mesh;
    GridGenerator::subdivided_hyper_cube_with_simplices(old_mesh, 3);
    GridGenerator::subdivided_hyper_cube_with_simplices(new_mesh,
                                                        dim == 2 ? 5 : 3,
                                                        -0.05,
                                                        1.05);
    const auto fields = linear_fields();
    transfer<dim>(old_mesh,
                  new_mesh,
                  fields,
                  [&fields](const Point<dim> &p,
                            unsigned int      d,
                            unsigned int k) { return fields[k](to_3d(p), d); });
  }

  /** Two quadratic fields (every second-order term in each component),
   * carried as P2: exact at every node. */
  template <int dim>
  void
  quadratic_to_another_mesh()
  {
    if (first_process())
      std::cout << dim << "D, quadratic fields (P2), [0, 1] in 3 -> "
                << "[-0.05, 1.05] in " << (dim == 2 ? 5 : 2)
                << " subdivisions:\n";
    Triangulation<dim> old_mesh, new_mesh;
    GridGenerator::subdivided_hyper_cube_with_simplices(old_mesh, 3);
    GridGenerator::subdivided_hyper_cube_with_simplices(new_mesh,
                                                        dim == 2 ? 5 : 2,
                                                        -0.05,
                                                        1.05);
    const std::vector<Field> fields = {[](const Point<3> &x, unsigned int c) {
                                         return 1. + c + 2. * x[0] * x[0] -
                                                3. * x[0] * x[1] +
                                                (c + 0.5) * x[1] * x[1] +
                                                x[2] * (x[0] - 2. * x[2] + c);
                                       },
                                       [](const Point<3> &x, unsigned int c) {
                                         return -4. + (c + 1.) * x[0] * x[1] +
                                                x[1] * x[2] - x[2] + 0.5 * x[0];
                                       }};
    transfer<dim>(
      old_mesh,
      new_mesh,
      fields,
      [&fields](const Point<dim> &p, unsigned int d, unsigned int k) {
        return fields[k](to_3d(p), d);
      },
      2);
  }

  /** The linear extension to @p p of the P1 function of the vertex values
   * f(v) on a 2D @p cell. */
  double
  extension(const Triangulation<2>::active_cell_iterator  &cell,
            const Point<2>                                &p,
            const std::function<double(const Point<2> &)> &f)
  {
    Tensor<2, 2> jacobian;
    for (unsigned int j = 0; j < 2; ++j)
      for (unsigned int d = 0; d < 2; ++d)
        jacobian[d][j] = cell->vertex(j + 1)[d] - cell->vertex(0)[d];
    const Tensor<1, 2> xi = invert(jacobian) * (p - cell->vertex(0));
    return (1. - xi[0] - xi[1]) * f(cell->vertex(0)) +
           xi[0] * f(cell->vertex(1)) + xi[1] * f(cell->vertex(2));
  }

  /** @p curved: the new mesh's vertices at the midpoints of boundary edges
   * moved out by 0.01, as on a curved boundary (2D). */
  template <int dim>
  void
  nonlinear_to_refined_mesh(const bool curved = false)
  {
    if (first_process())
      std::cout << dim
                << "D, a nonlinear field, [0, 1] in 2 subdivisions -> "
                   "refined once"
                << (curved ? ", boundary midpoints moved out by 0.01" : "")
                << ":\n";
    Triangulation<dim> old_mesh, new_mesh;
    GridGenerator::subdivided_hyper_cube_with_simplices(old_mesh, 2);
    new_mesh.copy_triangulation(old_mesh);
    new_mesh.refine_global(1);
    if (curved)
      {
        std::vector<bool> visited(new_mesh.n_vertices(), false);
        for (const auto &cell : new_mesh.active_cell_iterators())
          for (const unsigned int v : cell->vertex_indices())
            if (!visited[cell->vertex_index(v)])
              {
                visited[cell->vertex_index(v)] = true;
                Point<dim> &x                  = cell->vertex(v);
                for (unsigned int d = 0; d < dim; ++d)
                  for (unsigned int e = 0; e < dim; ++e)
                    if (e != d && std::abs(std::fmod(x[e], 0.5)) > 0.1)
                      {
                        if (x[d] == 0.)
                          x[d] = -0.01;
                        else if (x[d] == 1.)
                          x[d] = 1.01;
                      }
              }
      }
    const Field field = [](const Point<3> &x, unsigned int c) {
      return std::sin(3. * x[0] + c) + x[0] * x[1] * x[1] + std::exp(x[2]);
    };
    // A new vertex is an old one or the midpoint of an old edge; a moved
    // one takes the linear extension of the old cell of its edge.
    const auto expected =
      [&](const Point<dim> &p, unsigned int d, unsigned int) {
        if constexpr (dim == 2)
          if (curved)
            for (const auto &cell : old_mesh.active_cell_iterators())
              for (const unsigned int a : cell->vertex_indices())
                for (const unsigned int b : cell->vertex_indices())
                  if (b > a && std::abs(p.distance(0.5 * (cell->vertex(a) +
                                                          cell->vertex(b))) -
                                        0.01) < 1e-12)
                    return extension(cell, p, [&](const Point<2> &x) {
                      return field(to_3d(x), d);
                    });
        for (const auto &cell : old_mesh.active_cell_iterators())
          for (const unsigned int a : cell->vertex_indices())
            for (const unsigned int b : cell->vertex_indices())
              if (b >= a &&
                  p.distance(0.5 * (cell->vertex(a) + cell->vertex(b))) < 1e-12)
                return 0.5 * (field(to_3d(cell->vertex(a)), d) +
                              field(to_3d(cell->vertex(b)), d));
        return 1e300; // not found: a difference that fails
      };
    if (curved)
      {
        // The moved vertices, and how far their extension is from the mean
        // of their edge's ends: what the test tells apart.
        unsigned int n_moved = 0;
        double       apart   = 0.;
        for (const auto &x : new_mesh.get_vertices())
          {
            Point<dim> back = x;
            for (unsigned int d = 0; d < dim; ++d)
              back[d] = std::clamp(back[d], 0., 1.);
            if (back == x)
              continue;
            ++n_moved;
            for (unsigned int d = 0; d < dim; ++d)
              apart =
                std::max(apart,
                         std::abs(expected(x, d, 0) - expected(back, d, 0)));
          }
        if (first_process())
          std::cout << "  vertices moved " << n_moved
                    << ", their extension differs from the edge mean by up to "
                    << apart << '\n';
      }
    transfer<dim>(old_mesh, new_mesh, {field}, expected);
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  if (first_process())
    std::cout << std::setprecision(10);
  linear_to_another_mesh<2>();
  linear_to_another_mesh<3>();
  quadratic_to_another_mesh<2>();
  quadratic_to_another_mesh<3>();
  nonlinear_to_refined_mesh<2>();
  nonlinear_to_refined_mesh<3>();
  nonlinear_to_refined_mesh<2>(true);
}
