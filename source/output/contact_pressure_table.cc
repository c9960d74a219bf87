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
                               const MPI_Comm mpi_communicator)
  {
    // x, y[, z], pressure, gap, obstacle: a node at a corner has one row
    // per obstacle it touches.
    using Row = std::array<double, dim + 3>;
    std::vector<Row> rows;
    for (const auto &node : surface.nodes())
      if (node.owned)
        {
          Row row;
          for (unsigned int d = 0; d < dim; ++d)
            row[d] = node.position[d];
          row[dim]     = pressure(node.scalar_dof);
          row[dim + 1] = surface.deformed_gap(node, solution);
          row[dim + 2] = surface.obstacles().number(node.obstacle);
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
      out << (dim == 2 ? "x,y" : "x,y,z") << ",pressure,gap,obstacle\n";
      char number[32];
      for (const auto &row : all)
        {
          for (unsigned int c = 0; c < dim + 2; ++c)
            {
              std::snprintf(number, sizeof(number), "%.10e,", row[c]);
              out << number;
            }
          out << static_cast<unsigned int>(row[dim + 2]) << '\n';
        }
    });
  }

  template void
  write_contact_pressure_table(const std::string &,
                               const ContactSurface<2> &,
                               const TrilinosWrappers::MPI::Vector &,
                               const TrilinosWrappers::MPI::Vector &,
                               const MPI_Comm);
  template void
  write_contact_pressure_table(const std::string &,
                               const ContactSurface<3> &,
                               const TrilinosWrappers::MPI::Vector &,
                               const TrilinosWrappers::MPI::Vector &,
                               const MPI_Comm);
} // namespace signorini
