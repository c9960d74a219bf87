#include <deal.II/base/mpi.h>

#include <signorini/output/contact_pressure_table.h>
#include <signorini/output/file_output.h>

#include <algorithm>
#include <array>
#include <cstdio>
#include <vector>

namespace signorini
{
  using namespace dealii;

  template <int dim>
  void
  write_contact_pressure_table(const std::string                   &file,
                               const ContactSurface<dim>           &surface,
                               const TrilinosWrappers::MPI::Vector &pressure,
                               const TrilinosWrappers::MPI::Vector &solution,
                               const MPI_Comm mpi_communicator,
                               const TrilinosWrappers::MPI::Vector *tangential)
  {
    // x, y[, z], pressure, gap, obstacle, state, then the node's frame
    // (normal, tangents): a node at a corner has one row per obstacle it
    // touches; with friction, the shear traction and the slip of the load
    // step in the node's tangent coordinates.
    constexpr unsigned int frame    = dim + 4;
    constexpr unsigned int friction = frame + dim * dim;
    using Row                  = std::array<double, friction + 2 * (dim - 1)>;
    const unsigned int columns = tangential ? Row().size() : friction;
    std::vector<Row>   rows;
    for (const auto &node : surface.nodes())
      if (node.owned)
        {
          Row row = {};
          for (unsigned int d = 0; d < dim; ++d)
            row[d] = node.position[d];
          row[dim]     = pressure(node.scalar_dof);
          row[dim + 1] = surface.deformed_gap(node, solution);
          row[dim + 2] = surface.obstacles().number(node.obstacle);
          row[dim + 3] = static_cast<double>(node.state);
          for (unsigned int d = 0; d < dim; ++d)
            {
              // (+ 0.: no negative zeros in the table)
              row[frame + d] = node.normal[d] + 0.;
              for (unsigned int t = 0; t < dim - 1; ++t)
                row[frame + (t + 1) * dim + d] = node.tangents[t][d] + 0.;
            }
          if (tangential)
            {
              Tensor<1, dim> q;
              for (unsigned int d = 0; d < dim; ++d)
                q[d] = (*tangential)(node.dofs[d]);
              const auto slip = node.slip(solution);
              for (unsigned int t = 0; t < dim - 1; ++t)
                {
                  row[friction + t]           = q * node.tangents[t] + 0.;
                  row[friction + dim - 1 + t] = slip * node.tangents[t] + 0.;
                }
            }
          rows.push_back(row);
        }
    const auto gathered = Utilities::MPI::gather(mpi_communicator, rows);
    if (Utilities::MPI::this_mpi_process(mpi_communicator) != 0)
      return;
    std::vector<Row> all;
    for (const auto &part : gathered)
      all.insert(all.end(), part.begin(), part.end());
    std::sort(all.begin(), all.end());

    write_atomically(file, [&](std::ostream &out) {
      out << (dim == 2 ? "x,y" : "x,y,z") << ",pressure,gap,obstacle,state"
          << (dim == 2 ? ",n_x,n_y,t_x,t_y" :
                         ",n_x,n_y,n_z,t1_x,t1_y,t1_z,t2_x,t2_y,t2_z")
          << (!tangential ? "" :
              dim == 2    ? ",shear,slip" :
                            ",shear_t1,shear_t2,slip_t1,slip_t2")
          << '\n';
      char       number[32];
      const auto write = [&](const double value, const char separator) {
        std::snprintf(number, sizeof(number), "%.10e%c", value, separator);
        out << number;
      };
      for (const auto &row : all)
        {
          for (unsigned int c = 0; c < dim + 2; ++c)
            write(row[c], ',');
          out << static_cast<unsigned int>(row[dim + 2]) << ','
              << static_cast<unsigned int>(row[dim + 3]) << ',';
          for (unsigned int c = frame; c < columns; ++c)
            write(row[c], c + 1 < columns ? ',' : '\n');
        }
    });
  }

  template void
  write_contact_pressure_table(const std::string &,
                               const ContactSurface<2> &,
                               const TrilinosWrappers::MPI::Vector &,
                               const TrilinosWrappers::MPI::Vector &,
                               const MPI_Comm,
                               const TrilinosWrappers::MPI::Vector *);
  template void
  write_contact_pressure_table(const std::string &,
                               const ContactSurface<3> &,
                               const TrilinosWrappers::MPI::Vector &,
                               const TrilinosWrappers::MPI::Vector &,
                               const MPI_Comm,
                               const TrilinosWrappers::MPI::Vector *);
} // namespace signorini
