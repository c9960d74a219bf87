#include <deal.II/base/mpi.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/lac/vector.h>

#include <signorini/input/input_error.h>
#include <signorini/postprocessing/probes.h>

#include <sstream>

namespace signorini
{
  using namespace dealii;

  namespace
  {
    /** The displacement at @p point, if a locally owned cell holds it. */
    template <int dim>
    bool
    evaluate_displacement(const Discretisation<dim>           &discretisation,
                          const TrilinosWrappers::MPI::Vector &u,
                          const Point<dim>                    &point,
                          Tensor<1, dim>                      &value)
    {
      const auto &mapping = discretisation.mapping();
      // deal.II 9.4's GridTools::find_active_cell_around_point can return a
      // tetrahedron that does not contain the point; test containment here.
      for (const auto &cell :
           discretisation.dof_handler().active_cell_iterators())
        if (cell->is_locally_owned() &&
            cell->bounding_box().point_inside(point, 1e-10))
          {
            Point<dim> unit;
            try
              {
                unit = mapping.transform_real_to_unit_cell(cell, point);
              }
            catch (const typename Mapping<dim>::ExcTransformationFailed &)
              {
                continue;
              }
            if (!cell->reference_cell().contains_point(unit, 1e-10))
              continue;
            FEValues<dim> fe_values(mapping,
                                    discretisation.fe(),
                                    Quadrature<dim>(
                                      std::vector<Point<dim>>{unit}),
                                    update_values);
            fe_values.reinit(cell);
            std::vector<Vector<double>> values(1, Vector<double>(dim));
            fe_values.get_function_values(u, values);
            for (unsigned int d = 0; d < dim; ++d)
              value[d] = values[0](d);
            return true;
          }
      return false;
    }
  } // namespace

  template <int dim>
  std::vector<Tensor<1, dim>>
  evaluate_probes(const Discretisation<dim>           &discretisation,
                  const TrilinosWrappers::MPI::Vector &u,
                  const std::vector<Point<dim>>       &points)
  {
    const MPI_Comm              comm = discretisation.mpi_communicator();
    const unsigned int          rank = Utilities::MPI::this_mpi_process(comm);
    const unsigned int          n_ranks = Utilities::MPI::n_mpi_processes(comm);
    std::vector<Tensor<1, dim>> values;
    for (const auto &point : points)
      {
        Tensor<1, dim>     value;
        const unsigned int owner = Utilities::MPI::min(
          evaluate_displacement(discretisation, u, point, value) ? rank :
                                                                   n_ranks,
          comm);
        if (owner == n_ranks)
          {
            std::ostringstream text;
            text << "the point (" << point << ") is not in the body";
            throw InputError("Output/Probe points", text.str());
          }
        values.push_back(
          Utilities::MPI::sum(rank == owner ? value : Tensor<1, dim>(), comm));
      }
    return values;
  }

  template std::vector<Tensor<1, 2>>
  evaluate_probes(const Discretisation<2> &,
                  const TrilinosWrappers::MPI::Vector &,
                  const std::vector<Point<2>> &);
  template std::vector<Tensor<1, 3>>
  evaluate_probes(const Discretisation<3> &,
                  const TrilinosWrappers::MPI::Vector &,
                  const std::vector<Point<3>> &);
} // namespace signorini
