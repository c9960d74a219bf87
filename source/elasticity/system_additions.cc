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

  template <int dim>
  void
  SystemAdditions<dim>::close(dealii::AffineConstraints<double>       &lines,
                              const dealii::AffineConstraints<double> &given,
                              const dealii::IndexSet                  &relevant,
                              const bool test_weights) const
  {
    lines.clear();
    lines.reinit(relevant);
    if (test_weights)
      add_test_constraints(lines);
    else
      add_constraints(lines);
    lines.merge(given, dealii::AffineConstraints<double>::left_object_wins);
    lines.close();
  }

  template struct SystemAdditions<2>;
  template struct SystemAdditions<3>;
} // namespace signorini
