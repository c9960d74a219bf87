#ifndef signorini_base_mpi_session_h
#define signorini_base_mpi_session_h

namespace signorini
{
  /**
   * Gives a run started without mpiexec (a singleton) an Open MPI session
   * folder of its own, before MPI_Init. Open MPI (4.1) keeps each run's
   * session directory in ompi.HOST.UID under the temporary folder, shared
   * by all runs of the user and removed by a run that ends once it is
   * empty: a run starting at that moment stopped in MPI_Init ("A call to
   * mkdir was unable to create the desired directory ... File exists",
   * "orte_init failed"), as in a parameter sweep of simultaneous runs. The
   * folder, TMPDIR/signorini-XXXXXX, is removed at exit. Nothing is done
   * under mpiexec (its folder exists before the program starts: give
   * simultaneous mpiexec runs different TMPDIRs) or where the user set
   * OMPI_MCA_orte_tmpdir_base.
   */
  void
  use_private_mpi_session_folder();
} // namespace signorini

#endif
