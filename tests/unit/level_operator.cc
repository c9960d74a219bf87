// ElasticLevelOperator::vmult() against the stiffness matrix assembled with
// FEValues and condensed by deal.II's AffineConstraints, on a cube refined
// towards a corner (hanging nodes) with the dofs of one face fixed
// (Dirichlet): its cells are read and written directly (no constrained dof),
// through their hanging nodes' and Dirichlet lines (both kinds of constrained
// dofs), or both. The rows of free dofs agree to round-off, constrained rows
// are the identity, and so does the matrix assemble_matrix() makes (the
// coarse level's); in 2D and 3D, on one process and on two. On the box every
// cell is a parallelepiped: the operator is set up from the vertices, without
// MatrixFree; the same mesh distorted by x += 0.2 x y (no cell a
// parallelepiped) takes the MatrixFree path.

#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/distributed/tria.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping_q1.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_sparsity_pattern.h>
#include <deal.II/lac/trilinos_vector.h>
#include <deal.II/numerics/vector_tools.h>

#include <signorini/elasticity/elastic_level_operator.h>
#include <signorini/elasticity/material.h>

#include "checks.h"
#include <cmath>
#include <iostream>

using namespace dealii;
using namespace signorini;
using checks::first_process;
using checks::report;

namespace
{
  template <int dim>
  void
  check(const unsigned int global, const bool distorted)
  {
    parallel::distributed::Triangulation<dim> mesh(MPI_COMM_WORLD);
    checks::corner_refined_cube(mesh, global, 2, 0.45);
    if (distorted)
      GridTools::transform(
        [](const Point<dim> &p) {
          Point<dim> q = p;
          q[0] += 0.2 * p[0] * p[1];
          return q;
        },
        mesh);
    const FESystem<dim> fe(FE_Q<dim>(1), dim);
    DoFHandler<dim>     dofs(mesh);
    dofs.distribute_dofs(fe);
    const IndexSet owned    = dofs.locally_owned_dofs();
    const IndexSet relevant = DoFTools::extract_locally_relevant_dofs(dofs);

    AffineConstraints<double> constraints(relevant);
    DoFTools::make_hanging_node_constraints(dofs, constraints);
    const MappingQ1<dim> mapping;
    VectorTools::interpolate_boundary_values(
      mapping, dofs, 0, Functions::ZeroFunction<dim>(dim), constraints);
    constraints.close();

    Material material;
    material.young_modulus = 1000.;
    material.poisson_ratio = 0.3;
    const double mu = material.mu(), lambda = material.template lambda<dim>();

    // The reference: K condensed (C^T K C) by deal.II.
    TrilinosWrappers::SparsityPattern pattern(owned,
                                              owned,
                                              relevant,
                                              MPI_COMM_WORLD);
    DoFTools::make_sparsity_pattern(dofs, pattern, constraints, false);
    pattern.compress();
    TrilinosWrappers::SparseMatrix matrix;
    matrix.reinit(pattern);
    const QGauss<dim>                    quadrature(2);
    FEValues<dim>                        values(mapping,
                         fe,
                         quadrature,
                         update_gradients | update_JxW_values);
    const unsigned int                   n = fe.n_dofs_per_cell();
    FullMatrix<double>                   cell_matrix(n, n);
    std::vector<types::global_dof_index> indices(n);
    unsigned int                         n_plain = 0, n_constrained = 0;
    for (const auto &cell : dofs.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          values.reinit(cell);
          cell_matrix = 0.;
          for (unsigned int q = 0; q < quadrature.size(); ++q)
            for (unsigned int i = 0; i < n; ++i)
              {
                const unsigned int ci = fe.system_to_component_index(i).first;
                for (unsigned int j = 0; j < n; ++j)
                  {
                    const unsigned int cj =
                      fe.system_to_component_index(j).first;
                    const auto gi = values.shape_grad(i, q);
                    const auto gj = values.shape_grad(j, q);
                    // eps(v) : sigma(u) for v = phi_i e_ci, u = phi_j e_cj.
                    double value = lambda * gi[ci] * gj[cj] +
                                   mu * gi[cj] * gj[ci] +
                                   (ci == cj ? mu * (gi * gj) : 0.);
                    cell_matrix(i, j) += value * values.JxW(q);
                  }
              }
          cell->get_dof_indices(indices);
          bool plain = true;
          for (const auto i : indices)
            plain = plain && !constraints.is_constrained(i);
          ++(plain ? n_plain : n_constrained);
          constraints.distribute_local_to_global(cell_matrix, indices, matrix);
        }
    matrix.compress(VectorOperation::add);

    ElasticLevelOperator<dim> level(material);
    level.reinit(mapping, dofs, constraints);
    typename ElasticLevelOperator<dim>::VectorType src, dst;
    level.initialize_dof_vector(src);
    level.initialize_dof_vector(dst);
    TrilinosWrappers::MPI::Vector x(owned, MPI_COMM_WORLD), y(x);
    for (const auto i : owned)
      {
        src(i) = x(i) = std::sin(0.37 * i) + 0.01 * (i % 7);
        if (constraints.is_constrained(i))
          x(i) = 0.;
      }
    x.compress(VectorOperation::insert);
    level.vmult(dst, src);
    matrix.vmult(y, x);
    TrilinosWrappers::SparseMatrix coarse;
    level.assemble_matrix(coarse);
    TrilinosWrappers::MPI::Vector z(y);
    coarse.vmult(z, x);

    double free_rows = 0., identity_rows = 0., scale = 0., assembled = 0.;
    for (const auto i : owned)
      if (constraints.is_constrained(i))
        identity_rows = std::max(identity_rows, std::abs(dst(i) - src(i)));
      else
        {
          free_rows = std::max(free_rows, std::abs(dst(i) - y(i)));
          assembled = std::max(assembled, std::abs(z(i) - y(i)));
          scale     = std::max(scale, std::abs(y(i)));
        }
    scale         = Utilities::MPI::max(scale, MPI_COMM_WORLD);
    free_rows     = Utilities::MPI::max(free_rows, MPI_COMM_WORLD) / scale;
    assembled     = Utilities::MPI::max(assembled, MPI_COMM_WORLD) / scale;
    identity_rows = Utilities::MPI::max(identity_rows, MPI_COMM_WORLD);
    const unsigned int plain_cells =
      Utilities::MPI::sum(n_plain, MPI_COMM_WORLD);
    const unsigned int constrained_cells =
      Utilities::MPI::sum(n_constrained, MPI_COMM_WORLD);
    unsigned int n_constrained_dofs = 0;
    for (const auto i : owned)
      n_constrained_dofs += constraints.is_constrained(i);
    n_constrained_dofs =
      Utilities::MPI::sum(n_constrained_dofs, MPI_COMM_WORLD);
    if (first_process())
      std::cout << dim << "D" << (distorted ? ", distorted" : "") << ": "
                << dofs.n_dofs() << " dofs, " << n_constrained_dofs
                << " constrained, " << plain_cells << " cells without and "
                << constrained_cells << " with constrained dofs" << std::endl;
    report("free rows against C^T K C (relative)", free_rows, 1e-12);
    report("constrained rows against the identity", identity_rows, 0.);
    report("free rows of the assembled matrix (relative)", assembled, 1e-12);
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  for (const bool distorted : {false, true})
    {
      check<2>(3, distorted);
      check<3>(2, distorted);
    }
}
