// outputs.connectivity (docs/config.md): off by default, read and written back when on, and
// refused in one named error without a radio, where robots have no positions or ranges.
#include <string>

#include <gtest/gtest.h>

#include "tests/config/config_test_support.h"

namespace dvpr {
namespace {

using testing_support::ConfigErrorOf;
using testing_support::ParseTestConfig;

TEST(ConfigConnectivityTest, OffByDefaultAndOnReadsBack) {
  EXPECT_FALSE(ParseTestConfig("robots: [3]\n").outputs.connectivity);
  const ExperimentConfig c = ParseTestConfig(
      "robots: [3]\nnetwork: {model: [point_to_point, radio]}\noutputs: {connectivity: true}\n");
  EXPECT_TRUE(c.outputs.connectivity);
  EXPECT_EQ(ParseConfig(EmitConfig(c), DVPR_SOURCE_DIR, {}, "emitted.yaml"), c);
  // Off, the key is not written: config.yaml of every other run stays as it was.
  EXPECT_EQ(EmitConfig(ParseTestConfig("robots: [3]\nnetwork: {model: radio}\n")).find("connectivity"),
            std::string::npos);
}

TEST(ConfigConnectivityTest, WithoutARadioVariantItIsOneNamedError) {
  const std::string expected =
      "test.yaml: outputs.connectivity: needs a network variant of model radio (network.model lists none): "
      "robots have positions and ranges only on the radio";
  EXPECT_EQ(ConfigErrorOf("robots: [3]\noutputs: {connectivity: true}\n"), expected);
  EXPECT_EQ(ConfigErrorOf("robots: [3]\nnetwork: {model: [ideal, shared_medium]}\noutputs: {connectivity: true}\n"),
            expected);
  // Off needs nothing.
  EXPECT_EQ(ConfigErrorOf("robots: [3]\noutputs: {connectivity: false}\n"), "(no error)");
  EXPECT_EQ(ConfigErrorOf("robots: [3]\nnetwork: {model: radio}\noutputs: {connectivity: 2}\n").rfind(
                "test.yaml: outputs.connectivity: ", 0),
            0u);
}

}  // namespace
}  // namespace dvpr
