// The TEST_TARGET of the .prm tests: `run_case FILE.prm` runs
// run_case.sh (program output, exit status, statistics, checks). Under mpirun
// it becomes `signorini FILE.prm` itself, so that MPI variants diff the
// program's own output.
#include <cstdio>
#include <cstdlib>
#include <unistd.h>

int
main(int argc, char **argv)
{
  if (argc != 2)
    {
      std::fprintf(stderr, "usage: run_case FILE.prm\n");
      return 2;
    }
  if (std::getenv("OMPI_COMM_WORLD_SIZE") != nullptr)
    execl(SIGNORINI, SIGNORINI, argv[1], static_cast<char *>(nullptr));
  else
    execl("/bin/sh",
          "sh",
          RUN_CASE,
          SIGNORINI,
          argv[1],
          static_cast<char *>(nullptr));
  std::perror("run_case");
  return 127;
}
