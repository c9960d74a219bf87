// Each contact formulation (active set, penalty, augmented Lagrangian, none) on
// a plane-strain block whose answer is known, solved through the rooms as
// ContactProblem wires them, without the problem class: Discretisation,
// Loads, AssembledOperator, HeightObstacle, ContactSurface, the formulation of
// create_contact_formulation with the frictionless law, and the NewtonDriver.
//
// E = 1000, nu = 0.25, the unit square in 4 x 4 Q1 cells, x held on the left
// side (id 0), no body force. With sigma_xx = 0 and a uniform sigma_yy = s
// the displacement is linear, which Q1 reproduces exactly:
//   u_x = -nu (1 + nu) s / E x,  u_y = (1 - nu^2) s / E y + u_y(0).
//
// A. Resting block: traction (0, -t) on the top (id 3), the obstacle y = 0
//    under the bottom (id 2), nothing else holds it up. s = -t, the contact
//    pressure is t at every node; the bottom sits on the obstacle (active
//    set), sinks by epsilon t into the penalty's Winkler layer, or by nothing
//    once the augmented Lagrangian's multipliers have converged.
// B. Hanging block: y held on the top (id 3), traction (0, -t) on the bottom
//    pulls it down towards the obstacle y = -g. Free, the bottom would fall
//    by d = (1 - nu^2) t / E; with g < d contact closes: s = t - p with
//    p = t - E' g (E' = E / (1 - nu^2)) where the bottom reaches the
//    obstacle (active set, augmented Lagrangian), p = (t - E' g) / (1 + E'
//    epsilon) with the penalty; `none` lets it fall through (p = 0).

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/timer.h>

#include <signorini/base/failures.h>
#include <signorini/base/statistics_row.h>
#include <signorini/contact/contact_formulation.h>
#include <signorini/contact/contact_law.h>
#include <signorini/contact/contact_surface.h>
#include <signorini/contact/newton_driver.h>
#include <signorini/contact/obstacle_set.h>
#include <signorini/discretisation/discretisation.h>
#include <signorini/elasticity/assembled_operator.h>
#include <signorini/elasticity/loads.h>
#include <signorini/mesh_adaptation/mesh_adaptation_factory.h>
#include <signorini/problem/parameters.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <iostream>
#include <memory>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string>

using namespace dealii;
using namespace signorini;

namespace
{
  constexpr double E  = 1000.;
  constexpr double nu = 0.25;
  constexpr double t  = 2.;

  /** @p x in full precision, for a parameter text. */
  std::string
  full_precision(const double x)
  {
    std::ostringstream s;
    s << std::setprecision(17) << x;
    return s.str();
  }

  /** @p x for printing: 0 if below round-off of @p scale (the reported
   * differences keep the round-off). */
  double
  shown(const double x, const double scale)
  {
    return std::abs(x) < 1e-12 * scale ? 0. : x;
  }

  void
  report(const std::string &what, const double difference, const double tol)
  {
    std::cout << "  " << what << ": " << std::scientific << std::setprecision(1)
              << difference << (difference <= tol ? "  (ok)" : "  (FAILED)")
              << std::defaultfloat << std::setprecision(10) << '\n';
  }

  /** The rooms of ContactProblem for one cycle on one mesh. */
  struct Scene
  {
    using VectorType = TrilinosWrappers::MPI::Vector;

    Parameters<2>                          parameters;
    ConditionalOStream                     pcout;
    TimerOutput                            timer;
    std::unique_ptr<Discretisation<2>>     discretisation;
    std::unique_ptr<Loads<2>>              loads;
    std::unique_ptr<ElasticOperator<2>>    elastic_operator;
    std::unique_ptr<ObstacleSet<2>>        obstacle;
    std::unique_ptr<ContactSurface<2>>     surface;
    std::unique_ptr<ContactLaw<2>>         law;
    std::unique_ptr<ContactFormulation<2>> formulation;
    VectorType                             solution;
    VectorType                             pressure;
    std::unique_ptr<NewtonDriver<2>>       newton;

