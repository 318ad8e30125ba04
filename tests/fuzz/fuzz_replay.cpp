// Replays inputs through a fuzz target's LLVMFuzzerTestOneInput, as libFuzzer would run them
// but once each and without libFuzzer: the corpus replay tests (ctest FuzzCorpusTest.<name>)
// run every committed seed and kept failing input of tests/fuzz/corpus/<name>/ in the sanitizer
// build. A broken property aborts (tests/fuzz/fuzz_support.h) and a sanitizer report stops the
// program, so either fails the test; it also fails when a folder holds no input at all.
//
// Usage: fuzz_<name>_replay FILE_OR_FOLDER...
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <memory>
#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size);

namespace {

namespace fs = std::filesystem;

std::vector<fs::path> InputsOf(const fs::path& arg) {
  if (!fs::is_directory(arg)) return {arg};
  std::vector<fs::path> files;
  for (const auto& entry : fs::directory_iterator(arg)) {
    if (entry.is_regular_file()) files.push_back(entry.path());
  }
  std::sort(files.begin(), files.end());  // the same order on every machine
  return files;
}

}  // namespace

int main(int argc, char** argv) {
  std::size_t replayed = 0;
  for (int i = 1; i < argc; ++i) {
    const std::vector<fs::path> inputs = InputsOf(argv[i]);
    if (inputs.empty()) {
      std::fprintf(stderr, "fuzz replay: %s: no input\n", argv[i]);
      return 1;
    }
    for (const fs::path& input : inputs) {
      std::ifstream in(input, std::ios::binary);
      if (!in) {
        std::fprintf(stderr, "fuzz replay: %s: cannot read\n", input.c_str());
        return 1;
      }
      const std::vector<char> bytes{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
      // A heap block of exactly the input's size, so ASan sees a read past its end, as under
      // libFuzzer, which also passes a valid pointer for an empty input.
      const auto data = std::make_unique<std::uint8_t[]>(std::max<std::size_t>(bytes.size(), 1));
      std::copy(bytes.begin(), bytes.end(), data.get());
      LLVMFuzzerTestOneInput(data.get(), bytes.size());
      ++replayed;
    }
  }
  if (replayed == 0) {
    std::fprintf(stderr, "usage: fuzz_<name>_replay FILE_OR_FOLDER...\n");
    return 2;
  }
  std::printf("fuzz replay: %zu inputs, no failure\n", replayed);
  return 0;
}
