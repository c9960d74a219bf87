// An LD_AUDIT module that makes a program see an older x86-64 processor, so
// that the suite can be run here as on an AVX2 machine (or one with SSE2
// only) without one:
//
//   LD_AUDIT=build/tests/libcpu_mask.so SIGNORINI_TEST_CPU=x86-64-v3 PROGRAM
//   (scripts/test does this when SIGNORINI_TEST_CPU is set)
//
// SIGNORINI_TEST_CPU = x86-64-v3 hides AVX-512 (AVX512F and every AVX-512
// extension), x86-64 also AVX, AVX2, FMA, F16C, BMI1 and BMI2. Everything
// that chooses code by CPUID then chooses as on such a processor: the copy of
// the cell kernels GCC's target_clones picks (libgcc's __cpu_indicator_init
// reads CPUID when the kernels' resolver runs, while the library is
// relocated), OpenBLAS's kernels (chosen when it is loaded), hwloc. The
// dynamic loader's own choices (glibc's string functions and libm's FMA
// variants, made before any audit module is loaded) stay those of this
// processor: on an AVX2 machine libm picks the same FMA variants.
//
// How: the kernel's CPUID faulting (arch_prctl ARCH_SET_CPUID, x86 Linux
// on processors with `cpuid_fault`) makes every CPUID instruction raise
// SIGSEGV; the handler executes it with faulting off, clears the hidden
// feature bits and steps over the instruction. The loader calls la_version
// before it relocates the program and its libraries, so every ifunc
// resolver already sees the masked processor. Faulting is kept across fork
// and threads, not across exec: LD_AUDIT is in the environment, so every
// program started loads this module again, and masks the processor for the
// programs under test only (signorini, the unit tests): a program that
// replaces the SIGSEGV handler would die at its next CPUID (the compiler,
// Python do). Open MPI's handler is disabled by OMPI_MCA_opal_signal
// (scripts/test and run_as set it).
#include <asm/prctl.h>
#include <cpuid.h>
#include <cstdlib>
#include <cstring>
#include <link.h>
#include <signal.h>
#include <string>
#include <sys/syscall.h>
#include <ucontext.h>
#include <unistd.h>

namespace
{
  bool hide_avx2 = false;

  void
  say(const char *text)
  {
    if (write(2, text, std::strlen(text)) < 0)
      return;
  }

  void
  emulate_cpuid(int, siginfo_t *, void *context)
  {
    auto &registers = static_cast<ucontext_t *>(context)->uc_mcontext.gregs;
    const auto *instruction =
      reinterpret_cast<const unsigned char *>(registers[REG_RIP]);
    if (instruction[0] != 0x0f || instruction[1] != 0xa2)
      {
        // A real segmentation fault: die of it as without this module.
        signal(SIGSEGV, SIG_DFL);
        return;
      }
    const unsigned int leaf    = registers[REG_RAX];
    const unsigned int subleaf = registers[REG_RCX];
    unsigned int       a, b, c, d;
    syscall(SYS_arch_prctl, ARCH_SET_CPUID, 1);
    __cpuid_count(leaf, subleaf, a, b, c, d);
    syscall(SYS_arch_prctl, ARCH_SET_CPUID, 0);
    if (leaf == 7 && subleaf == 0)
      {
        // AVX512F, DQ, IFMA, PF, ER, CD, BW, VL; VBMI, VBMI2, VNNI, BITALG,
        // VPOPCNTDQ; 4VNNIW, 4FMAPS, VP2INTERSECT, FP16.
        b &= ~(1u << 16 | 1u << 17 | 1u << 21 | 1u << 26 | 1u << 27 | 1u << 28 |
               1u << 30 | 1u << 31);
        c &= ~(1u << 1 | 1u << 6 | 1u << 11 | 1u << 12 | 1u << 14);
        d &= ~(1u << 2 | 1u << 3 | 1u << 8 | 1u << 23);
        if (hide_avx2) // BMI1, AVX2, BMI2
          b &= ~(1u << 3 | 1u << 5 | 1u << 8);
      }
    if (leaf == 7 && subleaf == 1) // AVX512_BF16
      a &= ~(1u << 5);
    if (leaf == 1 && hide_avx2) // FMA, AVX, F16C
      c &= ~(1u << 12 | 1u << 28 | 1u << 29);
    registers[REG_RAX] = a;
    registers[REG_RBX] = b;
    registers[REG_RCX] = c;
    registers[REG_RDX] = d;
    registers[REG_RIP] += 2;
  }
} // namespace

extern "C" unsigned int
la_version(unsigned int)
{
  const char *cpu = std::getenv("SIGNORINI_TEST_CPU");
  if (cpu == nullptr || std::strcmp(cpu, "x86-64-v4") == 0)
    return LAV_CURRENT;
  // Only the programs under test see the older processor: signorini and the
  // unit tests (NAME.release, NAME.debug), and true (run_as asks it). The
  // compiler, Python, ParaView, ... install SIGSEGV handlers of their own.
  char        path[4096];
  const auto  length = readlink("/proc/self/exe", path, sizeof(path) - 1);
  std::string name(path, length > 0 ? length : 0);
  name            = name.substr(name.rfind('/') + 1);
  const auto ends = [&](const std::string &end) {
    return name.size() >= end.size() &&
           name.compare(name.size() - end.size(), end.size(), end) == 0;
  };
  if (name != "signorini" && name != "true" && !ends(".release") &&
      !ends(".debug"))
    return LAV_CURRENT;
  if (std::strcmp(cpu, "x86-64") == 0)
    hide_avx2 = true;
  else if (std::strcmp(cpu, "x86-64-v3") != 0)
    {
      say("cpu_mask: SIGNORINI_TEST_CPU is x86-64, x86-64-v3 or x86-64-v4\n");
      std::_Exit(2);
    }
  struct sigaction action;
  std::memset(&action, 0, sizeof(action));
  action.sa_sigaction = emulate_cpuid;
  action.sa_flags     = SA_SIGINFO | SA_NODEFER;
  sigaction(SIGSEGV, &action, nullptr);
  if (syscall(SYS_arch_prctl, ARCH_SET_CPUID, 0) != 0)
    {
      say("cpu_mask: this processor or kernel has no CPUID faulting\n");
      std::_Exit(2);
    }
  // (tests/processor/run_as asks, to know that the mask is in place.)
  if (std::getenv("SIGNORINI_TEST_CPU_SAY") != nullptr)
    say(hide_avx2 ? "cpu_mask: as on x86-64\n" : "cpu_mask: as on x86-64-v3\n");
  return LAV_CURRENT;
}
