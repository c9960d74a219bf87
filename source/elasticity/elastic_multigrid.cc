#include <deal.II/base/function.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/numerics/vector_tools.h>

#include <signorini/base/failures.h>
#include <signorini/elasticity/coarsening_sequence.h>
#include <signorini/elasticity/elastic_multigrid.h>

namespace signorini
{
  using namespace dealii;

  namespace
  {
    /** The coarsest level's solve: the factorisation of its matrix. */
    template <typename VectorType>
    class DirectCoarseSolve : public MGCoarseGridBase<VectorType>
    {
    public:
      DirectCoarseSolve(TrilinosWrappers::SolverDirect &solver)
        : solver(solver)
      {
      }

      void
      operator()(const unsigned int,
                 VectorType       &dst,
                 const VectorType &src) const override
      {
        solver.solve(dst, src);
      }

    private:
      TrilinosWrappers::SolverDirect &solver;
    };

    /** Chebyshev smoothing: degree 3 over the upper 1/20 of the spectrum
     * of D^-1 A, its largest eigenvalue estimated by 12 CG steps once per
     * mesh (degree 5 took 25 % fewer CG iterations but 20 % more time:
     * 165k dofs, sphere_indentation's cycle 4). */
    constexpr unsigned int chebyshev_degree    = 3;
    constexpr double       smoothing_range     = 20.;
    constexpr unsigned int eigenvalue_cg_steps = 12;
  } // namespace

  template <int dim>
  ElasticMultigrid<dim>::ElasticMultigrid(const Material &material)
    : material(material)
  {
  }

  template <int dim>
  ElasticMultigrid<dim>::~ElasticMultigrid()
  {
    clear();
  }

  template <int dim>
  void
  ElasticMultigrid<dim>::clear()
  {
    preconditioner.reset();
    multigrid.reset();
    coarse.reset();
    direct.reset();
    coarse_matrix.clear();
    smoother.clear();
    mg_matrix.reset();
    transfer.clear();
    transfer_ready = false;
    max_eigenvalues.clear();
    applied.resize(0, 0);
    operators.resize(0, 0);
    constraints.resize(0, 0);
    dofs.clear();
    meshes.clear();
  }

  template <int dim>
  bool
  ElasticMultigrid<dim>::ready() const
  {
    return transfer_ready;
  }

  template <int dim>
  unsigned int
  ElasticMultigrid<dim>::n_levels() const
  {
    return operators.n_levels();
  }

  template <int dim>
  std::vector<types::global_dof_index>
  ElasticMultigrid<dim>::level_sizes() const
  {
    std::vector<types::global_dof_index> sizes;
    for (unsigned int level = operators.min_level();
         level <= operators.max_level();
         ++level)
      sizes.push_back(operators[level]->m());
    return sizes;
  }

  template <int dim>
  void
  ElasticMultigrid<dim>::setup(
    const Mapping<dim>                   &mapping,
    const std::shared_ptr<LevelOperator> &fine,
    const AffineConstraints<double>      &fine_constraints,
    const std::vector<std::pair<types::boundary_id, ComponentMask>> &dirichlet)
  {
    clear();
    const auto &fine_dofs = fine->get_dof_handler();
    meshes                = coarsening_sequence(fine_dofs.get_triangulation());
    // The finest is the fine operator's own mesh (a reference: dropped).
    meshes.back().reset();
    // Above degree 1, the level below the fine one is Q1 on the same mesh
    // (a p-step), and the coarser ones Q1 too.
    const bool          raised = fine_dofs.get_fe().degree > 1;
    const FESystem<dim> linear(FE_Q<dim>(1), dim);
    const auto         &level_fe = raised ? linear : fine_dofs.get_fe();
    const unsigned int  top      = meshes.size() - (raised ? 0 : 1);

    constraints.resize(0, top);
    operators.resize(0, top);
    for (unsigned int level = 0; level < top; ++level)
      {
        dofs.push_back(std::make_unique<DoFHandler<dim>>(
          meshes[level] ? *meshes[level] : fine_dofs.get_triangulation()));
        dofs.back()->distribute_dofs(level_fe);
        IndexSet relevant;
        DoFTools::extract_locally_relevant_dofs(*dofs.back(), relevant);
        auto &level_constraints = constraints[level];
        level_constraints.reinit(relevant);
        DoFTools::make_hanging_node_constraints(*dofs.back(),
                                                level_constraints);
        for (const auto &[id, mask] : dirichlet)
          VectorTools::interpolate_boundary_values(mapping,
                                                   *dofs.back(),
                                                   id,
                                                   Functions::ZeroFunction<dim>(
                                                     dim),
                                                   level_constraints,
                                                   mask);
        level_constraints.close();
        operators[level] = std::make_shared<LevelOperator>(material);
        operators[level]->reinit(mapping, *dofs.back(), level_constraints);
      }
    operators[top] = fine;
    applied.resize(0, top);
    for (unsigned int level = 0; level <= top; ++level)
      applied[level] = std::make_shared<SinglePrecisionLevel>(operators[level]);

    std::vector<const DoFHandler<dim> *>           level_dofs;
    std::vector<const AffineConstraints<double> *> level_constraints;
    for (unsigned int level = 0; level < top; ++level)
      {
        level_dofs.push_back(dofs[level].get());
        level_constraints.push_back(&constraints[level]);
      }
    level_dofs.push_back(&fine_dofs);
    level_constraints.push_back(&fine_constraints);
    transfer.reinit(level_dofs,
                    level_constraints,
                    [this](const unsigned int level, VectorType &vector) {
                      operators[level]->initialize_dof_vector(vector);
                    });
    transfer_ready = true;
  }

