// The TEST_TARGET of the .prm tests: `run_case FILE.prm` runs run_case.sh
// (program output, exit status, files, statistics, checks). The MPI
// variants (NAME.mpirun=N.output) run through the same driver: for them
// tests/CMakeLists.txt makes run_case deal.II's MPI launcher, so that deal.II
// calls `run_case --processes N run_case FILE.prm`, and run_case.sh starts
// `mpiexec -n N signorini FILE.prm` itself.
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <unistd.h>

int
main(int argc, char **argv)
{
  const char *processes = "1";
  const char *prm       = nullptr;
  if (argc == 2)
    prm = argv[1];
  else if (argc == 5 && std::strcmp(argv[1], "--processes") == 0)
    {
      processes = argv[2];
      prm       = argv[4];
    }
  else
    {
      std::fprintf(stderr,
                   "usage: run_case FILE.prm\n"
                   "       run_case --processes N run_case FILE.prm\n");
      return 2;
    }
  execl("/bin/sh",
        "sh",
        RUN_CASE,
        SIGNORINI,
        prm,
        processes,
        MPIEXEC,
        static_cast<char *>(nullptr));
  std::perror("run_case");
  return 127;
}
