#include <signorini/discretisation/discretisation.h>
#include <signorini/elasticity/automatic_operator.h>

namespace signorini
{
  template <int dim>
  AutomaticOperator<dim>::AutomaticOperator(
    const Discretisation<dim> &discretisation,
    const bool                 pointwise,
    Factory                    make)
    : discretisation(discretisation)
    , pointwise(pointwise)
    , make(std::move(make))
  {
  }

  template <int dim>
  void
  AutomaticOperator<dim>::reinit()
  {
    if (!chosen)
      chosen = make(dim == 3 && !discretisation.simplex() && pointwise);
    chosen->reinit();
  }

  template <int dim>
  void
  AutomaticOperator<dim>::assemble_load()
  {
    chosen->assemble_load();
  }

  template <int dim>
  const typename AutomaticOperator<dim>::VectorType &
  AutomaticOperator<dim>::load() const
  {
    return chosen->load();
  }

  template <int dim>
  void
  AutomaticOperator<dim>::residual(const VectorType &u, VectorType &residual)
  {
    chosen->residual(u, residual);
  }

  template <int dim>
  void
  AutomaticOperator<dim>::solve(const ContactLinearisation<dim> &linearisation,
                                VectorType                      &u,
                                const bool                       final_step)
  {
    chosen->solve(linearisation, u, final_step);
  }

  template <int dim>
  void
  AutomaticOperator<dim>::invalidate()
  {
    if (chosen)
      chosen->invalidate();
  }

  template <int dim>
  void
  AutomaticOperator<dim>::release()
  {
    if (chosen)
      chosen->release();
  }

  template class AutomaticOperator<2>;
  template class AutomaticOperator<3>;
} // namespace signorini
