// dvpr's exit statuses (`dvpr --help`): 0 success, 1 an input the user can fix, 2 usage (a flag
// or its value), 3 an internal error - never 1, so a bug is not mistaken for a user's mistake.
#include <filesystem>
#include <new>
#include <sstream>
#include <stdexcept>
#include <string>
#include <system_error>

#include <gtest/gtest.h>

#include "experiments/app/cli.h"
#include "experiments/config/config.h"
#include "tests/app/cli_test_support.h"

namespace dvpr {
namespace {

using testing_support::CliTest;
using testing_support::Result;

// The status and the line ReportError gives for exception `e`.
template <typename E>
std::pair<int, std::string> Report(const E& e) {
  std::ostringstream err;
  const int status = ReportError(std::make_exception_ptr(e), err);
  return {status, err.str()};
}

TEST(ReportErrorTest, InputErrorsAreStatusOne) {
  EXPECT_EQ(Report(ConfigError("c.yaml: runs: must be at least 1, got 0")),
            std::make_pair(1, std::string("dvpr: error: c.yaml: runs: must be at least 1, got 0\n")));
  EXPECT_EQ(Report(std::invalid_argument("loss.p: a probability must lie in [0, 1], got 2")),
            std::make_pair(1, std::string("dvpr: error: loss.p: a probability must lie in [0, 1], got 2\n")));
  EXPECT_EQ(Report(std::runtime_error("d.csv: line 3: not a number: 'x'")),
            std::make_pair(1, std::string("dvpr: error: d.csv: line 3: not a number: 'x'\n")));
  const std::filesystem::filesystem_error fs("cannot create directory", std::filesystem::path("/proc/x"),
                                             std::make_error_code(std::errc::permission_denied));
  EXPECT_EQ(Report(fs).first, 1);
}

TEST(ReportErrorTest, EverythingElseIsAnInternalErrorStatusThree) {
  EXPECT_EQ(Report(std::logic_error("BuildRunPlacement: broadcast with a table")),
            std::make_pair(3, std::string("dvpr: internal error: BuildRunPlacement: broadcast with a table "
                                          "(a bug in dvpr; please report it)\n")));
  EXPECT_EQ(Report(std::out_of_range("CentroidTable: no robot 7")).first, 3);
  EXPECT_EQ(Report(std::length_error("vector")).first, 3);
  EXPECT_EQ(Report(std::bad_alloc()).first, 3);
  EXPECT_EQ(Report(42), std::make_pair(3, std::string("dvpr: internal error: an unknown exception (a bug in dvpr; "
                                                      "please report it)\n")));
}

// Line breaks and other control characters are shown as escapes (one_line_text.h), \r too.
TEST(ReportErrorTest, AMessageOverSeveralLinesIsKeptToOne) {
  EXPECT_EQ(Report(std::runtime_error("f.npy: bad\nheader\r\n")),
            std::make_pair(1, std::string("dvpr: error: f.npy: bad\\nheader\\r\\n\n")));
  EXPECT_EQ(Report(std::runtime_error("x\x1b[2J\ty\xff")),
            std::make_pair(1, std::string("dvpr: error: x\\x1B[2J\\ty\\xFF\n")));
}

TEST_F(CliTest, HelpDocumentsTheExitStatuses) {
  ASSERT_EQ(Dvpr("--help").status, 0);
  const std::string out = Stdout();
  EXPECT_NE(out.find("Exit status:\n  0  success\n  1  an input you can fix"), std::string::npos) << out;
  EXPECT_NE(out.find("\n  2  usage: an unknown command or flag"), std::string::npos) << out;
  EXPECT_NE(out.find("\n  3  internal error"), std::string::npos) << out;
}

TEST_F(CliTest, AMalformedThreadCountNamesTheFlag) {
  ExpectExactly(Dvpr("run c.yaml --threads abc"), 2,
                "dvpr run: --threads: expected an integer, got 'abc' (see dvpr --help)");
  ExpectExactly(Dvpr("run c.yaml --threads 2x"), 2, "dvpr run: --threads: expected an integer, got '2x' (see dvpr --help)");
}

TEST_F(CliTest, ANegativeThreadCountIsRefused) {
  ExpectExactly(Dvpr("run c.yaml --threads -3"), 2,
                "dvpr run: --threads: expected a count >= 0 (0: all cores), got -3 (see dvpr --help)");
}

TEST_F(CliTest, AnEmptyOutIsRefusedByEverySubcommand) {
  ExpectExactly(Dvpr("run c.yaml --out ''"), 2, "dvpr run: --out: expected a value, got '' (see dvpr --help)");
  ExpectExactly(Dvpr("agent --config c.yaml --robot 0 --out ''"), 2,
                "dvpr agent: --out: expected a value, got '' (see dvpr --help)");
  ExpectExactly(Dvpr("launch --config c.yaml --robots 2 --out ''"), 2,
                "dvpr launch: --out: expected a value, got '' (see dvpr --help)");
}

TEST_F(CliTest, UsageErrorsAreStatusTwo) {
  ExpectExactly(Dvpr("frobnicate"), 2, "dvpr: unknown command 'frobnicate' (see dvpr --help)");
  ExpectExactly(Dvpr("run c.yaml --fast"), 2, "dvpr run: unknown option --fast (see dvpr --help)");
  ExpectExactly(Dvpr("run c.yaml --threads"), 2, "dvpr run: --threads needs a value (see dvpr --help)");
  ExpectExactly(Dvpr("run"), 2, "dvpr run: dvpr run needs a CONFIG.yaml (see dvpr --help)");
  ExpectExactly(Dvpr("run c.yaml --set runs"), 2, "dvpr run: --set runs: expected key.path=value (see dvpr --help)");
  ExpectExactly(Dvpr("run c.yaml --set dropout[0].robot=1"), 2,
                "dvpr run: --set dropout[0].robot=1: a key path names map keys only, not list elements; set the "
                "whole list, e.g. --set 'dropout=[...]' (see dvpr --help)");
  ExpectExactly(Dvpr("agent --config c.yaml --robot 0 --set =1"), 2,
                "dvpr agent: --set =1: expected key.path=value (see dvpr --help)");
  ExpectExactly(Dvpr("launch --config c.yaml --robots 2 --grace"), 2, "dvpr launch: --grace needs a value (see dvpr --help)");
  ExpectExactly(Dvpr("plot"), 2, "dvpr plot: expected one folder (see dvpr --help)");
}

TEST_F(CliTest, AnAgentTeamOfFewerThanTwoIsRefused) {
  ExpectExactly(Dvpr("agent --config c.yaml --robot 0 --robots 1"), 2,
                "dvpr agent: --robots must be at least 2, got 1 (see dvpr --help)");
}

// A list index too long for any integer is past the end of the list, not an internal error.
TEST_F(CliTest, AnOverlongListIndexInASetIsAnInputError) {
  const Result r = RunConfig("robots: [2]\n", "--set robots.99999999999999999999=3");
  ExpectExactly(r, 1, "dvpr: error: " + Config().string() + ": --set robots.99999999999999999999: index "
                      "99999999999999999999 is past the end");
}

}  // namespace
}  // namespace dvpr
