#ifndef signorini_discretisation_axisymmetry_h
#define signorini_discretisation_axisymmetry_h

#include <deal.II/base/function.h>
#include <deal.II/base/index_set.h>
#include <deal.II/base/numbers.h>
#include <deal.II/base/point.h>
#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/grid/tria.h>
#include <deal.II/lac/affine_constraints.h>

#include <signorini/discretisation/geometry.h>

#include <algorithm>
#include <cmath>
#include <set>
#include <string>

namespace signorini
{
  /**
   * The axisymmetric model (`Material/Plane state = axisymmetric`): a 2D
   * mesh in the (r, z) half-plane, x = r >= 0 and y = z, of a body of
   * revolution about the y axis, with loads and supports that do not depend
   * on the angle. The displacement is (u_r, u_z); the strain adds the hoop
   * strain u_r / r to the in-plane one, and the stress is the 3D law's. Every
   * integral over the mesh is one over the whole revolution: its measure is
   * 2 pi r dr dz (2 pi r ds on the boundary), so forces are those of the whole
   * body [N], pressures [MPa] and energies [N mm] as in 3D. Nodes on the axis
   * r = 0 move along it: their u_r = 0 is a constraint of the discretisation.
   */
  namespace axisymmetry
  {
    /** The weight 2 pi r of the measure at @p x [mm]: an integral over the
     * (r, z) plane times this weight is the integral over the revolved
     * body. */
    template <int dim>
    inline double
    weight(const dealii::Point<dim> &x)
    {
      return 2. * dealii::numbers::PI * x[0];
    }

    /** The hoop strain u_r / r at radius @p r of the displacement @p u_r,
     * whose derivative along r is @p du_r_dr; on the axis (|r| <= @p
     * axis_tolerance, where u_r = 0) its limit du_r / dr. */
    inline double
    hoop_strain(const double u_r,
                const double du_r_dr,
                const double r,
                const double axis_tolerance)
    {
      return std::abs(r) <= axis_tolerance ? du_r_dr : u_r / r;
    }

    /** The strain in the (r, z, theta) frame of the in-plane strain
     * @p in_plane (its (r, z) block) and the hoop strain @p hoop. */
    template <int dim>
    inline dealii::SymmetricTensor<2, 3>
    revolved_strain(const dealii::SymmetricTensor<2, dim> &in_plane,
                    const double                           hoop)
    {
      dealii::SymmetricTensor<2, 3> strain;
      for (unsigned int i = 0; i < 2; ++i)
        for (unsigned int j = i; j < 2; ++j)
          strain[i][j] = in_plane[i][j];
      strain[2][2] = hoop;
      return strain;
    }

    /** Vertices closer to the axis than this are on it: round-off in the
     * size @p body_size of the body [mm]. */
    inline double
    axis_tolerance(const double body_size)
    {
      return 1e-10 * body_size;
    }

    /**
     * Adds u_r = 0 at every vertex of @p dofs on the axis (|x| <= @p
     * tolerance) that is locally relevant (@p relevant_dofs) and not yet
     * constrained (hanging nodes, whose masters then hold it, and Dirichlet
     * data come first) to the open @p constraints.
     */
    template <int dim>
    void
    add_axis_constraints(const dealii::DoFHandler<dim>     &dofs,
                         const dealii::IndexSet            &relevant_dofs,
                         const double                       tolerance,
                         dealii::AffineConstraints<double> &constraints);

    /**
     * Throws an InputError naming the entry of @p geometry that places the
     * body if a vertex of @p coarse_mesh lies at r = x < -@p tolerance: an
     * axisymmetric body must lie on one side of its axis.
     */
    template <int dim>
    void
    check_side_of_axis(const dealii::Triangulation<dim> &coarse_mesh,
                       const Geometry<dim>              &geometry,
                       const double                      tolerance);

    /**
     * Throws an InputError naming @p entry if a boundary id of @p ids lies
     * on the axis (every vertex of its faces at |r| <= @p tolerance) in the
     * coarse cells of @p mesh: revolved, it has no area, and a traction
     * there would act on nothing.
     */
    template <int dim>
    void
    check_off_axis(const dealii::Triangulation<dim>           &mesh,
                   const std::set<dealii::types::boundary_id> &ids,
                   const std::string                          &entry,
                   const double                                tolerance);

    /**
     * The coefficient sqrt(2 pi r) of the Kelly estimator: the jumps of the
     * normal derivative are multiplied by it before they are squared and
     * integrated over the faces, so each face's share is weighted by 2 pi r
     * as every other integral of the model.
     */
    template <int dim>
    class KellyCoefficient : public dealii::Function<dim>
    {
    public:
      double
      value(const dealii::Point<dim> &x,
            const unsigned int /*component*/ = 0) const override
      {
        return std::sqrt(std::max(0., weight(x)));
      }
    };
  } // namespace axisymmetry
} // namespace signorini

#endif
