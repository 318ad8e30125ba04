// The registry of built-in protocols and the traits catalogue agree: `dvpr run` accepts exactly
// the protocols it registers (config parsing's list), each has traits, and a protocol without
// traits cannot be registered.
#include <algorithm>
#include <stdexcept>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "experiments/config/config.h"
#include "experiments/results/protocol_traits.h"
#include "experiments/sweep/run_executor.h"

namespace dvpr {
namespace {

TEST(BuiltinProtocols, TheConfigAcceptsExactlyTheRegisteredProtocols) {
  std::vector<std::string> registered = BuiltinProtocols().Names();
  std::vector<std::string> accepted = KnownProtocols();
  std::sort(registered.begin(), registered.end());
  std::sort(accepted.begin(), accepted.end());
  EXPECT_EQ(registered, (std::vector<std::string>{"paper", "sim"}));
  EXPECT_EQ(accepted, registered);
  // The config's default list runs every one of them.
  std::vector<std::string> defaults = SweepConfig{}.protocols;
  std::sort(defaults.begin(), defaults.end());
  EXPECT_EQ(defaults, registered);
}

TEST(BuiltinProtocols, EachRegisteredProtocolHasTraits) {
  for (const std::string& name : BuiltinProtocols().Names()) {
    EXPECT_EQ(TraitsOf(name).name, name);
    EXPECT_NE(BuiltinProtocols().Find(name), nullptr);
  }
}

TEST(BuiltinProtocols, AProtocolWithoutTraitsCannotBeRegistered) {
  ProtocolRegistry registry;
  EXPECT_THROW(registry.Add("radio", [](const SharedInputs&) -> RunFunction { return {}; }), std::invalid_argument);
  EXPECT_EQ(registry.Find("radio"), nullptr);
  EXPECT_TRUE(registry.Names().empty());
  registry.Add(std::string(kSimProtocol), [](const SharedInputs&) -> RunFunction { return {}; });
  EXPECT_EQ(registry.Names(), std::vector<std::string>{"sim"});
}

}  // namespace
}  // namespace dvpr
