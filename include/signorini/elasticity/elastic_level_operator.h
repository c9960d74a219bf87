#ifndef signorini_elasticity_elastic_level_operator_h
#define signorini_elasticity_elastic_level_operator_h

#include <deal.II/base/subscriptor.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/mapping.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/la_parallel_vector.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/matrix_free/fe_evaluation.h>
#include <deal.II/matrix_free/matrix_free.h>

#include <signorini/elasticity/cell_matrices.h>
#include <signorini/elasticity/curved_cells.h>
#include <signorini/elasticity/material.h>

#include <array>
#include <memory>
#include <utility>
#include <vector>

namespace signorini
{
  /**
   * The stiffness operator of Q1 or Q2 elasticity (the degree of the
   * DoFHandler's element) on one mesh, evaluated cell by
   * cell with deal.II's MatrixFree (vectorised over cells, any number of
   * processes): the integral of eps(v) : sigma(u) with the isotropic law of
   * Material (plane strain, plane stress or 3D, volumetric strain at every
   * point). The hanging-node and Dirichlet constraints given to reinit()
   * are condensed; their rows act as the identity. Where every cell is a
   * parallelepiped (boxes), no MatrixFree is made: the cells' shape
   * matrices come from FEValues and the operator loops over its own dof
   * indices (MatrixFree::reinit() passes through about 1 kB per cell; at
   * 1.49M dofs on two processes it set the peak); at degree 2 in 3D they
   * are applied by CurvedCells' kernel in affine batches, their matrices
   * kept for the diagonal and the coarse level. Elsewhere MatrixFree
   * gives the curved cells' geometry, which CurvedCells evaluates.
   *
   * Around it, what contact adds, both local to a vertex:
   * - held lines: dofs expressed by other dofs of their vertex,
   *   u_s = sum_m w_m u_m (+ an inhomogeneity the caller lifts), the
   *   operator being P^T A P with P the map that sets them; their rows act
   *   as the identity;
   * - nodal blocks: a dim x dim stiffness added at a vertex's dofs (springs
   *   k n n^T), possibly not symmetric.
   *
   * A held line may have test weights of its own (Petrov-Galerkin: a
   * slipping node's): its row's force then goes to its masters with those
   * weights. The Newton system is then T^T A P + blocks, which
   * vmult_newton() applies; vmult() applies P^T A P with the blocks'
   * symmetric parts, the symmetric operator the multigrid smooths with
   * (the same where nothing breaks the symmetry).
   *
   * One level of ElasticMultigrid, and the fine-level operator that CG
   * solves with.
   */
  template <int dim>
  class ElasticLevelOperator : public dealii::Subscriptor
  {
  public:
    using VectorType = dealii::LinearAlgebra::distributed::Vector<double>;
    using value_type = double;
    /** A cell's evaluation at degree @p degree (Gauss points, degree + 1
     * per direction). */
    template <int degree>
    using Evaluation =
      dealii::FEEvaluation<dim, degree, degree + 1, dim, double>;

    /** A held dof and the dofs of its vertex it is solved from (global
     * indices, all owned here). */
    struct HeldLine
    {
      dealii::types::global_dof_index                                 dof;
      std::vector<std::pair<dealii::types::global_dof_index, double>> entries;
      /** Whether the row's force goes to the masters with test_entries
       * (Petrov-Galerkin) rather than with entries. */
      bool petrov_galerkin = false;
      std::vector<std::pair<dealii::types::global_dof_index, double>>
        test_entries;
    };

    /** A stiffness at the dofs of a vertex (global indices, owned here);
     * only its entries between unconstrained, not held dofs act. */
    struct NodalBlock
    {
      std::array<dealii::types::global_dof_index, dim> dofs;
      std::array<std::array<double, dim>, dim>         stiffness;
    };

    ElasticLevelOperator(const Material &material);

    /** The operator of @p dof_handler's active cells with the
     * @p constraints (hanging nodes and Dirichlet dofs; inhomogeneities are
     * ignored), which must live as long as it. Forgets the contact. */
    void
    reinit(const dealii::Mapping<dim>              &mapping,
           const dealii::DoFHandler<dim>           &dof_handler,
           const dealii::AffineConstraints<double> &constraints);

    /** Frees everything. */
    void
    clear();

    /** Sets what contact adds (see the class); recomputes the diagonal. */
    void
    set_contact(std::vector<HeldLine> held, std::vector<NodalBlock> blocks);

    /** dst = operator * src: P^T A P with the blocks' symmetric parts. */
    void
    vmult(VectorType &dst, const VectorType &src) const;

    /** dst = the Newton system * src: T^T A P with the blocks as they are
     * (vmult() where nothing breaks the symmetry). */
    void
    vmult_newton(VectorType &dst, const VectorType &src) const;

    /** vmult() with the cells applied in single precision, by their shape
     * matrices or by the kernel (the vectors and the constraints in
     * double): about 1e-7 relative, twice the entries per register, for
     * the multigrid's smoothing and residuals. */
    void
    vmult_single(VectorType &dst, const VectorType &src) const;