    explicit Scene(const std::string &text)
      : pcout(std::cout, false)
      , timer(pcout, TimerOutput::never, TimerOutput::wall_times)
    {
      ParameterHandler prm;
      declare_parameters(prm, 2);
      prm.parse_input_from_string(text);
      parameters.parse_parameters(prm, {});
      const MPI_Comm comm = MPI_COMM_WORLD;
      discretisation      = std::make_unique<Discretisation<2>>(
        parameters.geometry,
        mesh_adaptation_factory(parameters.geometry,
                                parameters.refinement,
                                comm),
        parameters.boundary_conditions,
        comm);
      loads = std::make_unique<Loads<2>>(parameters.boundary_conditions,
                                         *discretisation);
      elastic_operator =
        std::make_unique<AssembledOperator<2>>(*discretisation,
                                               parameters.material,
                                               *loads,
                                               parameters.linear_solver,
                                               parameters.contact.remedies,
                                               pcout,
                                               timer);
      obstacle = create_obstacles(parameters.obstacle);
      surface =
        std::make_unique<ContactSurface<2>>(parameters.obstacle.contact_ids,
                                            *obstacle);
      law = create_contact_law<2>(parameters.contact,
                                  parameters.friction,
                                  parameters.obstacle);
      formulation =
        create_contact_formulation<2>(parameters.contact,
                                      parameters.material.young_modulus,
                                      pcout);
      newton = std::make_unique<NewtonDriver<2>>(*discretisation,
                                                 *elastic_operator,
                                                 *surface,
                                                 *law,
                                                 *formulation,
                                                 parameters.contact,
                                                 false,
                                                 solution,
                                                 pressure,
                                                 pcout,
                                                 timer);

      // run.cc: the grid; setup.cc: setup_system.
      std::set<types::boundary_id> dirichlet_ids;
      for (const auto &[id, mask] : parameters.boundary_conditions.dirichlet)
        dirichlet_ids.insert(id);
      discretisation->make_grid(
        {{"Boundary conditions/Dirichlet", dirichlet_ids},
         {"Boundary conditions/Traction boundary ids",
          parameters.boundary_conditions.traction_ids},
         {"Obstacle/Contact boundary ids", parameters.obstacle.contact_ids}});
      elastic_operator->reinit();
      solution.reinit(discretisation->locally_owned_dofs(),
                      discretisation->locally_relevant_dofs(),
                      comm);
      pressure.reinit(discretisation->locally_owned_dofs(),
                      discretisation->locally_relevant_dofs(),
                      comm);
      newton->reinit();
      surface->setup(*discretisation);
    }

    /** run.cc: ContactProblem::solve of cycle 0. */
    void
    solve()
    {
      elastic_operator->assemble_load();
      newton->start_cycle();
      formulation->solve(*newton, 0);
    }
  };

  /** What a scene's answer should be: the uniform stress sigma_yy = s, the
   * bottom's displacement, the contact pressure. */
  struct Expected
  {
    double s;
    double bottom;
    double pressure;
    /** Tolerances of the pressure (relative to t) and of the gap [mm]. */
    double pressure_tolerance = 1e-10;
    double gap_tolerance      = 1e-14;
    /** Of the displacement at the vertices [mm]. */
    double displacement_tolerance = 1e-14;
    /** Whether every contact node ends active (otherwise none). */
    bool all_active = true;
  };

