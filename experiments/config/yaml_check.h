#pragma once
// What yaml-cpp accepts but a config must not hold: a key given twice in one map (yaml-cpp keeps
// both and a lookup finds the first, so the second would be silently ignored) and a second YAML
// document (YAML::Load reads only the first). Internal to the config parser.
#include <string>

namespace dvpr::config_detail {

// Walks the parser's events once (aliases are not expanded, so an alias bomb costs its text's
// length). Throws ConfigError "<origin>:<line>: <key.path>: duplicate key (first at line N)" or
// "<origin>:<line>: a second YAML document ...". Syntax errors are left to YAML::Load.
void CheckYamlStructure(const std::string& yaml_text, const std::string& origin);

// The same for the value of `--set <path>=<value>`: one line of text, so the error names the
// override and the key path inside the config instead of a line:
// "<origin>: --set <path>: <path>.<key>: duplicate key".
void CheckOverrideStructure(const std::string& value, const std::string& origin, const std::string& path);

}  // namespace dvpr::config_detail
