#include <deal.II/base/mpi.h>

#include <signorini/program.h>

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  return signorini::run_program(argc, argv);
}
