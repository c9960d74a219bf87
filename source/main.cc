#include <deal.II/base/mpi.h>

#include <signorini/program.h>

int
main(int argc, char **argv)
{
  // Threads: as many as there are cores per process (one process on two
  // cores estimates errors and builds output patches on both).
  dealii::Utilities::MPI::MPI_InitFinalize mpi(
    argc, argv, dealii::numbers::invalid_unsigned_int);
  return signorini::run_program(argc, argv);
}
