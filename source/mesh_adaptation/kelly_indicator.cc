#include <deal.II/base/geometry_info.h>
#include <deal.II/base/qprojector.h>
#include <deal.II/base/tensor.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/mapping_q.h>
#include <deal.II/grid/reference_cell.h>
#include <deal.II/numerics/error_estimator.h>

#include <signorini/mesh_adaptation/kelly_indicator.h>

#include <array>
#include <cmath>
#include <vector>

namespace signorini
{
  using namespace dealii;

  namespace
  {
    /** Whether the fast path applies: Q1 in every component on
     * quadrilaterals or hexahedra, mapped by their vertices. */
    template <int dim>
    bool
    is_linear_hypercube(const Mapping<dim>       &mapping,
                        const FiniteElement<dim> &fe)
    {
      const auto *linear = dynamic_cast<const MappingQ<dim> *>(&mapping);
      const auto *base   = dynamic_cast<const FE_Q<dim> *>(&fe.base_element(0));
      return linear != nullptr && linear->get_degree() == 1 &&
             fe.reference_cell() == ReferenceCells::get_hypercube<dim>() &&
             fe.n_base_elements() == 1 && base != nullptr &&
             base->degree == 1 && fe.n_components() == dim;
    }

    /** The Q1 shape functions and their reference gradients at the face
     * points of every face (every orientation), or of every subface. */
    template <int dim>
    struct PointTable
    {
      static constexpr unsigned int n_vertices = 1 << dim;

      explicit PointTable(const Quadrature<dim> &points)
        : values(points.size())
        , gradients(points.size())
        , weights(points.get_weights())
      {
        for (unsigned int q = 0; q < points.size(); ++q)
          for (unsigned int v = 0; v < n_vertices; ++v)
            {
              const Point<dim> &xi    = points.point(q);
              double            value = 1.;
              for (unsigned int d = 0; d < dim; ++d)
                value *= (v >> d & 1) ? xi[d] : 1. - xi[d];
              values[q][v] = value;
              for (unsigned int j = 0; j < dim; ++j)
                {
                  double derivative = (v >> j & 1) ? 1. : -1.;
                  for (unsigned int d = 0; d < dim; ++d)
                    if (d != j)
                      derivative *= (v >> d & 1) ? xi[d] : 1. - xi[d];
                  gradients[q][v][j] = derivative;
                }
            }
      }

      std::vector<std::array<double, n_vertices>>                  values;
      std::vector<std::array<std::array<double, dim>, n_vertices>> gradients;
      std::vector<double>                                          weights;
    };

    /** One side of a face at the face's points: each component's
     * derivative along this side's outward normal and, for the side that
     * integrates, the measure and (with a coefficient) the points. */
    template <int dim>
    struct Side
    {
      explicit Side(const unsigned int n_points)
        : normal_derivatives(n_points)
        , JxW(n_points)
        , points(n_points)
      {
      }
      std::vector<std::array<double, dim>> normal_derivatives;
      std::vector<double>                  JxW;
      std::vector<Point<dim>>              points;
    };

    template <int dim>
    class Estimator
    {
    public:
      using VectorType = LinearAlgebra::distributed::Vector<double>;
      using Cell       = typename DoFHandler<dim>::active_cell_iterator;

      Estimator(const DoFHandler<dim>     &dof_handler,
                const Quadrature<dim - 1> &face_quadrature,
                const VectorType          &solution,
                const Function<dim>       *coefficient)
        : solution(solution)
        , coefficient(coefficient)
        , n_points(face_quadrature.size())
        , faces(QProjector<dim>::project_to_all_faces(
            ReferenceCells::get_hypercube<dim>(),
            face_quadrature))
        , subfaces(QProjector<dim>::project_to_all_subfaces(
            ReferenceCells::get_hypercube<dim>(),
            face_quadrature))
        , working(n_points)
        , other(n_points)
        , dof_values(dof_handler.get_fe().n_dofs_per_cell())
      {
        const auto &fe = dof_handler.get_fe();
        for (unsigned int i = 0; i < fe.n_dofs_per_cell(); ++i)
          component_and_vertex.push_back(fe.system_to_component_index(i));
      }

