// The YAML config reader as `dvpr run CONFIG --set key=value ...` drives it. The input is the
// config text; each of its lines that starts with "#%set " (a YAML comment, so the YAML reader
// skips it) is also passed as a `--set` argument. Properties (experiments/config/config.h):
// - a bad config throws ConfigError, nothing else (another exception escapes, and libFuzzer
//   reports it);
// - a config that loads is emitted and read back to an equal config.
#include <cstddef>
#include <cstdint>
#include <sstream>
#include <string_view>
#include <string>
#include <vector>

#include "experiments/config/config.h"
#include "tests/fuzz/fuzz_support.h"

namespace {

constexpr std::string_view kSetPrefix = "#%set ";

std::vector<std::string> SetArguments(const std::string& text) {
  std::vector<std::string> args;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) {
    if (line.starts_with(kSetPrefix)) args.push_back(line.substr(kSetPrefix.size()));
  }
  return args;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  const auto& base = dvpr::fuzz::Scratch().path();
  dvpr::ExperimentConfig config;
  try {
    std::vector<dvpr::ConfigOverride> overrides;
    for (const auto& arg : SetArguments(text)) overrides.push_back(dvpr::ParseOverride(arg));
    config = dvpr::ParseConfig(text, base, overrides, "fuzz.yaml");
  } catch (const dvpr::ConfigError&) {
    return 0;
  }
  const std::string emitted = dvpr::EmitConfig(config);
  try {
    if (!(dvpr::ParseConfig(emitted, base, {}, "emitted.yaml") == config)) {
      dvpr::fuzz::Violated("the emitted config reads back different:\n" + emitted);
    }
  } catch (const dvpr::ConfigError& e) {
    dvpr::fuzz::Violated(std::string("the emitted config does not read back: ") + e.what() + "\n" +
                         emitted);
  }
  return 0;
}
