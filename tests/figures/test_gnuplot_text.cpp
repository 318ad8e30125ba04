// Text in gnuplot scripts (gnuplot_text.h): worked by hand, and checked against the installed
// gnuplot: a backquoted command in a single-quoted title is text, not a command.
#include <fcntl.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>

#include "experiments/figures/gnuplot_run.h"
#include "experiments/figures/gnuplot_text.h"
#include "tests/test_support.h"

namespace dvpr {
namespace {

namespace fs = std::filesystem;

TEST(GnuplotText, OneLineShowsControlCharactersAndInvalidBytes) {
  EXPECT_EQ(OneLineText("plain name_1.5"), "plain name_1.5");
  EXPECT_EQ(OneLineText("a\nb\rc\td"), "a\\nb\\rc\\td");
  EXPECT_EQ(OneLineText(std::string("nul\0esc\x1b" "del\x7f", 12)), "nul\\x00esc\\x1Bdel\\x7F");
  // Valid UTF-8 stays: é (C3 A9), U+2028 (E2 80 A8), U+1F600 (F0 9F 98 80).
  EXPECT_EQ(OneLineText("caf\xc3\xa9 \xe2\x80\xa8 \xf0\x9f\x98\x80"), "caf\xc3\xa9 \xe2\x80\xa8 \xf0\x9f\x98\x80");
  // Invalid: a lone continuation byte, FF, an overlong '/' (C0 AF), a surrogate (ED A0 80), a
  // sequence cut by the end of the text (E2 82).
  EXPECT_EQ(OneLineText("\x80|\xff|\xc0\xaf|\xed\xa0\x80|\xe2\x82"), "\\x80|\\xFF|\\xC0\\xAF|\\xED\\xA0\\x80|\\xE2\\x82");
}

TEST(GnuplotText, QuoteDoublesQuotesAndNothingElse) {
  EXPECT_EQ(GnuplotQuote(""), "''");
  EXPECT_EQ(GnuplotQuote("john's \"x\" `touch y` $(z); @m \\"), "'john''s \"x\" `touch y` $(z); @m \\'");
  EXPECT_EQ(GnuplotQuote("''"), "''''''");
  EXPECT_EQ(GnuplotQuote("a\nb'\xff"), "'a\\nb''\\xFF'");
}

TEST(GnuplotText, TitlesStayDoubleQuotedOnlyWhenPlain) {
  EXPECT_EQ(GnuplotLines({"a", "b'c"}), "'a'.\"\\n\".'b''c'");
  EXPECT_EQ(GnuplotTitle({"point-to-point 10 Mbit/s 2 ms", "(n - 1 = 4); 50%"}),
            "\"point-to-point 10 Mbit/s 2 ms\\n(n - 1 = 4); 50%\"");
  EXPECT_EQ(GnuplotTitle({"ok", "`touch x`"}), "'ok'.\"\\n\".'`touch x`'");
  EXPECT_EQ(GnuplotTitle({"@macro"}), "'@macro'");
  EXPECT_EQ(GnuplotTitle({"back\\slash"}), "'back\\slash'");
}

// gnuplot itself: the title holds a backquoted command, a $(...) and a macro; the canary file
// must not appear, and the PNG must be drawn.
TEST(GnuplotText, GnuplotRunsNothingFromAQuotedTitle) {
  const std::optional<fs::path> gnuplot = FindProgram("gnuplot");
  if (!gnuplot) GTEST_SKIP() << "gnuplot is not installed";
  const fs::path dir = fs::path(DVPR_TEST_TMP) / "gnuplot_text" / "canary";
  fs::remove_all(dir);
  fs::create_directories(dir / "data");
  const fs::path canary = dir / "PWNED";
  const std::string hostile = "it's `touch " + canary.string() + "` $(touch " + canary.string() + "); @x\n\xff";
  std::ofstream(dir / "data" / "t.gp") << "set terminal pngcairo size 200,150 noenhanced\n"
                                          "set output (exists('dvpr_output') ? dvpr_output : '../t.png')\n"
                                          "set title " << GnuplotQuote(hostile) << "\nplot x title "
                                       << GnuplotTitle({hostile, "second line"}) << "\n";
  DrawWithGnuplot(*gnuplot, dir / "data", dir / "data" / "t.gp", dir / "t.png", dir / "data" / "t.log");
  EXPECT_FALSE(fs::exists(canary));
  EXPECT_EQ(testing_support::Slurp(dir / "t.png").substr(1, 3), "PNG");
  EXPECT_FALSE(fs::exists(dir / "data" / "t.log"));  // drawn: gnuplot said nothing worth keeping
}

}  // namespace
}  // namespace dvpr
