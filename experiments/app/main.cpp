// The dvpr command: see README.md and docs/design.md section 6. The subcommands live in
// experiments/app/cli.cpp.
#include <iostream>
#include <string>
#include <vector>

#include "experiments/app/cli.h"
#include "experiments/arch/dispatch.h"

int main(int argc, char** argv) {
#ifdef DVPR_FAST_EXECUTABLE
  dvpr::ExecFastestVariant(argv, DVPR_FAST_EXECUTABLE);  // returns when the generic code runs
#endif
  const std::vector<std::string> args(argv + 1, argv + argc);
  return dvpr::RunCli(args, std::cout, std::cerr);
}
