#include <deal.II/base/mpi.h>
#include <deal.II/fe/fe.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <signorini/base/text.h>
#include <signorini/elasticity/rigid_motions.h>
#include <signorini/input/input_error.h>

#include <cmath>
#include <limits>

namespace signorini
{
  using namespace dealii;

  namespace
  {
    /** @p x embedded in 3D. */
    template <int dim>
    Tensor<1, 3>
    in_space(const Tensor<1, dim> &x)
    {
      Tensor<1, 3> y;
      for (unsigned int d = 0; d < dim; ++d)
        y[d] = x[d];
      return y;
    }

    /** "x", "y" or "z" for a direction along an axis, else its unit vector
     * "(a, b[, c])" with its first component positive. */
    std::string
    rigid_direction(Tensor<1, 3> direction, const unsigned int dim)
    {
      direction /= direction.norm();
      for (unsigned int d = 0; d < dim; ++d)
        if (std::abs(direction[d]) >= 1. - 1e-9)
          return std::string(1, static_cast<char>('x' + d));
      for (unsigned int d = 0; d < dim; ++d)
        if (std::abs(direction[d]) > 1e-9)
          {
            if (direction[d] < 0.)
              direction *= -1.;
            break;
          }
      std::string text = "(";
      for (unsigned int d = 0; d < dim; ++d)
        text += (d > 0 ? ", " : "") +
                number(std::abs(direction[d]) > 1e-9 ? direction[d] : 0.);
      return text + ")";
    }

    /** The rigid motion sum_k @p coefficients[k] @p modes[k] in words: a
     * translation along its direction, or a rotation about the point (2D)
     * or the axis through a point (3D) that it leaves in place. */
    template <int dim>
    std::string
    rigid_motion_in_words(const Vector<double>              &coefficients,
                          const std::vector<RigidMode<dim>> &modes,
                          const double                       length)
    {
      // u(x) = translation + rotation x x, about the origin.
      Tensor<1, 3> translation, rotation;
      for (unsigned int k = 0; k < modes.size(); ++k)
        {
          Tensor<1, 3> spin = modes[k].rotation;
          if (dim == 2)
            spin[0] = spin[1] = 0.;
          rotation += coefficients[k] * spin;
          translation += coefficients[k] *
                         (in_space(modes[k].translation) -
                          cross_product_3d(spin, in_space(modes[k].centre)));
        }
      if (rotation.norm() * length <= 1e-9 * translation.norm())
        return "a translation along " + rigid_direction(translation, dim);
      const Tensor<1, 3> fixed =
        cross_product_3d(rotation, translation) / rotation.norm_square();
      std::string point = "(";
      for (unsigned int d = 0; d < dim; ++d)
        point += (d > 0 ? ", " : "") +
                 number(std::abs(fixed[d]) > 1e-9 * length ? fixed[d] : 0.);
      point += ")";
      if (dim == 2)
        return "a rotation about the point " + point;
      return "a rotation about the axis along " +
             rigid_direction(rotation, dim) + " through " + point;
    }
  } // namespace

  template <int dim>
  Tensor<1, dim>
  RigidMode<dim>::value(const Point<dim> &x) const
  {
    const Tensor<1, 3> turn = cross_product_3d(rotation, in_space(x - centre));
    Tensor<1, dim>     u    = translation;
    for (unsigned int d = 0; d < dim; ++d)
      u[d] += turn[d];
    return u;
  }

  template <int dim>
  std::vector<RigidMode<dim>>
  rigid_body_modes(const Discretisation<dim> &discretisation)
  {
    const MPI_Comm comm = discretisation.mpi_communicator();
    Point<dim>     lower, upper;
    for (unsigned int d = 0; d < dim; ++d)
      {
        lower[d] = std::numeric_limits<double>::max();
        upper[d] = -std::numeric_limits<double>::max();
      }
    for (const auto &cell :
         discretisation.triangulation().active_cell_iterators())
      if (cell->is_locally_owned())
        for (const unsigned int v : cell->vertex_indices())
          for (unsigned int d = 0; d < dim; ++d)
            {
              lower[d] = std::min(lower[d], cell->vertex(v)[d]);
              upper[d] = std::max(upper[d], cell->vertex(v)[d]);
            }
    for (unsigned int d = 0; d < dim; ++d)
      {
        lower[d] = Utilities::MPI::min(lower[d], comm);
        upper[d] = Utilities::MPI::max(upper[d], comm);
      }
    const Point<dim> centre    = 0.5 * (lower + upper);
    const double     half_size = 0.5 * lower.distance(upper);
    const double     rate      = half_size > 0. ? 1. / half_size : 1.;

    std::vector<RigidMode<dim>> modes;
    if (discretisation.axisymmetric())
      {
        // A body of revolution moves rigidly along its axis only (the axis
        // holds it radially, and it cannot turn in its section).
        RigidMode<dim> along_axis;
        along_axis.translation[1] = 1.;
        along_axis.centre         = centre;
        return {along_axis};
      }
    for (unsigned int d = 0; d < dim; ++d)
      {
        RigidMode<dim> mode;
        mode.translation[d] = 1.;
        mode.centre         = centre;
        modes.push_back(mode);
      }
    for (unsigned int axis = (dim == 2 ? 2 : 0); axis < 3; ++axis)
      {
        RigidMode<dim> mode;
        mode.rotation[axis] = rate;
        mode.centre         = centre;
        modes.push_back(mode);
      }
    return modes;
  }

