#include <signorini/contact/height_obstacle.h>
#include <signorini/contact/obstacle_set.h>

#include <limits>

namespace signorini
{
  using namespace dealii;

  template <int dim>
  void
  ObstacleSet<dim>::add(std::unique_ptr<Obstacle<dim>> obstacle,
                        const TimeVector<dim>         &displacement,
                        const unsigned int             number,
                        const bool                     may_start_inside)
  {
    numbers.push_back(number > 0 ? number : obstacles.size() + 1);
    obstacles.push_back(std::move(obstacle));
    histories.push_back(displacement);
    // A displacement of t is set by set_time().
    displacements.push_back(displacement.depends_on_time() ?
                              Tensor<1, dim>() :
                              displacement.value(0.));
    may_start_inside_flags.push_back(may_start_inside);
  }

  template <int dim>
  void
  ObstacleSet<dim>::set_time(const double t)
  {
    for (unsigned int k = 0; k < obstacles.size(); ++k)
      displacements[k] = histories[k].value(t);
  }

  template <int dim>
  const Tensor<1, dim> &
  ObstacleSet<dim>::displacement(const unsigned int k) const
  {
    return displacements[k];
  }

  template <int dim>
  unsigned int
  ObstacleSet<dim>::size() const
  {
    return obstacles.size();
  }

  template <int dim>
  unsigned int
  ObstacleSet<dim>::number(const unsigned int k) const
  {
    return numbers[k];
  }

  template <int dim>
  double
  ObstacleSet<dim>::gap(const unsigned int k,
                        const Point<dim>  &point,
                        Tensor<1, dim>    &normal) const
  {
    // The obstacle moved by d (zero too: a punch that does not move keeps
    // a point beyond its rim clear of it, as a moved one does).
    return obstacles[k]->moved_gap(point, displacements[k], normal);
  }

  template <int dim>
  double
  ObstacleSet<dim>::initial_gap(const unsigned int k,
                                const Point<dim>  &point) const
  {
    Tensor<1, dim> normal;
    return obstacles[k]->gap(point, normal);
  }

  template <int dim>
  bool
  ObstacleSet<dim>::may_start_inside(const unsigned int k) const
  {
    return may_start_inside_flags[k];
  }

  template <int dim>
  bool
  ObstacleSet<dim>::single_height() const
  {
    return obstacles.size() == 1 &&
           dynamic_cast<const HeightObstacle<dim> *>(obstacles[0].get());
  }

  template <int dim>
  const Obstacle<dim> &
  ObstacleSet<dim>::operator[](const unsigned int k) const
  {
    return *obstacles[k];
  }

  template <int dim>
  unsigned int
  ObstacleSet<dim>::nearest(const Point<dim> &point) const
  {
    unsigned int   k_min = 0;
    double         g_min = 0.;
    Tensor<1, dim> normal;
    for (unsigned int k = 0; k < obstacles.size(); ++k)
      {
        const double g = gap(k, point, normal);
        if (k == 0 || g < g_min)
          {
            g_min = g;
            k_min = k;
          }
      }
    return k_min;
  }

  template <int dim>
  unsigned int
  ObstacleSet<dim>::facing(const Point<dim>     &point,
                           const Tensor<1, dim> &boundary_normal) const
  {
    unsigned int best           = 0;
    double       best_alignment = 0., best_gap = 0.;
    for (unsigned int k = 0; k < obstacles.size(); ++k)
      {
        Tensor<1, dim> normal;
        const double   g         = gap(k, point, normal);
        const double   alignment = -(boundary_normal * normal);
        if (k == 0 || alignment > best_alignment + 1e-12 ||
            (alignment > best_alignment - 1e-12 && g < best_gap))
          {
            best           = k;
            best_alignment = alignment;
            best_gap       = g;
          }
      }
    return best;
  }

  template <int dim>
  double
  ObstacleSet<dim>::gap(const Point<dim> &point, Tensor<1, dim> &normal) const
  {
    double nearest = std::numeric_limits<double>::quiet_NaN();
    for (unsigned int k = 0; k < obstacles.size(); ++k)
      {
        Tensor<1, dim> n;
        const double   g = gap(k, point, n);
        if (k == 0 || g < nearest)
          {
            nearest = g;
            normal  = n;
          }
      }
    return nearest;
  }

  template <int dim>
  std::string
  ObstacleSet<dim>::entry() const
  {
    std::string entries;
    for (const auto &obstacle : obstacles)
      entries += (entries.empty() ? "" : ", ") + obstacle->entry();
    return entries;
  }

  template <int dim>
  SurfaceMesh<dim>
  ObstacleSet<dim>::moved_surface(const unsigned int      k,
                                  const BoundingBox<dim> &box) const
  {
    auto moved_box = box;
    moved_box.get_boundary_points().first -= displacements[k];
    moved_box.get_boundary_points().second -= displacements[k];
    auto mesh = obstacles[k]->surface(moved_box);
    for (auto &p : mesh.points)
      p += displacements[k];
    return mesh;
  }

  template <int dim>
  SurfaceMesh<dim>
  ObstacleSet<dim>::surface(const BoundingBox<dim> &box) const
  {
    SurfaceMesh<dim> all;
    for (unsigned int k = 0; k < obstacles.size(); ++k)
      {
        const auto         mesh  = moved_surface(k, box);
        const unsigned int first = all.points.size();
        all.points.insert(all.points.end(),
                          mesh.points.begin(),
                          mesh.points.end());
        for (auto cell : mesh.cells)
          {
            for (auto &v : cell)
              v += first;
            all.cells.push_back(cell);
          }
      }
    return all;
  }

  template <int dim>
  const std::vector<unsigned int> &
  ObstacleSet<dim>::obstacle_numbers() const
  {
    return numbers;
  }

  template <int dim>
  std::unique_ptr<ObstacleSet<dim>>
  create_obstacles(const ObstacleParameters<dim> &parameters)
  {
    auto set = std::make_unique<ObstacleSet<dim>>();
    for (const auto &description : parameters.obstacles)
      set->add(create_obstacle(description),
               description.displacement,
               description.number,
               description.may_start_inside());
    return set;
  }

  template class ObstacleSet<2>;
  template class ObstacleSet<3>;
  template std::unique_ptr<ObstacleSet<2>>
  create_obstacles(const ObstacleParameters<2> &);
  template std::unique_ptr<ObstacleSet<3>>
  create_obstacles(const ObstacleParameters<3> &);
} // namespace signorini
