// estimate_kelly_indicators against deal.II's KellyErrorEstimator, on one
// process and on two: a smooth displacement on a cube whose cells are
// warped (no two faces parallel) and refined towards a corner (hanging
// nodes, faces between processes), and on a Moebius loop (faces that meet
// rotated, so that each side orders the face's points differently), in 3D;
// and in 2D on a warped square, also with the weight of the axisymmetric
// model as the coefficient. Every locally
// owned cell's indicator must agree to the rounding of a float; the
// indicators' norm is printed so that zeros on both sides would show.

#include <deal.II/base/function.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/distributed/tria.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/mapping_q1.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/lac/la_parallel_vector.h>
#include <deal.II/numerics/error_estimator.h>
#include <deal.II/numerics/vector_tools.h>

#include <signorini/discretisation/axisymmetry.h>
#include <signorini/mesh_adaptation/kelly_indicator.h>

#include "checks.h"
#include <cmath>
#include <functional>
#include <iomanip>
#include <iostream>
#include <string>

using namespace dealii;
using namespace signorini;
using checks::first_process;
using checks::report;

namespace
{
  /** A smooth displacement with no symmetry. */
  template <int dim>
  class Smooth : public Function<dim>
  {
  public:
    Smooth()
      : Function<dim>(dim)
    {
    }
    double
    value(const Point<dim> &p, const unsigned int component) const override
    {
      const double z = dim == 3 ? p[dim - 1] : 0.5;
      switch (component)
        {
          case 0:
            return std::sin(2. * p[0] + p[1]) * (1. + z * z);
          case 1:
            return std::cos(p[0] * (1. + z)) * p[1] * p[1];
          default:
            return p[0] * p[1] * std::exp(z);
        }
    }
  };

  /** Refines the cells within @p radius of @p centre, twice: hanging
   * nodes. */
  template <int dim>
  void
  refine_near(parallel::distributed::Triangulation<dim> &mesh,
              const Point<dim>                          &centre,
              const double                               radius)
  {
    for (unsigned int step = 0; step < 2; ++step)
      {
        for (const auto &cell : mesh.active_cell_iterators())
          if (cell->is_locally_owned() &&
              cell->center().distance(centre) < radius)
            cell->set_refine_flag();
        mesh.execute_coarsening_and_refinement();
      }
  }

  /** Moves every vertex of the unit cube smoothly: no cell is a
   * parallelepiped. */
  template <int dim>
  Point<dim>
  warp(const Point<dim> &p)
  {
    Point<dim> q = p;
    for (unsigned int d = 0; d < dim; ++d)
      q[d] += 0.08 * std::sin(3. * p[(d + 1) % dim] + d) * p[d];
    return q;
  }

  /** The unit cube, refined twice, warped, then refined twice more near
   * the origin. */
  template <int dim>
  void
  warped_cube(parallel::distributed::Triangulation<dim> &mesh)
  {
    GridGenerator::hyper_cube(mesh, 0., 1.);
    mesh.refine_global(2);
    GridTools::transform(&warp<dim>, mesh);
    refine_near(mesh, Point<dim>(), 0.5);
  }

  /** A ring of 8 cells twisted by a quarter turn before it is closed: the
   * faces where it closes meet rotated, which the points on either side
   * must follow. Refined once, then twice more near one side. */
  void
  moebius_loop(parallel::distributed::Triangulation<3> &mesh)
  {
    GridGenerator::moebius(mesh, 8, 1, 1., 0.3);
    mesh.refine_global(1);
    refine_near(mesh, Point<3>(1., 0., 0.), 0.6);
  }

  template <int dim>
  void
  compare(const std::string &name,
          const std::function<void(parallel::distributed::Triangulation<dim> &)>
                              &make_mesh,
          const Function<dim> *coefficient)
  {
    parallel::distributed::Triangulation<dim> mesh(MPI_COMM_WORLD);
    make_mesh(mesh);
    // Faces seen from a cell in other than the standard orientation.
    unsigned int turned = 0;
    for (const auto &cell : mesh.active_cell_iterators())
      if (cell->is_locally_owned())
        for (const unsigned int f : cell->face_indices())
          turned += !cell->face_orientation(f) || cell->face_flip(f) ||
                    cell->face_rotation(f);
    turned = Utilities::MPI::sum(turned, MPI_COMM_WORLD);

    const FESystem<dim> fe(FE_Q<dim>(1), dim);
    DoFHandler<dim>     dofs(mesh);
    dofs.distribute_dofs(fe);
    IndexSet relevant;
    DoFTools::extract_locally_relevant_dofs(dofs, relevant);
    LinearAlgebra::distributed::Vector<double> u(dofs.locally_owned_dofs(),
                                                 relevant,
                                                 MPI_COMM_WORLD);
    VectorTools::interpolate(dofs, Smooth<dim>(), u);
    u.update_ghost_values();

    const MappingQ1<dim>  mapping;
    const QGauss<dim - 1> face_rule(2);
    Vector<float>         ours, dealii;
    estimate_kelly_indicators(mapping, dofs, face_rule, u, coefficient, ours);
    KellyErrorEstimator<dim>::estimate(
      mapping, dofs, face_rule, {}, u, dealii, ComponentMask(), coefficient);

    double difference = 0., largest = 0., squares = 0.;
    for (const auto &cell : mesh.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          const unsigned int i = cell->active_cell_index();
          difference =
            std::max<double>(difference, std::abs(ours(i) - dealii(i)));
          largest = std::max<double>(largest, dealii(i));
          squares += double(ours(i)) * ours(i);
        }
    difference = Utilities::MPI::max(difference, MPI_COMM_WORLD);
    largest    = Utilities::MPI::max(largest, MPI_COMM_WORLD);
    squares    = Utilities::MPI::sum(squares, MPI_COMM_WORLD);
    if (first_process())
      std::cout << name << ", " << mesh.n_global_active_cells() << " cells, "
                << turned << " faces turned"
                << (coefficient ? ", weighted by 2 pi r" : "")
                << ": norm of the indicators " << std::setprecision(6)
                << std::sqrt(squares) << '\n';
    report("largest difference to deal.II's, relative",
           difference / largest,
           5e-7);
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  compare<3>("3D warped cube", &warped_cube<3>, nullptr);
  compare<3>("3D Moebius loop", &moebius_loop, nullptr);
  compare<2>("2D warped square", &warped_cube<2>, nullptr);
  const axisymmetry::KellyCoefficient<2> revolved;
  compare<2>("2D warped square", &warped_cube<2>, &revolved);
}
