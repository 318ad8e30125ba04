// Printable (experiments/domain/data/printable.h): file bytes quoted in a one-line error message.
#include "experiments/domain/data/printable.h"

#include <gtest/gtest.h>

#include <string>

namespace dvpr {
namespace {

TEST(PrintableTest, KeepsPrintableAsciiAsIs) {
  EXPECT_EQ(Printable("{'descr': '<f4'}"), "{'descr': '<f4'}");
}

TEST(PrintableTest, EscapesLineBreaksTabsBackslashesAndOtherBytes) {
  // \n \r \t \\ as in C; 0x00, 0x7f (DEL), 0x93 (npy's magic) and UTF-8 'é' (c3 a9) as \xNN.
  EXPECT_EQ(Printable(std::string("a\nb\rc\td\\e", 9)), "a\\nb\\rc\\td\\\\e");
  EXPECT_EQ(Printable(std::string("\x00\x7f\x93NUMPY", 8)), "\\x00\\x7f\\x93NUMPY");
  EXPECT_EQ(Printable("caf\xc3\xa9"), "caf\\xc3\\xa9");
}

TEST(PrintableTest, CutsLongTextAndSaysSo) {
  EXPECT_EQ(Printable("abcdef", 3), "abc...");
  EXPECT_EQ(Printable("abc", 3), "abc");
  EXPECT_EQ(Printable(std::string(100, 'x')), std::string(80, 'x') + "...");
}

}  // namespace
}  // namespace dvpr
