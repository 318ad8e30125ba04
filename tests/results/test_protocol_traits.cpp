// The protocols' traits: what each built-in protocol answers (from what it does: the paper
// protocol evaluates statically without messages, the simulation runs one row per network
// variant, dvpr launch's agents talk over a real network), the lookup of an unknown name, and a
// row of an unknown protocol read from a file.
#include <set>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include <gtest/gtest.h>

#include "experiments/results/protocol_traits.h"

namespace dvpr {
namespace {

TEST(ProtocolTraits, ThePaperProtocolEvaluatesStaticallyWithoutMessages) {
  const ProtocolTraits& t = TraitsOf("paper");
  EXPECT_EQ(t.name, "paper");
  EXPECT_TRUE(t.static_evaluation);
  EXPECT_FALSE(t.simulated_network);
  EXPECT_FALSE(t.sends_messages);
  EXPECT_TRUE(t.bow_strategies);
  EXPECT_EQ(t.relative_auc_reference, "centralized");
  EXPECT_EQ(t.title, "paper (static) protocol");
}

TEST(ProtocolTraits, TheSimulationRunsOnTheSweepsNetworkAndSendsMessages) {
  const ProtocolTraits& t = TraitsOf("sim");
  EXPECT_EQ(t.name, "sim");
  EXPECT_FALSE(t.static_evaluation);
  EXPECT_TRUE(t.simulated_network);
  EXPECT_TRUE(t.sends_messages);
  EXPECT_TRUE(t.bow_strategies);
  EXPECT_EQ(t.relative_auc_reference, "broadcast");
  EXPECT_EQ(t.title, "simulation");
}

TEST(ProtocolTraits, RealAgentsSendMessagesOnANetworkNoConfigDescribes) {
  const ProtocolTraits& t = TraitsOf("lcm");
  EXPECT_FALSE(t.static_evaluation);
  EXPECT_FALSE(t.simulated_network);
  EXPECT_TRUE(t.sends_messages);
  EXPECT_FALSE(t.bow_strategies);
  EXPECT_EQ(t.relative_auc_reference, "broadcast");
}

TEST(ProtocolTraits, TheNameConstantsAreTheCataloguesNamesEachOnce) {
  std::vector<std::string_view> names;
  for (const ProtocolTraits& t : ProtocolCatalogue()) names.push_back(t.name);
  EXPECT_EQ(names, (std::vector<std::string_view>{"paper", "sim", "lcm"}));
  EXPECT_EQ(TraitsOf(kPaperProtocol).name, "paper");
  EXPECT_EQ(TraitsOf(kSimProtocol).name, "sim");
  EXPECT_EQ(TraitsOf(kLcmProtocol).name, "lcm");
  // The lookup returns the catalogue's own entry, not a copy.
  EXPECT_EQ(&TraitsOf("sim"), &ProtocolCatalogue()[1]);
}

TEST(ProtocolTraits, AnUnknownNameIsAnErrorNamingItAndTheKnownOnes) {
  try {
    static_cast<void>(TraitsOf("simulation"));
    FAIL() << "no error for an unknown protocol";
  } catch (const std::invalid_argument& e) {
    EXPECT_STREQ(e.what(), "unknown protocol 'simulation' (known: paper, sim, lcm)");
  }
  EXPECT_THROW(static_cast<void>(TraitsOf("")), std::invalid_argument);
  EXPECT_THROW(static_cast<void>(TraitsOf("Sim")), std::invalid_argument);  // names are exact
}

TEST(ProtocolTraits, ARowOfAnUnknownProtocolHasNoTrait) {
  for (const char* name : {"simulation", "", "PAPER"}) {
    const ProtocolTraits& t = RowTraits(name);
    EXPECT_FALSE(t.static_evaluation) << name;
    EXPECT_FALSE(t.simulated_network) << name;
    EXPECT_FALSE(t.sends_messages) << name;
    EXPECT_FALSE(t.bow_strategies) << name;
    EXPECT_EQ(t.title, "") << name;
  }
  EXPECT_EQ(&RowTraits("paper"), &TraitsOf("paper"));
}

TEST(ProtocolTraits, AnyProtocolAsksEachListedName) {
  const std::vector<std::string> paper{"paper"}, both{"paper", "sim"}, none;
  EXPECT_FALSE(AnyProtocol(paper, &ProtocolTraits::sends_messages));
  EXPECT_TRUE(AnyProtocol(both, &ProtocolTraits::sends_messages));
  EXPECT_TRUE(AnyProtocol(both, &ProtocolTraits::static_evaluation));
  EXPECT_FALSE(AnyProtocol(none, &ProtocolTraits::static_evaluation));
  const std::vector<std::string> typo{"paper", "smi"};
  EXPECT_THROW(static_cast<void>(AnyProtocol(typo, &ProtocolTraits::simulated_network)), std::invalid_argument);
}

}  // namespace
}  // namespace dvpr
