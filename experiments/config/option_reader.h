#pragma once
// Reading "--flag value" pairs of a dvpr subcommand, with errors that name the
// flag and what was expected (std::stoi's own message is just "stoi").
#include <charconv>
#include <cstddef>
#include <stdexcept>
#include <string>
#include <vector>

namespace dvpr {

class OptionReader {
 public:
  // args[0] is the subcommand; flags follow.
  explicit OptionReader(const std::vector<std::string>& args) : args_(args) {}

  // Moves to the next flag; false when there is none.
  bool Next() { return ++i_ < args_.size(); }
  const std::string& flag() const { return args_[i_]; }

  // No flag takes an empty value: `--out ''` (an unset shell variable) would otherwise mean the
  // flag's default, or the current directory.
  const std::string& Text() {
    if (i_ + 1 >= args_.size()) throw std::invalid_argument(flag() + " needs a value");
    if (args_[i_ + 1].empty()) throw std::invalid_argument(flag() + ": expected a value, got ''");
    return args_[++i_];
  }
  int Int() { return Number<int>("an integer"); }
  long long Int64() { return Number<long long>("an integer"); }
  double Double() { return Number<double>("a number"); }
  [[noreturn]] void Unknown() const { throw std::invalid_argument("unknown option " + flag()); }

 private:
  template <typename T>
  T Number(const char* what) {
    const std::string& flag_name = flag();
    const std::string& text = Text();
    T value{};
    const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (ec != std::errc() || end != text.data() + text.size() || text.empty()) {
      throw std::invalid_argument(flag_name + ": expected " + what + ", got '" + text + "'");
    }
    return value;
  }

  const std::vector<std::string>& args_;
  std::size_t i_ = 0;
};

}  // namespace dvpr
