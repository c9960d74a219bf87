#ifndef signorini_elasticity_local_constraints_h
#define signorini_elasticity_local_constraints_h

#include <deal.II/base/partitioner.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/la_parallel_vector.h>

#include <memory>
#include <utility>
#include <vector>

namespace signorini
{
  /**
   * AffineConstraints::distribute() for the vectors of one partitioner (the
   * fine matrix-free operator's), by local indices. deal.II's distribute()
   * of a parallel vector builds a vector with the masters as ghosts on
   * every call (for a Trilinos vector an Epetra import, 45 ms a call at
   * 1.5 M dofs); here the owned constraint lines are translated once, and a
   * call is one ghost exchange and a loop. If some master of an owned line
   * is neither owned nor a ghost of the partitioner, distribute() falls
   * back to deal.II's.
   */
  class LocalConstraints
  {
  public:
    using VectorType = dealii::LinearAlgebra::distributed::Vector<double>;

    /** The owned lines of @p constraints (closed) in the local indices of
     * @p partitioner; @p constraints must outlive this object. */
    void
    reinit(const dealii::AffineConstraints<double> &constraints,
           const std::shared_ptr<const dealii::Utilities::MPI::Partitioner>
             &partitioner);

    /** Sets each owned constrained entry of @p vector (of the partitioner)
     * to its inhomogeneity plus the weighted masters' entries; its ghost
     * entries are up to date afterwards if they were before. Collective. */
    void
    distribute(VectorType &vector) const;

    /** Whether some master was not local on some process, so that
     * distribute() is deal.II's. */
    bool
    falls_back() const
    {
      return general;
    }

    /** Forgets the lines. */
    void
    clear();

  private:
    struct Line
    {
      unsigned int index;
      double       inhomogeneity;
      /** The range of this line's masters in `entries`. */
      unsigned int begin, end;
    };
    const dealii::AffineConstraints<double> *constraints = nullptr;
    std::shared_ptr<const dealii::Utilities::MPI::Partitioner> partitioner;
    std::vector<Line>                                          lines;
    std::vector<std::pair<unsigned int, double>>               entries;
    /** Some master is not local: deal.II's distribute(). */
    bool general = false;
  };
} // namespace signorini

#endif
