#include <signorini/elasticity/system_additions.h>

namespace signorini
{
  template <int dim>
  void
  SystemAdditions<dim>::add_constraints(
    dealii::AffineConstraints<double> &constraints) const
  {
    for (const auto &line : this->constraints)
      {
        constraints.add_line(line.dof);
        for (const auto &[master, weight] : line.entries)
          constraints.add_entry(line.dof, master, weight);
        constraints.set_inhomogeneity(line.dof, line.inhomogeneity);
      }
  }

  template <int dim>
  void
  SystemAdditions<dim>::add_test_constraints(
    dealii::AffineConstraints<double> &constraints) const
  {
    for (const auto &line : this->constraints)
      {
        constraints.add_line(line.dof);
        for (const auto &[master, weight] :
             line.petrov_galerkin ? line.test_entries : line.entries)
          constraints.add_entry(line.dof, master, weight);
      }
  }

  template struct SystemAdditions<2>;
  template struct SystemAdditions<3>;
} // namespace signorini
