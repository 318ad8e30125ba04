// The resolved config (EmitConfig, the config.yaml of every result folder) must run again as it
// is. Found by tests/fuzz/fuzz_config: a config without link overrides or dropouts was written
// with `links: []` and `dropout: []`, which the reader refused ("expected at least one value,
// got an empty list"), so `dvpr run <result>/config.yaml` failed.
#include <string>

#include <gtest/gtest.h>

#include "experiments/config/config.h"
#include "tests/config/config_test_support.h"

namespace dvpr {
namespace {

using testing_support::Parse;

TEST(ConfigEmittedReadsBackTest, EmptyLinksAndDropoutListsMeanNone) {
  const ExperimentConfig c = Parse("network: {links: []}\ndropout: []\n");
  EXPECT_TRUE(c.network.links.empty());
  EXPECT_TRUE(c.dropout.empty());
  EXPECT_EQ(c, Parse("{}"));
}

TEST(ConfigEmittedReadsBackTest, DefaultConfigReadsBackEqual) {
  const ExperimentConfig c = Parse("{}");
  const std::string yaml = EmitConfig(c);
  ASSERT_NE(yaml.find("links:"), std::string::npos) << yaml;  // the empty list is written
  EXPECT_EQ(ParseConfig(yaml, "/nonexistent", {}, "config.yaml"), c) << yaml;
}

// Found by fuzz_config: a name with an invalid UTF-8 byte was emitted with U+FFFD in its place,
// so the result folder's config.yaml named another folder. `..` would name the folder above.
TEST(ConfigEmittedReadsBackTest, NameMustBePrintableUtf8AndNotDotDot) {
  for (const char* bad : {"\"a\\x01b\"", "\"a\\tb\"", "..", "."}) {
    try {
      Parse(std::string("name: ") + bad + "\n");
      ADD_FAILURE() << bad << " accepted";
    } catch (const ConfigError& e) {
      EXPECT_NE(std::string(e.what()).find("name: expected a non-empty name"), std::string::npos) << e.what();
    }
  }
  // Raw bytes: a lone continuation byte, a truncated 3-byte sequence.
  for (const std::string& bad : {std::string("a\x80"), std::string("a\xe2\x82")}) {
    EXPECT_THROW(Parse("name: " + bad + "\n"), ConfigError) << bad;
  }
  const ExperimentConfig c = Parse("name: \"caf\xc3\xa9 run 2\"\n");  // UTF-8 and spaces are fine
  EXPECT_EQ(c.name, "caf\xc3\xa9 run 2");
  EXPECT_EQ(ParseConfig(EmitConfig(c), "/nonexistent", {}, "config.yaml").name, c.name);
}

// Found by fuzz_config: a missing key read as a value threw YAML::InvalidNode ("invalid node; this
// may result from using a map iterator as a sequence iterator"), not a ConfigError naming it.
TEST(ConfigEmittedReadsBackTest, MissingRangeEndIsAConfigErrorNamingTheKey) {
  try {
    Parse("robots: {from: 2}\n");
    ADD_FAILURE() << "accepted";
  } catch (const ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find("robots.to: expected"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace dvpr
