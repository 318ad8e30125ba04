#include "experiments/config/yaml_check.h"

#include <map>
#include <sstream>
#include <string>
#include <vector>

#include <yaml-cpp/eventhandler.h>
#include <yaml-cpp/mark.h>
#include <yaml-cpp/yaml.h>

#include "experiments/config/config.h"

namespace dvpr::config_detail {
namespace {

// Follows the nesting from the events: every node starts inside the innermost open collection;
// in a map, nodes alternate key, value.
class StructureCheck : public YAML::EventHandler {
 public:
  // Errors read "<where><line>: <path>: ..." when with_lines, else "<where>: <path>: ..."; paths
  // start at `root` (the override's key path, or the top level).
  StructureCheck(const std::string& where, bool with_lines, const std::string& root)
      : where_(where), with_lines_(with_lines), root_(root) {}

  void OnDocumentStart(const YAML::Mark& mark) override {
    if (++documents_ > 1) {
      Fail(mark, "", "a second YAML document (a config is one document; remove the '---' or '...')");
    }
  }
  void OnDocumentEnd() override {}
  void OnNull(const YAML::Mark& mark, YAML::anchor_t) override { Enter(mark, nullptr); }
  void OnAlias(const YAML::Mark& mark, YAML::anchor_t) override { Enter(mark, nullptr); }
  void OnScalar(const YAML::Mark& mark, const std::string&, YAML::anchor_t, const std::string& value) override {
    Enter(mark, &value);
  }
  void OnSequenceStart(const YAML::Mark& mark, const std::string&, YAML::anchor_t, YAML::EmitterStyle::value) override {
    open_.push_back(Frame{false, Enter(mark, nullptr), {}, true, {}, 0});
  }
  void OnSequenceEnd() override { open_.pop_back(); }
  void OnMapStart(const YAML::Mark& mark, const std::string&, YAML::anchor_t, YAML::EmitterStyle::value) override {
    open_.push_back(Frame{true, Enter(mark, nullptr), {}, true, {}, 0});
  }
  void OnMapEnd() override { open_.pop_back(); }

 private:
  struct Frame {
    bool map;
    std::string path;
    std::map<std::string, int> first_line;  // key -> line (1-based)
    bool at_key;
    std::string key;
    std::size_t index;
  };

  static std::string Join(const std::string& path, const std::string& key) {
    return path.empty() ? key : path + "." + key;
  }

  [[noreturn]] void Fail(const YAML::Mark& mark, const std::string& path, const std::string& problem) const {
    const std::string at = with_lines_ ? ":" + std::to_string(mark.line + 1) : "";
    throw ConfigError(where_ + at + ": " + (path.empty() ? "" : path + ": ") + problem);
  }

  // A node starts: returns its key path; a map key given before in the same map fails.
  std::string Enter(const YAML::Mark& mark, const std::string* scalar) {
    if (open_.empty()) return root_;
    Frame& f = open_.back();
    if (!f.map) return f.path + "[" + std::to_string(f.index++) + "]";
    if (!f.at_key) {
      f.at_key = true;
      return Join(f.path, f.key);
    }
    f.at_key = false;
    f.key = scalar != nullptr ? *scalar : "?";  // a collection as a key: never a config key
    if (scalar != nullptr) {
      const auto [it, fresh] = f.first_line.emplace(*scalar, mark.line + 1);
      if (!fresh) {
        Fail(mark, Join(f.path, f.key),
             with_lines_ ? "duplicate key (first at line " + std::to_string(it->second) + ")" : "duplicate key");
      }
    }
    return Join(f.path, f.key);
  }

  std::string where_;
  bool with_lines_;
  std::string root_;
  int documents_ = 0;
  std::vector<Frame> open_;
};

void Walk(const std::string& text, StructureCheck& check) {
  std::istringstream in(text);
  try {
    YAML::Parser parser(in);
    while (parser.HandleNextDocument(check)) {
    }
  } catch (const YAML::Exception&) {
    // Malformed YAML: YAML::Load reports it with the parser's own message.
  }
}

}  // namespace

void CheckYamlStructure(const std::string& yaml_text, const std::string& origin) {
  StructureCheck check(origin, /*with_lines=*/true, "");
  Walk(yaml_text, check);
}

void CheckOverrideStructure(const std::string& value, const std::string& origin, const std::string& path) {
  const std::string where = origin + ": --set " + path;
  StructureCheck check(where, /*with_lines=*/false, path);
  Walk(value, check);
}

}  // namespace dvpr::config_detail
