#include <deal.II/base/mpi.h>
#include <deal.II/lac/full_matrix.h>

#include <signorini/contact/condition_enforcement.h>

#include <algorithm>
#include <cmath>
#include <map>

namespace signorini
{
  namespace condition_enforcement
  {
    using namespace dealii;

    namespace
    {
      /** d.u = value solved for component c: one line. */
      template <int dim>
      void
      add_line(const ContactNode<dim>   &node,
               const NodeCondition<dim> &condition,
               SystemAdditions<dim>     &additions)
      {
        const unsigned int along = condition.component;
        const double       d     = condition.direction[along];
        typename SystemAdditions<dim>::ConstraintLine line;
        line.dof = node.dofs[along];
        for (unsigned int k = 0; k < dim; ++k)
          if (k != along && condition.direction[k] != 0.)
            line.entries.emplace_back(node.dofs[k],
                                      -condition.direction[k] / d);
        line.inhomogeneity = condition.value / d;
        additions.constraints.push_back(std::move(line));
      }

      /** D_S u_S + D_F u_F = values for the m conditions of one vertex:
       * u_S on the m free components S with the largest |det D_S|, the
       * others F. */
      template <int dim>
      void
      add_lines(const ContactNode<dim>                &first,
                const std::vector<NodeCondition<dim>> &conditions,
                SystemAdditions<dim>                  &additions)
      {
        const unsigned int        m = conditions.size();
        std::vector<unsigned int> best, columns;
        double                    best_det = 0.;
        const auto choose = [&](const auto &self, const unsigned int from) {
          if (columns.size() == m)
            {
              FullMatrix<double> a(m, m);
              for (unsigned int i = 0; i < m; ++i)
                for (unsigned int j = 0; j < m; ++j)
                  a(i, j) = conditions[i].direction[columns[j]];
              const double det = std::abs(a.determinant());
              if (det > best_det)
                {
                  best_det = det;
                  best     = columns;
                }
              return;
            }
          for (unsigned int d = from; d < dim; ++d)
            if (first.free[d])
              {
                columns.push_back(d);
                self(self, d + 1);
                columns.pop_back();
              }
        };
        choose(choose, 0);
        if (best.size() != m)
          return; // cannot happen: a corner's normals are independent
        FullMatrix<double> a(m, m);
        for (unsigned int i = 0; i < m; ++i)
          for (unsigned int j = 0; j < m; ++j)
            a(i, j) = conditions[i].direction[best[j]];
        a.gauss_jordan();
        for (unsigned int j = 0; j < m; ++j)
          {
            typename SystemAdditions<dim>::ConstraintLine line;
            line.dof = first.dofs[best[j]];
            for (unsigned int i = 0; i < m; ++i)
              line.inhomogeneity += a(j, i) * conditions[i].value;
            for (unsigned int d = 0; d < dim; ++d)
              if (std::find(best.begin(), best.end(), d) == best.end())
                {
                  double weight = 0.;
                  for (unsigned int i = 0; i < m; ++i)
                    weight -= a(j, i) * conditions[i].direction[d];
                  if (weight != 0.)
                    line.entries.emplace_back(first.dofs[d], weight);
                }
            additions.constraints.push_back(std::move(line));
          }
      }
      /** The force equations E f = values of @p node, whose conditions are
       * the lines @p first ... of @p additions: on the node's free dofs F
       * that no line solves for, as f_F + V f_S = E_F^-1 values (f_S on the
       * lines' dofs S, V = E_F^-1 E_S): the lines' test weights V and
       * forces at F. Returns whether it could (as many equations as F, E_F
       * regular); if not, F keeps the force balance. */
      template <int dim>
      bool
      add_equations(const ContactNode<dim>               &node,
                    const std::vector<NodeEquation<dim>> &equations,
                    const std::size_t                     first,
                    SystemAdditions<dim>                 &additions)
      {
        std::vector<unsigned int> solved, others;
        for (unsigned int d = 0; d < dim; ++d)
          {
            bool is_solved = false;
            for (std::size_t l = first; l < additions.constraints.size(); ++l)
              is_solved =
                is_solved || additions.constraints[l].dof == node.dofs[d];
            if (is_solved)
              solved.push_back(d);
            else if (node.free[d])
              others.push_back(d);
          }
        const unsigned int k = others.size();
        if (k == 0 || equations.size() != k)
          return false;
        FullMatrix<double> e_f(k, k);
        for (unsigned int i = 0; i < k; ++i)
          for (unsigned int j = 0; j < k; ++j)
            e_f(i, j) = equations[i].direction[others[j]];
        if (std::abs(e_f.determinant()) < 1e-8)
          return false;
        e_f.gauss_jordan();
        for (std::size_t l = first; l < additions.constraints.size(); ++l)
          {
            auto        &line = additions.constraints[l];
            unsigned int s    = 0;
            while (node.dofs[s] != line.dof)
              ++s;
            line.petrov_galerkin = true;
            for (unsigned int j = 0; j < k; ++j)
              {
                double v = 0.;
                for (unsigned int i = 0; i < k; ++i)
                  v += e_f(j, i) * equations[i].direction[s];
                if (v != 0.)
                  line.test_entries.emplace_back(node.dofs[others[j]], v);
              }
          }
        if (node.owned)
          {
            // The equations' displacement terms E_F^-1 G, a block at the
            // rows F.
            typename SystemAdditions<dim>::Block block;
            block.rows    = node.dofs;
            block.columns = node.dofs;
            bool any      = false;
            for (unsigned int j = 0; j < k; ++j)
              {
                double value = 0.;
                for (unsigned int i = 0; i < k; ++i)
                  {
                    value += e_f(j, i) * equations[i].value;
                    for (unsigned int d = 0; d < dim; ++d)
                      block.matrix[others[j]][d] +=
                        e_f(j, i) * equations[i].displacement[d];
                  }
                if (value != 0.)
                  additions.forces.push_back({node.dofs[others[j]], value});
                for (unsigned int d = 0; d < dim; ++d)
                  any = any || block.matrix[others[j]][d] != 0.;
              }
            if (any)
              additions.blocks.push_back(block);
          }
        return true;
      }

