#ifndef signorini_elasticity_automatic_operator_h
#define signorini_elasticity_automatic_operator_h

#include <signorini/elasticity/elastic_operator.h>

#include <functional>
#include <memory>

namespace signorini
{
  template <int dim>
  class Discretisation;

  /**
   * `Linear solver/Type = automatic`: the elastic operator that measured
   * fastest for the mesh, chosen at the first reinit(), when the mesh is
   * known. MatrixFreeOperator on hexahedra in 3D with the volumetric strain
   * taken at every point when at least half the cells are parallelepipeds
   * with flat manifolds (their stiffness one matrix per shape, which stays
   * so as they refine): on sphere_indentation's boxes it solved faster than
   * the assembled operator on every mesh (2,187 to 493,287 dofs, one and
   * two processes; one linear solve 2.76 s against 6.39 s at 493,287 dofs)
   * in half the memory. AssembledOperator otherwise: on the Hertz quarter
   * ball's curved cells (evaluated at quadrature points, one at a time) one
   * linear solve took 6.62 s matrix-free against 4.24 s assembled (244,143
   * dofs). At degree 2 (Q2) in 3D always MatrixFreeOperator: on the Q2
   * Hertz ball (Kelly cycles to 85,863 dofs) the whole run took 6.9 s
   * matrix-free against 32.2 s assembled, in 314 MB against 581 MB, its
   * curved cells included.
   * In 2D the assembled solvers took half the matrix-free time on
   * the 2D Hertz scene at every size; tetrahedra and the cell mean of the
   * volumetric strain the matrix-free operator does not evaluate.
   */
  template <int dim>
  class AutomaticOperator : public ElasticOperator<dim>
  {
  public:
    using VectorType = typename ElasticOperator<dim>::VectorType;
    using Factory =
      std::function<std::unique_ptr<ElasticOperator<dim>>(bool matrix_free)>;

    /** @p make builds the matrix-free (true) or the assembled operator;
     * @p pointwise: whether the volumetric strain is taken at every
     * point and no line will have test weights of its own (what the
     * matrix-free operator does). */
    AutomaticOperator(const Discretisation<dim> &discretisation,
                      const bool                 pointwise,
                      Factory                    make);

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
    const Discretisation<dim>            &discretisation;
    const bool                            pointwise;
    Factory                               make;
    std::unique_ptr<ElasticOperator<dim>> chosen;
  };
} // namespace signorini

#endif
