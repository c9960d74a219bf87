#ifndef signorini_elasticity_assembled_operator_h
#define signorini_elasticity_assembled_operator_h

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/timer.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/vector.h>

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
   * CellStiffness (once per cell shape), the additions' constraint lines
   * condensed and their blocks added to the matrix, solved by
   * LinearSystemSolver. The matrix and its factorisation or AMG are kept
   * while the additions' key stays; only their forces then change the
   * right-hand side.
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
    solve(const SystemAdditions<dim> &additions,
          VectorType                 &u,
          const bool                  final_step) override;

    void
    invalidate() override;

    void
    release() override;

  private:
    /** The Newton system with the @p additions, reusing the matrix if
     * their key is that of the last one. */
    void
    assemble_newton_system(const SystemAdditions<dim> &additions);

    /** The stiffness matrix with the current constraints and the blocks,
     * and the right-hand side without the forces. */
    void
    assemble_matrix(const SystemAdditions<dim> &additions);

    /** Adds a cell's @p cell_matrix at @p dof_indices to the matrix as
     * Q^T K P (the test weights on the rows, the lines' on the columns) and
     * its lifting of the inhomogeneities to the right-hand side
     * (@p cell_lifted: scratch). */
    void
    add_petrov_galerkin(
      const dealii::FullMatrix<double>                   &cell_matrix,
      const std::vector<dealii::types::global_dof_index> &dof_indices,
      dealii::Vector<double>                             &cell_lifted);

    const Discretisation<dim>    &discretisation;
    Loads<dim>                   &loads;
    const LinearSolverParameters &parameters;
    dealii::TimerOutput          &timer;

    /** Cell stiffness matrices, computed once per cell shape. */
    CellStiffness<dim> cell_stiffness;
    const Material    &material;
    /** The discretisation's constraints plus the additions' lines. */
    dealii::AffineConstraints<double> constraints;
    /** The same with the lines' test weights, where a line has its own:
     * the equations' side of the condensation (empty where it is the
     * constraints' side). */
    dealii::AffineConstraints<double>      test_constraints;
    dealii::TrilinosWrappers::SparseMatrix system_matrix;
    VectorType                             system_rhs;
    /** system_rhs without the extra forces. */
    VectorType base_rhs;
    VectorType load_vector;
    /** The solver, with the factorisation or AMG of system_matrix. */
    LinearSystemSolver linear_system_solver;
    bool               matrix_assembled = false;
    /** The key of the additions system_matrix was assembled for. */
    typename SystemAdditions<dim>::Key assembled_for;
  };
} // namespace signorini

#endif