  template <int dim>
  void
  ElasticMultigrid<dim>::update(const VectorType                &diagonal,
                                const VectorType                &off_diagonal,
                                const AffineConstraints<double> &fine_contact)
  {
    const unsigned int     top   = operators.max_level();
    constexpr unsigned int n_off = dim == 2 ? 1 : 3;
    // Off-diagonal entry k of a block: components (0,1), (1,2), (0,2).
    constexpr unsigned int pairs[3][2] = {{0, 1}, {1, 2}, {0, 2}};

    // The previous step's multigrid, with its level vectors and smoothers'
    // vectors, goes before this step's level diagonals take their memory.
    preconditioner.reset();
    multigrid.reset();
    smoother.clear();
    coarse.reset();
    direct.reset();

    // Restricted from the fine vectors themselves, then level by level.
    VectorType finer_diagonal, finer_off;
    for (unsigned int level = top; level-- > 0;)
      {
        VectorType level_diagonal, level_off;
        operators[level]->initialize_dof_vector(level_diagonal);
        operators[level]->initialize_dof_vector(level_off);
        const bool from_fine = level + 1 == top;
        transfer.restrict_and_add(level + 1,
                                  level_diagonal,
                                  from_fine ? diagonal : finer_diagonal);
        transfer.restrict_and_add(level + 1,
                                  level_off,
                                  from_fine ? off_diagonal : finer_off);

        // The owned dofs come as whole vertices, dim at a time.
        std::vector<typename LevelOperator::NodalBlock> blocks;
        const auto &partitioner = *level_diagonal.get_partitioner();
        for (unsigned int i = 0; i + dim <= level_diagonal.locally_owned_size();
             i += dim)
          {
            typename LevelOperator::NodalBlock block{};
            bool                               any = false;
            for (unsigned int a = 0; a < dim; ++a)
              {
                block.dofs[a]         = partitioner.local_to_global(i + a);
                block.stiffness[a][a] = level_diagonal.local_element(i + a);
                any                   = any || block.stiffness[a][a] != 0.;
              }
            for (unsigned int k = 0; k < n_off; ++k)
              {
                const double value = level_off.local_element(i + k);
                block.stiffness[pairs[k][0]][pairs[k][1]] = value;
                block.stiffness[pairs[k][1]][pairs[k][0]] = value;
              }
            if (any)
              blocks.push_back(block);
          }
        operators[level]->set_contact({}, blocks);
        finer_diagonal.swap(level_diagonal);
        finer_off.swap(level_off);
      }

    // The coarsest level's factorisation; where it is the only level, the
    // fine one's with its contact's lines (without them a body held only
    // by the obstacle has a singular matrix).
    operators[0]->assemble_matrix(coarse_matrix,
                                  top == 0 ? &fine_contact : nullptr);
    direct = std::make_unique<TrilinosWrappers::SolverDirect>(coarse_control);
    try
      {
        direct->initialize(coarse_matrix);
      }
    catch (const ExceptionBase &)
      {
        throw SolverFailure(exit_status::linear_solver,
                            "multigrid failed: the coarsest level's matrix is "
                            "singular");
      }
    coarse = std::make_unique<DirectCoarseSolve<VectorType>>(*direct);

    MGLevelObject<typename Smoother::AdditionalData> data(0, top);
    for (unsigned int level = 0; level <= top; ++level)
      {
        data[level].preconditioner =
          std::make_shared<DiagonalMatrix<VectorType>>();
        data[level].preconditioner->get_vector() =
          operators[level]->inverse_diagonal();
        data[level].degree          = chebyshev_degree;
        data[level].smoothing_range = smoothing_range;
        // Estimated at the first update of these levels; later ones (a
        // Newton step's contact, which changes a few nodes' rows of D^-1 A
        // but not its range) reuse the estimate.
        data[level].eig_cg_n_iterations =
          max_eigenvalues.empty() ? eigenvalue_cg_steps : 0;
        data[level].max_eigenvalue =
          max_eigenvalues.empty() ? 1. : max_eigenvalues[level];
      }
    smoother.initialize(applied, data);
    if (max_eigenvalues.empty())
      {
        // Levels 1 to top smooth (0 is solved directly).
        max_eigenvalues.assign(top + 1, 1.);
        for (unsigned int level = 1; level <= top; ++level)
          {
            VectorType layout;
            operators[level]->initialize_dof_vector(layout);
            max_eigenvalues[level] = smoother.smoothers[level]
                                       .estimate_eigenvalues(layout)
                                       .max_eigenvalue_estimate;
          }
      }
    mg_matrix.initialize(applied);
    multigrid = std::make_unique<Multigrid<VectorType>>(
      mg_matrix, *coarse, transfer, smoother, smoother);
    preconditioner =
      std::make_unique<PreconditionMG<dim, VectorType, LevelTransfer<dim>>>(
        operators[top]->get_dof_handler(), *multigrid, transfer);
  }

  template <int dim>
  void
  ElasticMultigrid<dim>::vmult(VectorType &dst, const VectorType &src) const
  {
    preconditioner->vmult(dst, src);
  }

  template class ElasticMultigrid<2>;
  template class ElasticMultigrid<3>;
} // namespace signorini