      /** The obstacle's tangential forces of @p node, which its force
       * @p equations E f + G u = v bind to its normal spring's force
       * f_n = k (v_n - n.u) + m lambda (of the @p normal condition n.u =
       * v_n, the spring's @p stiffness k and the augmented Lagrangian's
       * @p multiplier force m lambda): f_T = A^-1 (v - G u - (E n) f_n) along
       * its free tangents t_j, A_ij = e_i.t_j; a block on its dofs. */
      template <int dim>
      void
      add_spring_equations(const ContactNode<dim>               &node,
                           const NodeCondition<dim>             &normal,
                           const std::vector<NodeEquation<dim>> &equations,
                           const double                          stiffness,
                           const double                          multiplier,
                           SystemAdditions<dim>                 &additions)
      {
        std::vector<Tensor<1, dim>> tangents;
        for (const auto &t : node.tangents)
          if (ContactSurface<dim>::free_part(t, node.free) >=
              ContactSurface<dim>::fixed_along_normal)
            tangents.push_back(t);
        const unsigned int k = tangents.size();
        if (k == 0 || equations.size() != k)
          return;
        FullMatrix<double> a(k, k);
        for (unsigned int i = 0; i < k; ++i)
          for (unsigned int j = 0; j < k; ++j)
            a(i, j) = equations[i].direction * tangents[j];
        if (std::abs(a.determinant()) < 1e-8)
          return;
        a.gauss_jordan();
        const Tensor<1, dim>                &n = normal.direction;
        typename SystemAdditions<dim>::Block block;
        block.rows    = node.dofs;
        block.columns = node.dofs;
        for (unsigned int j = 0; j < k; ++j)
          {
            Tensor<1, dim> w;
            double         r = 0.;
            for (unsigned int i = 0; i < k; ++i)
              {
                const double en = equations[i].direction * n;
                w += a(j, i) * (equations[i].displacement - stiffness * en * n);
                r += a(j, i) * (equations[i].value -
                                en * (stiffness * normal.value + multiplier));
              }
            for (unsigned int p = 0; p < dim; ++p)
              {
                for (unsigned int q = 0; q < dim; ++q)
                  block.matrix[p][q] += tangents[j][p] * w[q];
                block.rhs[p] += tangents[j][p] * r;
              }
          }
        additions.blocks.push_back(block);
      }
    } // namespace

    template <int dim>
    void
    add_constraints(const ContactSurface<dim>            &surface,
                    const ContactLaw<dim>                &law,
                    const std::vector<NodeTraction<dim>> &tractions,
                    SystemAdditions<dim>                 &additions)
    {
      // A node with one condition alone on its vertex: one line; the
      // conditions of a corner's nodes (and several of one node) together,
      // after the others.
      std::map<unsigned int, std::vector<NodeCondition<dim>>> corners;
      std::map<unsigned int, unsigned int>                    corner_node;
      std::vector<NodeCondition<dim>>                         conditions;
      std::vector<NodeEquation<dim>>                          equations;
      bool        test_weights = false, forces = false;
      const auto &nodes = surface.nodes();
      for (unsigned int i = 0; i < nodes.size(); ++i)
        {
          const auto &node = nodes[i];
          conditions.clear();
          equations.clear();
          law.conditions(node, tractions[i], conditions, equations);
          if (conditions.empty())
            continue;
          if (!equations.empty() &&
              node.corner == numbers::invalid_unsigned_int)
            {
              // A node with equations alone: its lines, then their test
              // weights (a law gives a corner's nodes no equations).
              const std::size_t first = additions.constraints.size();
              if (conditions.size() == 1)
                add_line(node, conditions.front(), additions);
              else
                add_lines(node, conditions, additions);
              if (add_equations(node, equations, first, additions))
                {
                  test_weights = true;
                  forces       = forces || node.owned;
                }
            }
          else if (node.corner == numbers::invalid_unsigned_int &&
                   conditions.size() == 1)
            add_line(node, conditions.front(), additions);
          else
            {
              // A node's own group sits after every corner's.
              const unsigned int group =
                node.corner != numbers::invalid_unsigned_int ?
                  node.corner :
                  surface.corners().size() + i;
              corners[group].insert(corners[group].end(),
                                    conditions.begin(),
                                    conditions.end());
              corner_node.emplace(group, i);
            }
          if (node.owned)
            for (const auto &condition : conditions)
              additions.constraint_springs.push_back(
                {node.dofs, condition.direction, node.scalar_dof});
        }
      for (const auto &[group, group_conditions] : corners)
        add_lines(nodes[corner_node.at(group)], group_conditions, additions);
      const MPI_Comm comm = surface.communicator();
      additions.has_blocks =
        additions.has_blocks ||
        Utilities::MPI::logical_or(!additions.blocks.empty(), comm);
      if (Utilities::MPI::logical_or(test_weights, comm))
        {
          additions.has_test_weights = true;
          additions.symmetric        = false;
        }
      additions.has_forces =
        additions.has_forces || Utilities::MPI::logical_or(forces, comm);
    }

