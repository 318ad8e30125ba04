// The dvpr command: see README.md and ../shared/DESIGN.md section 6.
#include <iostream>
#include <string_view>

#include "dvpr/version.h"

namespace {

constexpr std::string_view kUsage = R"(dvpr: discrete-event simulator of decentralized visual place recognition

Usage:
  dvpr --help        this text
  dvpr --version     the version

Subcommands arrive with their issues (run, plot, agent, launch).
)";

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) {
    std::cerr << kUsage;
    return 2;
  }
  const std::string_view arg = argv[1];
  if (arg == "--help" || arg == "-h" || arg == "help") {
    std::cout << kUsage;
    return 0;
  }
  if (arg == "--version") {
    std::cout << "dvpr " << dvpr::kVersion << "\n";
    return 0;
  }
  std::cerr << "dvpr: unknown command '" << arg << "' (see dvpr --help)\n";
  return 2;
}
