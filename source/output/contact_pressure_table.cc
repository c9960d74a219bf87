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
    std::vector<std::array<double, dim + 1>> rows;
    for (const auto &node : surface.nodes())
      if (node.owned)
        {
          std::array<double, dim + 1> row;
          unsigned int                column = 0;
          for (; column < dim - 1; ++column)
            row[column] = node.position[column];
          row[column++] = pressure(node.scalar_dof);
          row[column]   = surface.deformed_gap(node, solution);
          rows.push_back(row);
        }
    const auto gathered = Utilities::MPI::gather(mpi_communicator, rows);
    if (Utilities::MPI::this_mpi_process(mpi_communicator) != 0)
      return;
    std::vector<std::array<double, dim + 1>> all;
    for (const auto &part : gathered)
      all.insert(all.end(), part.begin(), part.end());
    std::sort(all.begin(), all.end());

    write_atomically(file, [&](std::ostream &out) {
      out << (dim == 2 ? "x" : "x,y") << ",pressure,gap\n";
      char number[32];
      for (const auto &row : all)
        {
          for (unsigned int c = 0; c <= dim; ++c)
            {
              std::snprintf(number, sizeof(number), "%.10e", row[c]);
              out << (c > 0 ? "," : "") << number;
            }
          out << '\n';
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
