#pragma once
// Text that reaches a gnuplot script: names, labels and paths read from configs and CSV files
// (strategy and network names, loss models, legend titles), which dvpr does not trust.
//
// gnuplot runs backquoted commands (`...`) and expands @macros on a script line before it
// parses it, also inside double-quoted strings; it does neither inside single-quoted strings,
// where the only special character is the quote itself (written twice). So every such text is
// written single-quoted (GnuplotQuote), and a title that needs a line break is single-quoted
// pieces joined by the string "\n" (GnuplotLines), never one double-quoted string.
#include <string>
#include <string_view>
#include <vector>

namespace dvpr {

// `s` as one line of valid UTF-8, for a script line or a line-based data file (.titles):
// control characters (0x00-0x1f, 0x7f) are shown as the two characters \n, \r or \t, or as \xNN
// for the others, and so is every byte that is not part of a valid UTF-8 sequence (gnuplot's
// cairo terminal garbles such bytes and warns on stderr). Valid UTF-8 is kept as it is.
std::string OneLineText(std::string_view s);

// `s` as a gnuplot single-quoted string: OneLineText(s), quotes doubled, in single quotes.
std::string GnuplotQuote(std::string_view s);

// Lines joined by line breaks, as a gnuplot string expression: 'line 1'."\n".'line 2'.
std::string GnuplotLines(const std::vector<std::string>& lines);

// A title of one or more lines: one double-quoted string "line 1\nline 2", as dvpr has always
// written its titles, when every line is made only of characters that mean nothing to gnuplot
// inside double quotes (letters, digits, space and _ , . : ; ( ) + - = / %); else GnuplotLines.
// So the scripts of ordinary names stay as they were, and any other text is single-quoted.
std::string GnuplotTitle(const std::vector<std::string>& lines);

}  // namespace dvpr
