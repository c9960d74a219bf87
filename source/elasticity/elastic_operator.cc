#include <signorini/elasticity/assembled_operator.h>
#include <signorini/elasticity/automatic_operator.h>
#include <signorini/elasticity/matrix_free_operator.h>

namespace signorini
{
  using namespace dealii;

  template <int dim>
  std::unique_ptr<ElasticOperator<dim>>
  create_elastic_operator(const Discretisation<dim>     &discretisation,
                          const Material                &material,
                          const BoundaryConditions<dim> &boundary_conditions,
                          Loads<dim>                    &loads,
                          const LinearSolverParameters  &parameters,
                          const bool                     remedies,
                          const bool                     verbose,
                          ConditionalOStream            &pcout,
                          TimerOutput                   &timer)
  {
    const auto make =
      [&, remedies, verbose](
        const bool matrix_free) -> std::unique_ptr<ElasticOperator<dim>> {
      if (matrix_free)
        return std::make_unique<MatrixFreeOperator<dim>>(discretisation,
                                                         material,
                                                         boundary_conditions,
                                                         loads,
                                                         parameters,
                                                         remedies,
                                                         verbose,
                                                         pcout,
                                                         timer);
      return std::make_unique<AssembledOperator<dim>>(
        discretisation, material, loads, parameters, remedies, pcout, timer);
    };
    switch (parameters.type)
      {
        case LinearSolverParameters::Type::matrix_free:
          return make(true);
        case LinearSolverParameters::Type::automatic:
          return std::make_unique<AutomaticOperator<dim>>(
            discretisation,
            !material.axisymmetric() &&
              !material.template mean_dilatation<dim>(false),
            make);
        default:
          return make(false);
      }
  }

  template std::unique_ptr<ElasticOperator<2>>
  create_elastic_operator(const Discretisation<2> &,
                          const Material &,
                          const BoundaryConditions<2> &,
                          Loads<2> &,
                          const LinearSolverParameters &,
                          bool,
                          bool,
                          ConditionalOStream &,
                          TimerOutput &);
  template std::unique_ptr<ElasticOperator<3>>
  create_elastic_operator(const Discretisation<3> &,
                          const Material &,
                          const BoundaryConditions<3> &,
                          Loads<3> &,
                          const LinearSolverParameters &,
                          bool,
                          bool,
                          ConditionalOStream &,
                          TimerOutput &);
} // namespace signorini
