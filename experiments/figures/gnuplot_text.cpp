#include "experiments/figures/gnuplot_text.h"

#include <algorithm>

namespace dvpr {

std::string GnuplotQuote(std::string_view s) {
  std::string out = "'";
  for (const char c : OneLineText(s)) {
    out += c;
    if (c == '\'') out += '\'';
  }
  return out + "'";
}

std::string GnuplotLines(const std::vector<std::string>& lines) {
  std::string out;
  for (std::size_t i = 0; i < lines.size(); ++i) out += (i ? ".\"\\n\"." : "") + GnuplotQuote(lines[i]);
  return out.empty() ? "''" : out;
}

std::string GnuplotTitle(const std::vector<std::string>& lines) {
  const auto plain = [](const std::string& line) {
    return line.find_first_not_of("ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789 _,.:;()+-=/%") ==
           std::string::npos;
  };
  if (!std::all_of(lines.begin(), lines.end(), plain)) return GnuplotLines(lines);
  std::string out = "\"";
  for (std::size_t i = 0; i < lines.size(); ++i) out += (i ? "\\n" : "") + lines[i];
  return out + "\"";
}

}  // namespace dvpr
