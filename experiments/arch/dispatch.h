#pragma once
// Run-time choice of the instruction set (cmake/DvprArch.cmake). A default build on x86-64 makes
// every executable twice: the generic one (any x86-64) and `<name>-x86-64-v3` beside it (AVX2,
// FMA, BMI2). The generic one calls ExecFastestVariant first thing in main(): on a CPU that runs
// x86-64-v3 it replaces itself with its fast sibling, so users get the fast code without
// choosing, and a CPU without AVX2 still runs dvpr. The environment variable DVPR_ARCH=generic
// keeps the generic code (to compare the two, or to rule the fast one out).
#include <string>
#include <string_view>

namespace dvpr {

// The instruction set this code was compiled for: "x86-64-v3", "x86-64", "aarch64", or
// "generic" for any other target.
std::string_view CompiledArch();

// Whether this CPU runs x86-64-v3 code (false on other architectures).
bool CpuRunsX86_64_V3();

struct VariantChoice {
  bool exec_fast = false;
  std::string warning;  // one line for stderr, or empty
};

// What the generic executable does, given the CPU, whether its fast sibling is there, and the
// value of DVPR_ARCH (null when unset). "generic" keeps the generic code; unset, "" and "auto"
// take the fast code when the CPU runs it; any other value is warned about and read as "auto".
VariantChoice ChooseVariant(bool cpu_runs_fast, bool fast_exists, const char* env_arch);

// Replaces this process by `fast_name`, a file in the directory of /proc/self/exe, with the same
// argv and environment, when ChooseVariant says so; returns when it does not (or when exec
// fails, after one line on stderr).
void ExecFastestVariant(char** argv, const char* fast_name);

}  // namespace dvpr
