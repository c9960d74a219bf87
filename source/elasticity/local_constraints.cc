#include <deal.II/base/mpi.h>

#include <signorini/elasticity/local_constraints.h>

namespace signorini
{
  using namespace dealii;

  void
  LocalConstraints::reinit(
    const AffineConstraints<double>                          &given,
    const std::shared_ptr<const Utilities::MPI::Partitioner> &partitioner)
  {
    clear();
    constraints       = &given;
    this->partitioner = partitioner;
    const auto &owned = partitioner->locally_owned_range();
    bool        local = true;
    for (const auto &line : given.get_lines())
      if (owned.is_element(line.index))
        {
          Line mine;
          mine.index         = partitioner->global_to_local(line.index);
          mine.inhomogeneity = line.inhomogeneity;
          mine.begin         = entries.size();
          for (const auto &[master, weight] : line.entries)
            {
              if (!partitioner->in_local_range(master) &&
                  !partitioner->is_ghost_entry(master))
                {
                  local = false;
                  break;
                }
              entries.emplace_back(partitioner->global_to_local(master),
                                   weight);
            }
          mine.end = entries.size();
          lines.push_back(mine);
          if (!local)
            break;
        }
    general =
      Utilities::MPI::logical_or(!local, partitioner->get_mpi_communicator());
    if (general)
      {
        lines.clear();
        entries.clear();
      }
  }

  void
  LocalConstraints::distribute(VectorType &vector) const
  {
    Assert(constraints && vector.get_partitioner()->is_compatible(*partitioner),
           ExcMessage("a vector of another partitioner"));
    const bool had_ghosts = vector.has_ghost_elements();
    if (general)
      {
        // deal.II's compresses, which a vector with ghost values forbids.
        vector.zero_out_ghost_values();
        constraints->distribute(vector);
        if (had_ghosts)
          vector.update_ghost_values();
        return;
      }
    if (!had_ghosts)
      vector.update_ghost_values();
    for (const auto &line : lines)
      {
        double value = line.inhomogeneity;
        for (unsigned int k = line.begin; k < line.end; ++k)
          value += entries[k].second * vector.local_element(entries[k].first);
        vector.local_element(line.index) = value;
      }
    // Another process's ghost copies of the entries just set are stale.
    vector.zero_out_ghost_values();
    if (had_ghosts)
      vector.update_ghost_values();
  }

  void
  LocalConstraints::clear()
  {
    constraints = nullptr;
    partitioner.reset();
    lines.clear();
    entries.clear();
    general = false;
  }
} // namespace signorini