    void
    Tvmult(VectorType &dst, const VectorType &src) const;

    /** dst = C^T K u, the internal force of the displacement @p u read as
     * it is at every dof (constraints satisfied), with the hanging nodes
     * condensed and zero at the constrained dofs; no contact. */
    void
    internal_force(VectorType &dst, const VectorType &u) const;

    /** @p force = T^T @p force (a held dof's force moved to the dofs it is
     * solved from, with its test weights), then zero at the identity
     * rows. */
    void
    condense(VectorType &force) const;

    /** The inverse of the operator's diagonal (the held lines' cross terms
     * left out), for the Chebyshev smoother. */
    const VectorType &
    inverse_diagonal() const;

    /** The diagonal of the operator without contact (1 at constrained
     * dofs). */
    const VectorType &
    diagonal() const;

    /** The operator as a Trilinos matrix (the coarse level's), without
     * the held lines; or, with @p with_contact (the constraints of
     * reinit() with the held lines), the fine operator's symmetric part
     * itself: where the fine level is the only one. */
    void
    assemble_matrix(
      dealii::TrilinosWrappers::SparseMatrix  &matrix,
      const dealii::AffineConstraints<double> *with_contact = nullptr) const;

    void
    initialize_dof_vector(VectorType &vector) const;

    /** The diagonal entry (@p i = @p j, locally owned) as inverse_diagonal()
     * has it: what PreconditionChebyshev asks of a matrix (unused, since
     * the smoothers get the inverse diagonal). */
    double
    el(const dealii::types::global_dof_index i,
       const dealii::types::global_dof_index j) const;

    /** The number of dofs. */
    dealii::types::global_dof_index
    m() const;

    /** The locally owned dofs (local indices, sorted) whose rows are the
     * identity: the constrained and the held ones. */
    const std::vector<unsigned int> &
    identity_rows() const;

    const dealii::DoFHandler<dim> &
    get_dof_handler() const;

  private:
    /** Calls @p f with std::integral_constant<int, the element's degree>. */
    template <typename F>
    void
    with_degree(const F &f) const;

    /** dst = operator * src, the shape matrices applied in CellNumber:
     * the Newton system's (T^T A P, whole blocks) if @p newton, else the
     * symmetric one's (P^T A P, the blocks' symmetric parts). */
    template <typename CellNumber, bool newton>
    void
    apply(VectorType &dst, const VectorType &src) const;

    /** The cell's stiffness times its dof values (in place): its shape's
     * matrix where it has one, else apply_at_quadrature_points() (the
     * coarse level's matrix, through FEEvaluation). */
    template <int degree>
    void
    apply_cell(Evaluation<degree> &phi) const;

    /** The stress of a cell's quadrature points, integrated. */
    template <int degree>
    void
    apply_at_quadrature_points(Evaluation<degree> &phi) const;

    /** The stiffness of @p phi's cell by columns (n x n), from the
     * quadrature points. */
    template <int degree>
    void
    quadrature_matrix(Evaluation<degree>  &phi,
                      std::vector<double> &columns) const;

    using CellIterator = typename dealii::DoFHandler<dim>::active_cell_iterator;

    /** The matrices of the cells with an affine mapping, one per shape;
     * the others' geometry at their quadrature points (curved_cells). */
    template <int degree>
    void
    setup_cell_matrices();

    /** Without MatrixFree: if every locally owned cell on every process is
     * a parallelepiped (the mapping is linear) of at most
     * CellMatrices::max_matrices shapes, their matrices (from FEValues),
     * @p cells (the locally owned cells in the mesh's order) and the
     * vectors' layout (the cells' dofs and the masters of their
     * constrained dofs); else false, and nothing set. Collective. */
    bool
    setup_by_vertices(const dealii::Mapping<dim> &mapping,
                      std::vector<CellIterator>  &cells);

    /** At degree 2, every cell of @p cells (parallelepipeds, set up by
     * setup_by_vertices()) also in curved_cells' affine batches, by its
     * Jacobian: applied by sum factorisation, at about half the cost of
     * its 81 x 81 matrix (which the diagonal and the coarse matrix still
     * use). */
    void
    setup_affine_cells(const std::vector<CellIterator> &cells);

    /** The FE's local dof k at FEEvaluation's position (component by
     * component, the nodes lexicographic: Q1's as its vertices). */
    std::vector<unsigned int>
    evaluation_positions() const;

    /** dst += K src over all cells: the `direct` cells by their matrix,
     * the `resolved` ones by their matrix or by the kernel (a batch at a
     * time, when its first lane's cell comes) and by their constraint lines
     * (unless @p as_given); cells and batches applied in CellNumber. */
    template <int degree, bool as_given, typename CellNumber>
    void
    apply_cells(VectorType &dst, const VectorType &src) const;