    template <int dim>
    void
    add_springs(const ContactSurface<dim>            &surface,
                const ContactLaw<dim>                &law,
                const std::vector<NodeTraction<dim>> &tractions,
                const double                          epsilon,
                const std::vector<double>            &multipliers,
                const std::vector<Tensor<1, dim>>    &tangential_multipliers,
                SystemAdditions<dim>                 &additions)
    {
      // The spring's force (k (value - d.u)) d, k = m / epsilon: at a
      // normal condition n.u = -gap, the obstacle's push -(k n.u + m gap /
      // epsilon) n on a penetrating node; the augmented Lagrangian adds
      // the multiplier's m lambda n.
      std::vector<NodeCondition<dim>> conditions;
      std::vector<NodeEquation<dim>>  equations;
      const auto                     &nodes = surface.nodes();
      for (unsigned int i = 0; i < nodes.size(); ++i)
        if (nodes[i].owned)
          {
            const auto &node = nodes[i];
            conditions.clear();
            equations.clear();
            law.conditions(node, tractions[i], conditions, equations);
            const double stiffness = node.mass / epsilon;
            if (!equations.empty() && !conditions.empty())
              {
                add_spring_equations(node,
                                     conditions.front(),
                                     equations,
                                     stiffness,
                                     multipliers.empty() ?
                                       0. :
                                       node.mass * multipliers[i],
                                     additions);
                additions.symmetric = false;
              }
            for (unsigned int c = 0; c < conditions.size(); ++c)
              {
                const auto  &d = conditions[c].direction;
                const double rest =
                  -(node.mass * conditions[c].value) / epsilon;
                typename SystemAdditions<dim>::Block block;
                block.rows    = node.dofs;
                block.columns = node.dofs;
                for (unsigned int a = 0; a < dim; ++a)
                  {
                    for (unsigned int b = 0; b < dim; ++b)
                      block.matrix[a][b] = stiffness * d[a] * d[b];
                    block.rhs[a] = -(rest * d[a]);
                  }
                additions.blocks.push_back(block);
                // The multipliers' forces: m lambda along the normal, and
                // along a sticking node's tangents m lambda_t.
                const double lambda =
                  c == 0 ? (multipliers.empty() ? 0. : multipliers[i]) :
                           (tangential_multipliers.empty() ?
                              0. :
                              tangential_multipliers[i] * d);
                if (lambda != 0.)
                  for (unsigned int a = 0; a < dim; ++a)
                    if (d[a] != 0. && node.free[a])
                      additions.forces.push_back(
                        {node.dofs[a], node.mass * lambda * d[a]});
              }
          }
      additions.has_blocks = true;
      // The same on every process (one may hold no contact node).
      additions.has_forces = Utilities::MPI::logical_or(!multipliers.empty(),
                                                        surface.communicator());
      // Slipping nodes' forces are not symmetric in their displacements.
      additions.symmetric = !Utilities::MPI::logical_or(!additions.symmetric,
                                                        surface.communicator());
    }

    template void
    add_constraints(const ContactSurface<2> &,
                    const ContactLaw<2> &,
                    const std::vector<NodeTraction<2>> &,
                    SystemAdditions<2> &);
    template void
    add_constraints(const ContactSurface<3> &,
                    const ContactLaw<3> &,
                    const std::vector<NodeTraction<3>> &,
                    SystemAdditions<3> &);
    template void
    add_springs(const ContactSurface<2> &,
                const ContactLaw<2> &,
                const std::vector<NodeTraction<2>> &,
                const double,
                const std::vector<double> &,
                const std::vector<Tensor<1, 2>> &,
                SystemAdditions<2> &);
    template void
    add_springs(const ContactSurface<3> &,
                const ContactLaw<3> &,
                const std::vector<NodeTraction<3>> &,
                const double,
                const std::vector<double> &,
                const std::vector<Tensor<1, 3>> &,
                SystemAdditions<3> &);
  } // namespace condition_enforcement
} // namespace signorini
