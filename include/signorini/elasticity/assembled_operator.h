#ifndef signorini_elasticity_assembled_operator_h
#define signorini_elasticity_assembled_operator_h

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/timer.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>

#include <signorini/discretisation/discretisation.h>
#include <signorini/elasticity/cell_stiffness.h>
#include <signorini/elasticity/elastic_operator.h>
#include <signorini/elasticity/linear_solver_parameters.h>
#include <signorini/elasticity/linear_system_solver.h>
#include <signorini/elasticity/loads.h>
#include <signorini/elasticity/material.h>

#include <cstddef>
#include <utility>

namespace signorini
{
  /**
   * The elastic operator as an assembled Trilinos matrix: cell matrices from
   * CellStiffness (once per cell shape), the contact linearisation's held
   * nodes as constraints and its springs added to the matrix, solved by
   * LinearSystemSolver. The matrix and its factorisation or AMG are kept
   * while the linearisation's key stays; only the extra forces then change
   * the right-hand side.
   */
  template <int dim>
  class AssembledOperator : public ElasticOperator<dim>
  {
  public:
    using VectorType = typename ElasticOperator<dim>::VectorType;

    /** @p remedies: a failed CG solve is retried (see LinearSystemSolver). */
    AssembledOperator(const Discretisation<dim>    &discretisation,
                      const Material               &material,
                      Loads<dim>                   &loads,
                      const LinearSolverParameters &parameters,
                      const bool                    remedies,
                      dealii::ConditionalOStream   &pcout,
                      dealii::TimerOutput          &timer);

    void
    reinit() override;

    void
    assemble_load() override;

    const VectorType &
    load() const override;

    void
    residual(const VectorType &u, VectorType &residual) override;

    void
    solve(const ContactLinearisation<dim> &linearisation,
          VectorType                      &u,
          const bool                       final_step) override;

    void
    invalidate() override;

    void
    release() override;

  private:
    /** The Newton system of @p linearisation, reusing the matrix if its key
     * is that of the last one. */
    void
    assemble_newton_system(const ContactLinearisation<dim> &linearisation);

    /** The stiffness matrix with the current constraints and the springs,
     * and the right-hand side without the extra forces. */
    void
    assemble_matrix(const ContactLinearisation<dim> &linearisation);

    const Discretisation<dim>    &discretisation;
    Loads<dim>                   &loads;
    const LinearSolverParameters &parameters;
    dealii::TimerOutput          &timer;

    /** Cell stiffness matrices, computed once per cell shape. */
    CellStiffness<dim> cell_stiffness;
    const Material    &material;
    /** The discretisation's constraints plus the held contact nodes. */
    dealii::AffineConstraints<double> constraints;
    /** The dofs that the held contact nodes' constraints solve for. */
    std::vector<dealii::types::global_dof_index> held_dofs;
    dealii::TrilinosWrappers::SparseMatrix       system_matrix;
    VectorType                                   system_rhs;
    /** system_rhs without the extra forces. */
    VectorType base_rhs;
    VectorType load_vector;
    /** The solver, with the factorisation or AMG of system_matrix. */
    LinearSystemSolver linear_system_solver;
    bool               matrix_assembled = false;
    /** The key of the linearisation system_matrix was assembled for. */
    std::pair<std::pair<unsigned int, std::size_t>, double> assembled_for;
  };
} // namespace signorini

#endif