      /** int_F |a [du/dn]|^2 over face @p face of @p cell, measured on
       * that side, against face @p other_face (its subface
       * @p other_subface, if not invalid) of @p neighbor. */
      double
      face_integral(const Cell        &cell,
                    const unsigned int face,
                    const Cell        &neighbor,
                    const unsigned int other_face,
                    const unsigned int other_subface)
      {
        evaluate(cell, face, numbers::invalid_unsigned_int, true, working);
        evaluate(neighbor, other_face, other_subface, false, other);
        std::vector<double> &jump = scratch_jump;
        jump.resize(n_points * dim);
        for (unsigned int q = 0; q < n_points; ++q)
          {
            const double a =
              coefficient ? coefficient->value(working.points[q]) : 1.;
            for (unsigned int c = 0; c < dim; ++c)
              jump[c * n_points + q] = a * (working.normal_derivatives[q][c] +
                                            other.normal_derivatives[q][c]);
          }
        // Summed component by component, as deal.II does.
        double integral = 0.;
        for (unsigned int c = 0; c < dim; ++c)
          for (unsigned int q = 0; q < n_points; ++q)
            integral +=
              jump[c * n_points + q] * jump[c * n_points + q] * working.JxW[q];
        return integral;
      }

    private:
      void
      evaluate(const Cell        &cell,
               const unsigned int face,
               const unsigned int subface,
               const bool         integrates,
               Side<dim>         &side)
      {
        constexpr unsigned int n_vertices = PointTable<dim>::n_vertices;
        const ReferenceCell    hypercube = ReferenceCells::get_hypercube<dim>();
        const unsigned int     offset =
          subface == numbers::invalid_unsigned_int ?
                static_cast<unsigned int>(QProjector<dim>::DataSetDescriptor::face(
              hypercube,
              face,
              cell->face_orientation(face),
              cell->face_flip(face),
              cell->face_rotation(face),
              n_points)) :
                static_cast<unsigned int>(
              QProjector<dim>::DataSetDescriptor::subface(
                hypercube,
                face,
                subface,
                cell->face_orientation(face),
                cell->face_flip(face),
                cell->face_rotation(face),
                n_points));
        const PointTable<dim> &table =
          subface == numbers::invalid_unsigned_int ? faces : subfaces;

        std::array<Point<dim>, n_vertices> vertices;
        for (unsigned int v = 0; v < n_vertices; ++v)
          vertices[v] = cell->vertex(v);
        std::array<std::array<double, dim>, n_vertices> u;
        cell->get_dof_values(solution, dof_values);
        for (unsigned int i = 0; i < dof_values.size(); ++i)
          u[component_and_vertex[i].second][component_and_vertex[i].first] =
            dof_values[i];

        const unsigned int normal_direction =
          GeometryInfo<dim>::unit_normal_direction[face];
        const double sign = GeometryInfo<dim>::unit_normal_orientation[face];
        for (unsigned int q = 0; q < n_points; ++q)
          {
            const auto    &gradients = table.gradients[offset + q];
            Tensor<2, dim> jacobian;
            double         reference_gradient[dim][dim] = {};
            for (unsigned int v = 0; v < n_vertices; ++v)
              for (unsigned int j = 0; j < dim; ++j)
                {
                  for (unsigned int i = 0; i < dim; ++i)
                    jacobian[i][j] += vertices[v][i] * gradients[v][j];
                  for (unsigned int c = 0; c < dim; ++c)
                    reference_gradient[c][j] += u[v][c] * gradients[v][j];
                }
            const double         det     = determinant(jacobian);
            const Tensor<2, dim> inverse = invert(jacobian);
            // The outward normal is J^{-T} of the reference one, scaled.
            Tensor<1, dim> normal;
            for (unsigned int k = 0; k < dim; ++k)
              normal[k] = sign * inverse[normal_direction][k];
            const double length = normal.norm();
            normal /= length;
            const Tensor<1, dim> direction = inverse * normal;
            for (unsigned int c = 0; c < dim; ++c)
              {
                double derivative = 0.;
                for (unsigned int j = 0; j < dim; ++j)
                  derivative += reference_gradient[c][j] * direction[j];
                side.normal_derivatives[q][c] = derivative;
              }
            if (integrates)
              {
                side.JxW[q] =
                  std::abs(det) * length * table.weights[offset + q];
                // The points only for a coefficient to be evaluated at.
                if (coefficient)
                  {
                    Point<dim> x;
                    for (unsigned int v = 0; v < n_vertices; ++v)
                      x += table.values[offset + q][v] * vertices[v];
                    side.points[q] = x;
                  }
              }
          }
      }

