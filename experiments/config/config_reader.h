#pragma once
// Internal to the config parser (config.cpp): typed reads from a YAML node that carry the key path
// into every error, and the check for unknown keys. Not for use outside experiments/config*.cpp.
#include <filesystem>
#include <initializer_list>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include <yaml-cpp/yaml.h>

#include "experiments/config/config.h"

namespace dvpr::config_detail {

// Where a config came from, for error messages and relative paths.
struct Origin {
  std::string name;                // the file (or "<config>")
  std::filesystem::path base_dir;  // its folder
  ConfigFiles files = ConfigFiles::kMustExist;
};

// A node and its dotted key path ("network.loss.p", "dropout[1].at").
class Field {
 public:
  Field(const Origin& origin, YAML::Node node, std::string path)
      : origin_(&origin), node_(std::move(node)), path_(std::move(path)) {}

  const std::string& path() const { return path_; }
  const YAML::Node& node() const { return node_; }
  bool present() const { return node_.IsDefined() && !node_.IsNull(); }
  const Origin& origin() const { return *origin_; }

  [[noreturn]] void Fail(const std::string& problem) const;

  // Runs a lower layer's params.Validate(); its error "<field>: <problem>" becomes this key's
  // error at "<path>.<field>" (the params' fields are the section's keys).
  template <typename Params>
  void Validate(const Params& params) const {
    try {
      params.Validate();
    } catch (const std::invalid_argument& e) {
      FailWithin(e.what());
    }
  }
  // A name parsed by the lower layer that owns the enum (ParseLinkModelKind, ...); its error
  // becomes this key's.
  template <typename Parse>
  auto Named(Parse parse) const -> decltype(parse(std::string_view())) {
    const std::string& name = Scalar("a name");
    try {
      return parse(name);
    } catch (const std::invalid_argument& e) {
      Fail(e.what());
    }
  }

  // Requires a map whose keys are all in `allowed`; the error lists them.
  void ExpectMap(std::initializer_list<std::string_view> allowed) const;
  Field Child(std::string_view key) const;
  // A list's items; a scalar counts as a one-item list (so `bandwidth: 10Mbps` and
  // `bandwidth: [1Mbps, 10Mbps]` both work). Fails on an empty list.
  std::vector<Field> Items() const;

  // The numeric reads take the key's valid range (docs/config.md): a value outside it, or one too
  // large to parse, fails with "must be in [min, max], got <the text as written>".
  std::string String() const;
  long long Int(long long min, long long max) const;
  double Double() const;  // any finite number; the params' Validate() checks it
  double Double(double min, double max) const;
  bool Bool() const;
  DataRate Rate(DataRate min, DataRate max) const;
  SimTime Duration(SimTime min, SimTime max) const;
  Bytes Size(Bytes min, Bytes max, bool plain_integer_is_bytes) const;
  // One of `names`; returns its index.
  std::size_t Choice(const std::vector<std::string>& names) const;
  // A file that must exist: absolute, or resolved against the config's folder, the current
  // directory, then the source tree. A candidate that is there but is not a regular file (a
  // folder, a FIFO, a device, a loop of symbolic links) is an error saying which, found by stat
  // without opening it; a symbolic link to a regular file is that file.
  std::filesystem::path ExistingFile() const;

 private:
  const std::string& Scalar(std::string_view expected) const;
  [[noreturn]] void FailRange(const std::string& min, const std::string& max) const;
  [[noreturn]] void FailWithin(const std::string& field_and_problem) const;

  const Origin* origin_;
  YAML::Node node_;
  std::string path_;
};

// Candidate locations of a relative path, in the order they are tried.
std::vector<std::filesystem::path> SearchDirs(const Origin& origin);

// Whether the number that begins `quantity` ("0.4mm", "0.0001 s") has a digit other than 0: a
// quantity the parser rounded to 0 at its resolution (1 ns, 1 mm) although it is not 0.
bool NonZeroNumber(std::string_view quantity);

}  // namespace dvpr::config_detail