  /** Solves @p scene and compares it with @p expected. */
  void
  check(const std::string &title, Scene &scene, const Expected &expected)
  {
    std::cout << title << '\n';
    try
      {
        scene.solve();
      }
    catch (const SolverFailure &failure)
      {
        std::cout << "  SolverFailure (FAILED): " << failure.what() << '\n';
        return;
      }

    const auto &nodes = scene.surface->nodes();
    const auto &u     = scene.solution;
    double gap_min = 1e300, gap_max = -1e300, p_min = 1e300, p_max = -1e300,
           force        = 0.;
    unsigned int active = 0;
    for (const auto &node : nodes)
      {
        const double gap = scene.surface->deformed_gap(node, u);
        const double p   = scene.pressure(node.scalar_dof);
        gap_min          = std::min(gap_min, gap);
        gap_max          = std::max(gap_max, gap);
        p_min            = std::min(p_min, p);
        p_max            = std::max(p_max, p);
        force += node.normal_displacement(scene.newton->residual());
        active += node.in_contact() ? 1 : 0;
      }
    StatisticsRow row;
    scene.formulation->report(row, scene.pcout);

    // The strategies' statistics columns: multiplier updates, epsilon.
    std::string columns;
    for (const std::string name : {"multiplier_updates", "penalty_parameter"})
      try
        {
          std::ostringstream value;
          value << std::setprecision(10) << row.value(name);
          columns += ", " + name + " " + value.str();
        }
      catch (const std::out_of_range &)
        {
        }
    std::cout << "  " << scene.formulation->name() << ": Newton iterations "
              << scene.newton->iterations() << columns << "; " << active
              << " of " << nodes.size() << " contact nodes active\n";
    report("|active nodes - expected|",
           std::abs(double(active) -
                    (expected.all_active ? double(nodes.size()) : 0.)),
           0.);
    // The obstacle is flat: the deformed gap is the bottom's displacement
    // less psi.
    const double expected_gap =
      expected.bottom -
      scene.parameters.obstacle.obstacles[0].height->value(Point<1>(0.));
    std::cout << "  deformed gap from " << shown(gap_min, 1e-3) << " to "
              << shown(gap_max, 1e-3) << ", expected " << expected_gap << '\n';
    report("max |deformed gap - expected|",
           std::max(std::abs(gap_min - expected_gap),
                    std::abs(gap_max - expected_gap)),
           expected.gap_tolerance);
    std::cout << "  nodal pressure from " << shown(p_min, t) << " to "
              << shown(p_max, t) << ", expected " << expected.pressure
              << "; contact force " << shown(force, t) << ", expected "
              << expected.pressure << " x 1\n";
    report("max |pressure - expected| / t",
           std::max(std::abs(p_min - expected.pressure),
                    std::abs(p_max - expected.pressure)) /
             t,
           expected.pressure_tolerance);
    report("|contact force - expected| / t",
           std::abs(force - expected.pressure) / t,
           expected.pressure_tolerance);

    // The displacement at every vertex against the linear closed form.
    const double a     = -nu * (1 + nu) * expected.s / E;
    const double b     = (1 - nu * nu) * expected.s / E;
    double       worst = 0.;
    Point<2>     corner;
    const auto  &dofs = scene.discretisation->dof_handler();
    for (const auto &cell : dofs.active_cell_iterators())
      for (const unsigned int v : cell->vertex_indices())
        {
          const Point<2> x = cell->vertex(v);
          worst =
            std::max(worst,
                     std::abs(u(cell->vertex_dof_index(v, 0)) - a * x[0]));
          worst = std::max(worst,
                           std::abs(u(cell->vertex_dof_index(v, 1)) -
                                    (b * x[1] + expected.bottom)));
          if (x[1] == 0. && x[0] == 1.)
            corner = Point<2>(u(cell->vertex_dof_index(v, 0)),
                              u(cell->vertex_dof_index(v, 1)));
        }
    std::cout << "  u(1, 0) = (" << shown(corner[0], 1e-3) << ", "
              << shown(corner[1], 1e-3) << "), expected (" << a << ", "
              << expected.bottom << ")\n";
    report("max |u - closed form| at the vertices",
           worst,
           expected.displacement_tolerance);
  }

  const std::string block = R"(
set Dimension = 2
subsection Geometry
  set Upper right corner = 1, 1
  set Subdivisions       = 4, 4
end
subsection Material
  set Young's modulus = 1000
  set Poisson's ratio = 0.25
end
)";

  /** Scene A with @p contact (lines of subsection Contact). */
  std::string
  resting(const std::string &contact)
  {
    return block + R"(
subsection Boundary conditions
  set Dirichlet             = 0: x
  set Traction boundary ids = 3
  set Traction              = 0; -2
end
subsection Obstacle
  set Height               = 0
  set Contact boundary ids = 2
end
subsection Contact
)" + contact +
           "\nend\n";
  }

  /** Scene B with the obstacle at y = -@p g. */
  std::string
  hanging(const double g, const std::string &contact)
  {
    return block + R"(
subsection Boundary conditions
  set Dirichlet             = 0: x; 3: y
  set Traction boundary ids = 2
  set Traction              = 0; -2
end
subsection Obstacle
  set Height               = )" +
           full_precision(-g) + R"(
  set Contact boundary ids = 2
