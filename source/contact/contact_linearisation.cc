#include <deal.II/lac/full_matrix.h>

#include <signorini/contact/contact_linearisation.h>

#include <algorithm>
#include <cmath>
#include <map>

namespace signorini
{
  using namespace dealii;

  template <int dim>
  void
  ContactLinearisation<dim>::add_held_constraints(
    AffineConstraints<double> &constraints) const
  {
    std::map<unsigned int, std::vector<const ContactNode<dim> *>> corners;
    for (const auto *node : held)
      if (node->corner == numbers::invalid_unsigned_int)
        {
          // n.u = -gap, solved for the component along which n is largest.
          unsigned int along = 0;
          while (node->dofs[along] != node->scalar_dof)
            ++along;
          const double n = node->normal[along];
          constraints.add_line(node->scalar_dof);
          for (unsigned int d = 0; d < dim; ++d)
            if (d != along && node->normal[d] != 0.)
              constraints.add_entry(node->scalar_dof,
                                    node->dofs[d],
                                    -node->normal[d] / n);
          constraints.set_inhomogeneity(node->scalar_dof, -node->gap / n);
        }
      else
        corners[node->corner].push_back(node);

    for (const auto &[corner, nodes] : corners)
      {
        // N_S u_S + N_F u_F = -g for the m held nodes: u_S on the m free
        // components S with the largest |det N_S|, the others F.
        const unsigned int        m     = nodes.size();
        const auto               &first = *nodes.front();
        std::vector<unsigned int> best, columns;
        double                    best_det = 0.;
        const auto                choose   = [&](const auto        &self,
                                const unsigned int from) -> void {
          if (columns.size() == m)
            {
              FullMatrix<double> a(m, m);
              for (unsigned int i = 0; i < m; ++i)
                for (unsigned int j = 0; j < m; ++j)
                  a(i, j) = nodes[i]->normal[columns[j]];
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
          continue; // cannot happen: a corner's normals are independent
        FullMatrix<double> a(m, m);
        for (unsigned int i = 0; i < m; ++i)
          for (unsigned int j = 0; j < m; ++j)
            a(i, j) = nodes[i]->normal[best[j]];
        a.gauss_jordan();
        for (unsigned int j = 0; j < m; ++j)
          {
            const auto dof = first.dofs[best[j]];
            constraints.add_line(dof);
            double inhomogeneity = 0.;
            for (unsigned int i = 0; i < m; ++i)
              inhomogeneity -= a(j, i) * nodes[i]->gap;
            constraints.set_inhomogeneity(dof, inhomogeneity);
            for (unsigned int d = 0; d < dim; ++d)
              if (std::find(best.begin(), best.end(), d) == best.end())
                {
                  double weight = 0.;
                  for (unsigned int i = 0; i < m; ++i)
                    weight -= a(j, i) * nodes[i]->normal[d];
                  if (weight != 0.)
                    constraints.add_entry(dof, first.dofs[d], weight);
                }
          }
      }
  }

  template struct ContactLinearisation<2>;
  template struct ContactLinearisation<3>;
} // namespace signorini
