#include <deal.II/base/mpi.h>

#include <signorini/base/interruption.h>
#include <signorini/base/memory.h>
#include <signorini/base/mpi_session.h>
#include <signorini/program.h>

int
main(int argc, char **argv)
{
  signorini::tune_allocator();
  signorini::use_private_mpi_session_folder();
  signorini::start_isolated_singleton();
  // Threads: as many as there are cores per process (one process on two
  // cores estimates errors and builds output patches on both).
  dealii::Utilities::MPI::MPI_InitFinalize mpi(
    argc, argv, dealii::numbers::invalid_unsigned_int);
  // SIGINT and SIGTERM stop the run after its files are consistent.
  signorini::interruption::install();
  return signorini::run_program(argc, argv);
}