end
subsection Contact
)" + contact +
           "\nend\n";
  }

  void
  resting_block()
  {
    std::cout << "A. resting block, t = " << t << ", obstacle y = 0\n";
    const double top = -(1 - nu * nu) * t / E;
    std::cout << "  closed form: p = t = " << t << ", u_y(top) = -t (1 - nu^2) "
              << "/ E = " << top << '\n';
    {
      Scene scene(resting("  set Method = active set"));
      check("active set:", scene, {-t, 0., t});
    }
    {
      const double epsilon = 1e-4;
      Scene        scene(resting("  set Method = penalty\n"
                                 "  set Penalty parameter = 1e-4"));
      check("penalty, epsilon = 1e-4 (penetration epsilon t = 2e-4):",
            scene,
            {-t, -epsilon * t, t, 1e-10, 1e-15});
    }
    {
      // Automatic: epsilon = 0.1 h_min / E, h_min the cell diagonal.
      const double epsilon = 0.1 * std::sqrt(2.) / 4 / E;
      Scene        scene(resting("  set Method = penalty"));
      std::cout << "  (automatic epsilon 0.1 h_min / E = " << epsilon << ")\n";
      check("penalty, automatic epsilon:",
            scene,
            {-t, -epsilon * t, t, 1e-10, 1e-15});
    }
    {
      // The pressure does not depend on the multiplier: the first update
      // finds it, the second one confirms it, and the penetration is gone.
      const double epsilon = 1e-4;
      Scene        scene(resting("  set Method = augmented lagrangian\n"
                                 "  set Penalty parameter = 1e-4"));
      check("augmented lagrangian, epsilon = 1e-4 (penetration below "
            "multiplier tolerance x epsilon x t):",
            scene,
            {-t, 0., t, 1e-10, 1e-8 * epsilon * t});
    }
  }

  void
  hanging_block()
  {
    const double Eprime = E / (1 - nu * nu);
    const double d      = t / Eprime;
    std::cout << "B. hanging block, t = " << t << ", free fall d = (1 - nu^2) "
              << "t / E = " << d << '\n';
    {
      // The obstacle at y = -d / 2 is ignored: the bottom falls through.
      Scene scene(hanging(d / 2, "  set Method = none"));
      check("none, obstacle at y = -d/2 (the bottom ends at -d, p = 0):",
            scene,
            {t, -d, 0., 1e-12, 1e-15, 1e-14, false});
    }
    const double g = 1e-3;
    const double p = t - Eprime * g;
    std::cout << "  obstacle at y = -g, g = " << g
              << " < d: p = t - E' g = " << p << '\n';
    {
      Scene scene(hanging(g, "  set Method = active set"));
      check("active set:", scene, {t - p, -g, p, 1e-10, 1e-15});
    }
    {
      const double epsilon = 1e-4;
      const double pp      = p / (1 + Eprime * epsilon);
      Scene        scene(hanging(g,
                          "  set Method = penalty\n"
                                 "  set Penalty parameter = 1e-4"));
      std::cout << "  (penalty: p = (t - E' g) / (1 + E' epsilon) = " << pp
                << ")\n";
      check("penalty, epsilon = 1e-4:",
            scene,
            {t - pp, -g - epsilon * pp, pp, 1e-10, 1e-15});
    }
    {
      const double epsilon = 1e-4;
      Scene        scene(hanging(g,
                          "  set Method = augmented lagrangian\n"
                                 "  set Penalty parameter = 1e-4"));
      // The multipliers converge by E' epsilon / (1 + E' epsilon) per update:
      // the last change (relative, at most the tolerance 1e-8) bounds the
      // pressure's error, that times epsilon p the penetration.
      check("augmented lagrangian, epsilon = 1e-4:",
            scene,
            {t - p, -g, p, 2e-8, 2e-8 * epsilon * p, 1e-10});
    }
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  std::cout << std::setprecision(10);
  resting_block();
  hanging_block();
}
