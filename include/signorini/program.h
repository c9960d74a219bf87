#ifndef signorini_program_h
#define signorini_program_h

namespace signorini
{
  /**
   * The `signorini` command: `signorini [--resume] FILE.prm`, `signorini
   * --print-parameters [2|3]`, `signorini --help`. Reads the parameter file
   * and the files it includes once (ParameterFile), reads its `Dimension`,
   * declares the entries for that dimension, parses them and runs all
   * cycles. Every error is reported as one line on standard error; the
   * return value is the exit status (see failures.h). MPI must be
   * initialised by the caller.
   */
  int
  run_program(int argc, char **argv);
} // namespace signorini

#endif