    /** dst = K src (or as given) over all cells: src's ghosts imported for
     * the loop, dst's added to their owners. */
    template <bool as_given, typename CellNumber>
    void
    cell_loop(VectorType &dst, const VectorType &src) const;


    /** The diagonal and cell_dofs (with the constraint lines) of
     * @p cells, in the order of matrix_of_cell. */
    template <int degree>
    void
    compute_diagonal(const std::vector<CellIterator> &cells);

    /** cell_dofs with one entry per node for the direct cells, whose
     * nodes have their dim dofs one after the other (deal.II numbers
     * them so; checked): a third of the indices to read in 3D. */
    void
    compact_cell_dofs();

    const Material &material;
    const double    mu;
    const double    lambda;
    /** The element's degree (1 or 2), set by reinit(). */
    unsigned int fe_degree = 1;
    /** Its dofs per cell. */
    unsigned int                    n_cell_dofs = 0;
    dealii::MatrixFree<dim, double> matrix_free;
    /** The stiffness of each affine cell shape (cell batches of one cell:
     * Debian's deal.II does not vectorise over cells). */
    CellMatrices cell_matrices;
    /** The matrix of each cell, or CellMatrices::none. */
    std::vector<unsigned int> matrix_of_cell;
    /** The cells without a matrix (curved), eight at a time; each cell's
     * number among them, or CellMatrices::none. */
    CurvedCells               curved_cells;
    std::vector<unsigned int> curved_of_cell;
    /** Per cell, its dofs' local vector indices in FEEvaluation's order,
     * for every cell, which is read and written without FEEvaluation:
     * `direct` if it has a shape matrix and none of its dofs is
     * constrained, else `resolved` (below). */
    std::vector<unsigned int> cell_dofs;
    std::vector<bool>         direct;
    /** Once compact_cell_dofs() ran (at setup), cell_dofs holds n / dim
     * entries per cell: a direct cell's vertices' first dofs (the other
     * dim - 1 follow each), and in the first, a resolved cell's place in
     * resolved_dofs (in units of n), where its n entries are. */
    std::vector<unsigned int> resolved_dofs;
    /** The curved cells, and the cells with a shape matrix and
     * constrained dofs (hanging nodes, Dirichlet dofs; `resolved`: not
     * direct) are applied as C^T K C without FEEvaluation too: in their entries
     * (cell_dofs, then resolved_dofs), a constrained dof is constrained_flag |
     * the index of its line, whose (local index, weight) pairs are line_entries
     * from line_offsets[line] to line_offsets[line + 1] (none for a Dirichlet
     * dof). */
    std::vector<unsigned int>                    line_offsets;
    std::vector<std::pair<unsigned int, double>> line_entries;
    static constexpr unsigned int                constrained_flag = 1u << 31;
    /** Per line, the constrained dof's own local index (read where the
     * values are taken as given). */
    std::vector<unsigned int> line_dof;
    /** The curved cells' local indices, a batch at a time: entry
     * (batch * n + i) * lanes + lane for dof i of the batch's cell in
     * that lane, 0 for a constrained dof or a lane without a cell, which
     * batch_patches list (their position in the batch, and the dof's line
     * or CellMatrices::none), batch_patch_offsets[batch] on. */
    std::vector<unsigned int>                          batch_dofs;
    std::vector<std::pair<unsigned int, unsigned int>> batch_patches;
    std::vector<unsigned int>                          batch_patch_offsets;
    /** Per line, apply_cells()'s value of its dof and the force on it
     * (scratch). */
    mutable std::vector<double>              line_values, line_forces;
    const dealii::AffineConstraints<double> *constraints = nullptr;
    const dealii::DoFHandler<dim>           *dof_handler = nullptr;
    /** The vectors' layout: MatrixFree's, or setup_by_vertices()'s. */
    std::shared_ptr<const dealii::Utilities::MPI::Partitioner> partitioner;
    /** Whether setup_by_vertices() set the operator up (matrix_free is then
     * empty): its cells are the locally owned ones in the mesh's order. */
    bool by_vertices = false;
    /** Locally owned constrained dofs (local indices). */
    std::vector<unsigned int> constrained;
    /** constrained and the held dofs, sorted. */
    std::vector<unsigned int> identity;
    /** The held lines in local indices. */
    std::vector<
      std::pair<unsigned int, std::vector<std::pair<unsigned int, double>>>>
      held;
    /** Per held line, its test weights (its entries where it has none of
     * its own). */
    std::vector<std::vector<std::pair<unsigned int, double>>> held_test;
    /** The nodal blocks in local indices, without constrained or held
     * entries: as given, and their symmetric parts. */
    std::vector<std::pair<std::array<unsigned int, dim>,
                          std::array<std::array<double, dim>, dim>>>
               blocks, symmetric_blocks;
    VectorType diagonal_without_contact;
    VectorType inverse;
    /** src with the held dofs set (mutable scratch of vmult). */
    mutable VectorType projected;
  };
} // namespace signorini

#endif
