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

  /**
   * Starts a run without mpiexec (a singleton) as an isolated Open MPI
   * process, before MPI_Init: no runtime daemon, and only the
   * self-transport (ess_singleton_isolated = 1, pml = ob1, btl = self).
   * MPI_Init of a singleton took 0.32 s of a small run's 0.58 s, probing
   * for a daemon and for network transports one process never uses; it
   * takes 0.02 s so. Nothing is done under mpiexec, and an Open MPI
   * setting the user made (OMPI_MCA_...) is kept.
   */
  void
  start_isolated_singleton();
} // namespace signorini

#endif
