// Golden outputs: `dvpr run tests/golden/golden.yaml` must write exactly the
// files committed under tests/golden/expected/, byte for byte. They pin what
// the program computes while its code is reorganised; a change that must alter
// them on purpose regenerates them in a commit of its own that says why:
//
//   build/<kind>/dvpr run tests/golden/golden.yaml --quiet --out /tmp/golden
//   then copy /tmp/golden/* over tests/golden/expected/ (config.yaml with the
//   source tree's absolute path replaced by @SOURCE_DIR@, see below).
//
// The files were written by the sanitizer build that scripts/test.sh and CI use (RelWithDebInfo
// with -fsanitize=address,undefined). A build without the sanitizers computes some squared
// distances in queries.csv differently in their last bits (43 of them already showed in the 6th
// decimal when the files had 6; a -O0 build also 3 centroid values), so compare with that build.
// Numbers are in full precision (the shortest form that reads back to the same double) since
// issue 12; the files were regenerated then, differing from the 6-decimal ones in form only.
//
// config.yaml holds absolute paths (the resolved config), so the checkout's
// own path is replaced by @SOURCE_DIR@ before comparing; nothing else is.
#include <sys/wait.h>

#include <filesystem>
#include <set>
#include <string>

#include <gtest/gtest.h>

#include "tests/test_support.h"

namespace {

using dvpr::testing_support::RunProgram;
using dvpr::testing_support::Slurp;

namespace fs = std::filesystem;

std::string ReplaceAll(std::string text, const std::string& from, const std::string& to) {
  for (std::size_t pos = text.find(from); pos != std::string::npos; pos = text.find(from, pos + to.size())) {
    text.replace(pos, from.size(), to);
  }
  return text;
}

std::set<fs::path> FilesBelow(const fs::path& root) {
  std::set<fs::path> files;
  for (const auto& entry : fs::recursive_directory_iterator(root)) {
    if (entry.is_regular_file()) files.insert(fs::relative(entry.path(), root));
  }
  return files;
}

TEST(GoldenTest, OutputsEqualTheCommittedFilesByteForByte) {
  const fs::path source = DVPR_SOURCE_DIR;
  const fs::path expected = source / "tests/golden/expected";
  const fs::path out = fs::path(DVPR_TEST_TMP) / "golden";
  fs::remove_all(out);
  const fs::path log = fs::path(DVPR_TEST_TMP) / "golden.log";
  const int status = RunProgram({std::string(DVPR_BINARY_DIR) + "/dvpr", "run", (source / "tests/golden/golden.yaml").string(),
                                  "--quiet", "--out", out.string()},
                                 log);
  ASSERT_EQ(status, 0) << Slurp(log);

  const std::set<fs::path> want = FilesBelow(expected);
  const std::set<fs::path> got = FilesBelow(out);
  // config.yaml, runs/per_robot/links/queries/messages CSVs, summary.json,
  // the centroids of 2 robot counts x 1 run.
  ASSERT_GE(want.size(), 7u + 2u) << "the expected folder is incomplete";
  EXPECT_EQ(got, want) << "the run wrote other files than the golden set";
  for (const fs::path& rel : want) {
    if (!got.count(rel)) continue;
    std::string text = Slurp(out / rel);
    if (rel == "config.yaml") text = ReplaceAll(text, fs::canonical(source).string(), "@SOURCE_DIR@");
    EXPECT_TRUE(text == Slurp(expected / rel)) << rel << " differs from tests/golden/expected/" << rel.string();
  }
}

}  // namespace
