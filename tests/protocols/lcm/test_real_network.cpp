// Real agents talk over the real network: a config that asks for the simulated radio is refused
// by dvpr launch and dvpr agent before any process starts, not run as a full mesh.
#include <stdexcept>
#include <string>

#include <gtest/gtest.h>

#include "experiments/protocols/lcm/agent_process.h"

namespace dvpr {
namespace {

TEST(RealNetworkTest, TheRadioIsRefusedNamingTheKey) {
  ExperimentConfig c;
  EXPECT_NO_THROW(CheckRealNetwork(c, "my.yaml"));
  c.network.model = {LinkModelKind::kPointToPoint, LinkModelKind::kRadio};
  try {
    CheckRealNetwork(c, "my.yaml");
    FAIL() << "accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_EQ(std::string(e.what()).rfind("my.yaml: network.model: radio is simulated only (dvpr run)", 0), 0u)
        << e.what();
  }
}

}  // namespace
}  // namespace dvpr