  template <int dim>
  bool
  check_rigid_motions_held(
    const Discretisation<dim>             &discretisation,
    const std::vector<HeldDirection<dim>> &contact_directions,
    const std::vector<RigidMode<dim>>     &modes,
    const bool                             contact_can_hold)
  {
    const unsigned int n = modes.size();
    if (n == 0)
      return true;
    // The Gram matrix of the constraints' rows (the modes at a constraint),
    // summed over the processes: its rank is the constraint matrix's.
    std::vector<double> gram(n * n, 0.);
    Vector<double>      row(n);
    const auto          add_row = [&]() {
      for (unsigned int i = 0; i < n; ++i)
        for (unsigned int j = 0; j < n; ++j)
          gram[i * n + j] += row[i] * row[j];
    };

    // Every dof of a fixed component, once, on the process that owns it.
    const auto       &fe          = discretisation.fe();
    const auto       &owned       = discretisation.locally_owned_dofs();
    const auto       &supported   = discretisation.support_dofs();
    const auto       &unit_points = fe.get_unit_support_points();
    std::vector<bool> seen(owned.n_elements(), false);
    std::vector<types::global_dof_index> cell_dofs(fe.n_dofs_per_cell());
    for (const auto &cell :
         discretisation.dof_handler().active_cell_iterators())
      if (cell->is_locally_owned() && cell->at_boundary())
        {
          cell->get_dof_indices(cell_dofs);
          for (unsigned int i = 0; i < cell_dofs.size(); ++i)
            {
              const auto dof = cell_dofs[i];
              if (!owned.is_element(dof) || !supported.is_element(dof) ||
                  seen[owned.index_within_set(dof)])
                continue;
              seen[owned.index_within_set(dof)] = true;
              const Point<dim> x =
                discretisation.mapping().transform_unit_to_real_cell(
                  cell, unit_points[i]);
              const unsigned int component =
                fe.system_to_component_index(i).first;
              for (unsigned int m = 0; m < n; ++m)
                row[m] = modes[m].value(x)[component];
              add_row();
            }
        }
    // The supports alone, then contact holding a node along the obstacle's
    // normal as well.
    std::vector<double> supports_gram = gram;
    if (contact_can_hold)
      for (const auto &[position, direction] : contact_directions)
        {
          for (unsigned int m = 0; m < n; ++m)
            row[m] = modes[m].value(position) * direction;
          add_row();
        }
    // The motions that a Gram matrix (this process's part) leaves free, in
    // words. Collective.
    const auto free_motions_of = [&](std::vector<double> part) {
      std::vector<double> summed(part.size());
      Utilities::MPI::sum(part, discretisation.mpi_communicator(), summed);

      // Cholesky in the order of the modes: a mode whose Schur complement on
      // the modes held before it vanishes is free, combined with those.
      FullMatrix<double> g(n, n);
      for (unsigned int i = 0; i < n; ++i)
        for (unsigned int j = 0; j < n; ++j)
          g(i, j) = summed[i * n + j];
      std::vector<unsigned int> held;
      std::vector<std::string>  free_motions;
      for (unsigned int m = 0; m < n; ++m)
        {
          Vector<double> motion(n);
          motion[m]                = 1.;
          double             schur = g(m, m);
          const unsigned int h     = held.size();
          if (h > 0)
            {
              FullMatrix<double> inverse(h, h);
              Vector<double>     coupling(h), coefficients(h);
              for (unsigned int a = 0; a < h; ++a)
                {
                  coupling[a] = g(held[a], m);
                  for (unsigned int b = 0; b < h; ++b)
                    inverse(a, b) = g(held[a], held[b]);
                }
              inverse.gauss_jordan();
              inverse.vmult(coefficients, coupling);
              for (unsigned int a = 0; a < h; ++a)
                {
                  schur -= coupling[a] * coefficients[a];
                  motion[held[a]] = -coefficients[a];
                }
            }
          if (schur <= 1e-10 * g(m, m))
            free_motions.push_back(rigid_motion_in_words(
              motion, modes, 0.5 * discretisation.body_size()));
          else
            held.push_back(m);
        }
      return free_motions;
    };
    const auto free_motions = free_motions_of(gram);
    if (free_motions.empty())
      return free_motions_of(supports_gram).empty();

    std::string motions;
    for (unsigned int k = 0; k < free_motions.size(); ++k)
      motions += (k == 0                       ? "" :
                  k + 1 == free_motions.size() ? " and " :
                                                 ", ") +
                 free_motions[k];
    throw InputError(
      "Boundary conditions/Dirichlet",
      "nothing holds the body against " + motions +
        ": add a support that fixes " +
        (free_motions.size() > 1 ? "them" : "it") +
        ", or a contact boundary (Obstacle/Contact boundary ids) whose "
        "obstacle can push against " +
        (free_motions.size() > 1 ? "them" : "it") +
        (contact_can_hold ? "" :
                            " (with Contact/Method = none the obstacle "
                            "holds nothing)"));
  }

  template struct RigidMode<2>;
  template struct RigidMode<3>;
  template std::vector<RigidMode<2>>
  rigid_body_modes(const Discretisation<2> &);
  template std::vector<RigidMode<3>>
  rigid_body_modes(const Discretisation<3> &);
  template bool
  check_rigid_motions_held(const Discretisation<2> &,
                           const std::vector<HeldDirection<2>> &,
                           const std::vector<RigidMode<2>> &,
                           const bool);
  template bool
  check_rigid_motions_held(const Discretisation<3> &,
                           const std::vector<HeldDirection<3>> &,
                           const std::vector<RigidMode<3>> &,
                           const bool);
} // namespace signorini