      const VectorType                                  &solution;
      const Function<dim>                               *coefficient;
      const unsigned int                                 n_points;
      const PointTable<dim>                              faces;
      const PointTable<dim>                              subfaces;
      Side<dim>                                          working;
      Side<dim>                                          other;
      Vector<double>                                     dof_values;
      std::vector<std::pair<unsigned int, unsigned int>> component_and_vertex;
      std::vector<double>                                scratch_jump;
    };
  } // namespace

  template <int dim>
  void
  estimate_kelly_indicators(
    const Mapping<dim>                               &mapping,
    const DoFHandler<dim>                            &dof_handler,
    const Quadrature<dim - 1>                        &face_quadrature,
    const LinearAlgebra::distributed::Vector<double> &solution,
    const Function<dim>                              *coefficient,
    Vector<float>                                    &indicators)
  {
    if (!is_linear_hypercube(mapping, dof_handler.get_fe()))
      {
        KellyErrorEstimator<dim>::estimate(mapping,
                                           dof_handler,
                                           face_quadrature,
                                           {},
                                           solution,
                                           indicators,
                                           ComponentMask(),
                                           coefficient);
        return;
      }

    const auto &mesh = dof_handler.get_triangulation();
    indicators.reinit(mesh.n_active_cells());
    Estimator<dim> estimator(dof_handler,
                             face_quadrature,
                             solution,
                             coefficient);
    // Each face's integral once, by its index (negative: not yet computed).
    std::vector<double> integrals(mesh.n_raw_faces(), -1.);
    const auto          integral_of = [&](const unsigned int index,
                                 const auto        &compute) {
      if (integrals[index] < 0.)
        integrals[index] = compute();
      return integrals[index];
    };

    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          const double factor = cell->diameter() / 24;
          float        sum    = 0.;
          for (const unsigned int f : cell->face_indices())
            {
              double integral = 0.;
              if (cell->at_boundary(f))
                continue;
              if (cell->face(f)->has_children())
                // Finer neighbours: over each subface, from the fine side.
                {
                  const auto         face     = cell->face(f);
                  const unsigned int opposite = cell->neighbor_of_neighbor(f);
                  for (unsigned int s = 0; s < face->n_children(); ++s)
                    integral += integral_of(face->child_index(s), [&]() {
                      return estimator.face_integral(
                        cell->neighbor_child_on_subface(f, s),
                        opposite,
                        cell,
                        f,
                        s);
                    });
                }
              else if (cell->neighbor_is_coarser(f))
                integral = integral_of(cell->face(f)->index(), [&]() {
                  const auto coarse = cell->neighbor(f);
                  const auto [coarse_face, subface] =
                    cell->neighbor_of_coarser_neighbor(f);
                  return estimator.face_integral(
                    cell, f, coarse, coarse_face, subface);
                });
              else
                // The same level: the side of the lower index integrates.
                integral = integral_of(cell->face(f)->index(), [&]() {
                  const auto         neighbor = cell->neighbor(f);
                  const unsigned int opposite = cell->neighbor_of_neighbor(f);
                  return neighbor->index() < cell->index() ?
                           estimator.face_integral(
                             neighbor,
                             opposite,
                             cell,
                             f,
                             numbers::invalid_unsigned_int) :
                           estimator.face_integral(
                             cell,
                             f,
                             neighbor,
                             opposite,
                             numbers::invalid_unsigned_int);
                });
              sum += integral * factor;
            }
          indicators(cell->active_cell_index()) = std::sqrt(sum);
        }
  }

  template void
  estimate_kelly_indicators<2>(
    const Mapping<2> &,
    const DoFHandler<2> &,
    const Quadrature<1> &,
    const LinearAlgebra::distributed::Vector<double> &,
    const Function<2> *,
    Vector<float> &);
  template void
  estimate_kelly_indicators<3>(
    const Mapping<3> &,
    const DoFHandler<3> &,
    const Quadrature<2> &,
    const LinearAlgebra::distributed::Vector<double> &,
    const Function<3> *,
    Vector<float> &);
} // namespace signorini
