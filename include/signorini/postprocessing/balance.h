#ifndef signorini_postprocessing_balance_h
#define signorini_postprocessing_balance_h

#include <deal.II/base/tensor.h>
#include <deal.II/lac/trilinos_vector.h>

#include <signorini/discretisation/discretisation.h>
#include <signorini/elasticity/loads.h>
#include <signorini/elasticity/material.h>

namespace signorini
{
  /** The forces on the body and its energy. */
  template <int dim>
  struct Balance
  {
    /** The loads' resultant, the integral of traction and body force [N]. */
    dealii::Tensor<1, dim> applied_force;
    /** Resultant of the reactions at the Dirichlet supports [N]. */
    dealii::Tensor<1, dim> support_reaction;
    /** Potential energy 1/2 a(u,u) - f(u) [N mm]. */
    double energy = 0.;
  };

  /**
   * Cell by cell, with the unconstrained cell matrices: the internal force
   * K u, the load f, their difference at the supported dofs (the support
   * reaction), and the energy 1/2 u.K u - f.u of the ghosted displacement
   * @p u, with the loads of the last Loads::assemble().
   */
  template <int dim>
  Balance<dim>
  evaluate_balance(const Discretisation<dim>                   &discretisation,
                   const Loads<dim>                            &loads,
                   const Material                              &material,
                   const dealii::TrilinosWrappers::MPI::Vector &u);
} // namespace signorini

#endif
