#pragma once
// Text dvpr does not trust (names and paths from configs, result folders and CSV files, a
// library's message) shown on one line: on the terminal (dvpr's error line, what dvpr replay and
// dvpr plot print), in a gnuplot script (gnuplot_text.h) or a line-based data file. Nothing in it
// can start a new line or reach the terminal as a control sequence.
#include <string>
#include <string_view>

namespace dvpr {

// `s` as one line of valid UTF-8: control characters (0x00-0x1f, 0x7f; ESC among them) are shown
// as the two characters \n, \r or \t, or as \xNN for the others, and so is every byte that is
// not part of a valid UTF-8 sequence (a terminal or gnuplot's cairo terminal garbles such bytes).
// Valid UTF-8 is kept as it is.
std::string OneLineText(std::string_view s);

}  // namespace dvpr
