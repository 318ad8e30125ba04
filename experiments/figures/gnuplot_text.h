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

#include "experiments/results/one_line_text.h"  // OneLineText: a script line, a .titles line

namespace dvpr {

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
