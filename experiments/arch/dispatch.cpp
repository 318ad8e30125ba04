#include "experiments/arch/dispatch.h"

#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <iostream>
#include <system_error>

namespace dvpr {

std::string_view CompiledArch() {
  // The macros -march=x86-64-v3 defines (x86-64-v3 also has AVX, F16C, LZCNT, MOVBE).
#if defined(__x86_64__) && defined(__AVX2__) && defined(__FMA__) && defined(__BMI2__)
  return "x86-64-v3";
#elif defined(__x86_64__)
  return "x86-64";
#elif defined(__aarch64__)
  return "aarch64";
#else
  return "generic";
#endif
}

bool CpuRunsX86_64_V3() {
#if defined(__x86_64__) && defined(__GNUC__)
  __builtin_cpu_init();
  return __builtin_cpu_supports("x86-64-v3") != 0;
#else
  return false;
#endif
}

VariantChoice ChooseVariant(bool cpu_runs_fast, bool fast_exists, const char* env_arch) {
  VariantChoice c;
  const std::string_view env = env_arch == nullptr ? std::string_view() : std::string_view(env_arch);
  if (env == "generic") return c;
  if (!env.empty() && env != "auto") {
    c.warning = "dvpr: DVPR_ARCH=" + std::string(env) + " is not generic or auto; reading it as auto";
  }
  c.exec_fast = cpu_runs_fast && fast_exists;
  return c;
}

void ExecFastestVariant(char** argv, const char* fast_name) {
  std::error_code ec;
  const std::filesystem::path self = std::filesystem::read_symlink("/proc/self/exe", ec);
  if (ec) return;  // no /proc: stay generic
  const std::filesystem::path fast = self.parent_path() / fast_name;
  const bool exists = access(fast.c_str(), X_OK) == 0;
  const VariantChoice choice = ChooseVariant(CpuRunsX86_64_V3(), exists, std::getenv("DVPR_ARCH"));
  if (!choice.warning.empty()) std::cerr << choice.warning << "\n";
  if (!choice.exec_fast) return;
  execv(fast.c_str(), argv);
  std::cerr << "dvpr: could not run " << fast.string() << " (" << std::strerror(errno)
            << "); running the generic build\n";
}

}  // namespace dvpr
