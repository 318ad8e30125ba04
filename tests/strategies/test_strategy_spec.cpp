// ParseStrategy (experiments/domain/strategies/strategy_spec.h): every family with its parameters read
// from the name, and the names it refuses with their reasons. Names are chosen by hand, some of
// them outside what the shipped configs use (lpt_c7, multi_probe_5).
#include <stdexcept>
#include <string>

#include <gtest/gtest.h>

#include "experiments/domain/strategies/strategy_spec.h"

namespace dvpr {
namespace {

using Table = StrategySpec::Table;
using Placement = StrategySpec::Placement;

TEST(ParseStrategy, DecentralizedIsThePaperMethod) {
  const StrategySpec s = ParseStrategy("decentralized");
  EXPECT_EQ(s.name, "decentralized");
  EXPECT_EQ(s.table, Table::kPaper);
  EXPECT_EQ(s.placement, Placement::kNearest);
  EXPECT_EQ(s.clusters_per_robot, 0);  // the config's
  EXPECT_TRUE(s.paper_method());
  EXPECT_FALSE(s.broadcast());
  EXPECT_FALSE(s.reclusters());
}

TEST(ParseStrategy, BroadcastSaysSo) {
  const StrategySpec s = ParseStrategy("broadcast");
  EXPECT_TRUE(s.broadcast());
  EXPECT_FALSE(s.paper_method());
  EXPECT_FALSE(s.reclusters());
}

TEST(ParseStrategy, BagOfWordsNames) {
  EXPECT_EQ(ParseStrategy("bow_centralized").bow, StrategySpec::Bow::kCentralized);
  EXPECT_EQ(ParseStrategy("bow_broadcast").bow, StrategySpec::Bow::kBroadcast);
  EXPECT_EQ(ParseStrategy("bow_decentralized").bow, StrategySpec::Bow::kModulo);
  const StrategySpec df = ParseStrategy("bow_decentralized_df");
  EXPECT_EQ(df.bow, StrategySpec::Bow::kDocumentFrequency);
  EXPECT_TRUE(df.bag_of_words());
  EXPECT_FALSE(df.paper_method());
  EXPECT_FALSE(df.broadcast());
  EXPECT_FALSE(ParseStrategy("decentralized").bag_of_words());
  EXPECT_THROW(ParseStrategy("bow_decentralized_x"), std::invalid_argument);
}

TEST(ParseStrategy, ProbingReadsItsCountOrEpsilon) {
  const StrategySpec m = ParseStrategy("multi_probe_5");
  EXPECT_EQ(m.table, Table::kPaper);
  EXPECT_EQ(m.placement, Placement::kProbe);
  EXPECT_EQ(m.probe.probes, 5);
  EXPECT_LT(m.probe.epsilon, 0);  // always 5 centroids
  EXPECT_FALSE(m.paper_method());
  const StrategySpec a = ParseStrategy("adaptive_probe_0.05");
  EXPECT_EQ(a.placement, Placement::kProbe);
  EXPECT_EQ(a.probe.probes, 8);
  EXPECT_EQ(a.probe.epsilon, 0.05);
}

TEST(ParseStrategy, ReplicationReadsEpsilonAndOptionalReplicas) {
  const StrategySpec r = ParseStrategy("replicate_0.2");
  EXPECT_EQ(r.table, Table::kPaper);
  EXPECT_EQ(r.placement, Placement::kReplicate);
  EXPECT_EQ(r.replicate.epsilon, 0.2);
  EXPECT_EQ(r.replicate.max_replicas, 3);
  const StrategySpec r8 = ParseStrategy("replicate_1_r8");
  EXPECT_EQ(r8.replicate.epsilon, 1.0);
  EXPECT_EQ(r8.replicate.max_replicas, 8);
}

TEST(ParseStrategy, TablesReadTheirClustersPerRobot) {
  const StrategySpec lpt = ParseStrategy("lpt_c7");
  EXPECT_EQ(lpt.table, Table::kLpt);
  EXPECT_EQ(lpt.clusters_per_robot, 7);
  EXPECT_FALSE(lpt.loads_from_training);
  EXPECT_LT(lpt.balance.epsilon, 0);  // LPT, no bound
  EXPECT_EQ(lpt.placement, Placement::kNearest);
  EXPECT_FALSE(lpt.paper_method());
  EXPECT_TRUE(ParseStrategy("lpt_c10_train").loads_from_training);
  const StrategySpec bounded = ParseStrategy("bounded_c10_0.25");
  EXPECT_EQ(bounded.table, Table::kBounded);
  EXPECT_EQ(bounded.clusters_per_robot, 10);
  EXPECT_EQ(bounded.balance.epsilon, 0.25);
  EXPECT_EQ(ParseStrategy("sample_c3").table, Table::kSampleKMeans);
  EXPECT_EQ(ParseStrategy("sample_c3").clusters_per_robot, 3);
  EXPECT_EQ(ParseStrategy("balanced_c2").table, Table::kBalanced);
  EXPECT_EQ(ParseStrategy("balanced_sample_c4").table, Table::kBalancedSample);
  EXPECT_EQ(ParseStrategy("balanced_sample_c4").clusters_per_robot, 4);
}

TEST(ParseStrategy, ReclusteringStartsFromTheTrainingLptTable) {
  const StrategySpec s = ParseStrategy("recluster_c4_p50");
  EXPECT_EQ(s.table, Table::kLpt);
  EXPECT_EQ(s.clusters_per_robot, 4);
  EXPECT_TRUE(s.loads_from_training);
  EXPECT_EQ(s.recluster_period, 50);
  EXPECT_TRUE(s.reclusters());
  EXPECT_FALSE(s.paper_method());
}

TEST(ParseStrategy, ATableCombinesWithAPlacement) {
  const StrategySpec s = ParseStrategy("lpt_c10+adaptive_probe_0.1");
  EXPECT_EQ(s.name, "lpt_c10+adaptive_probe_0.1");
  EXPECT_EQ(s.table, Table::kLpt);
  EXPECT_EQ(s.clusters_per_robot, 10);
  EXPECT_EQ(s.placement, Placement::kProbe);
  EXPECT_EQ(s.probe.probes, 8);
  EXPECT_EQ(s.probe.epsilon, 0.1);
  const StrategySpec b = ParseStrategy("balanced_sample_c1+replicate_0.5_r5");
  EXPECT_EQ(b.table, Table::kBalancedSample);
  EXPECT_EQ(b.clusters_per_robot, 1);
  EXPECT_EQ(b.placement, Placement::kReplicate);
  EXPECT_EQ(b.replicate.epsilon, 0.5);
  EXPECT_EQ(b.replicate.max_replicas, 5);
}

// The message ParseStrategy throws for `name`, or "accepted".
std::string Refusal(const std::string& name) {
  try {
    ParseStrategy(name);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "accepted";
}

TEST(ParseStrategy, RefusesMalformedParametersSayingWhy) {
  EXPECT_EQ(Refusal("multi_probe_x"), "'multi_probe_x' is not a strategy: M must be a whole number >= 1, got 'x'");
  EXPECT_EQ(Refusal("multi_probe_0"), "'multi_probe_0' is not a strategy: M must be a whole number >= 1, got '0'");
  EXPECT_EQ(Refusal("multi_probe_99999999999"),
            "'multi_probe_99999999999' is not a strategy: M must be a whole number >= 1, got '99999999999'");
  EXPECT_EQ(Refusal("adaptive_probe_-1"), "'adaptive_probe_-1' is not a strategy: E must be a number >= 0, got '-1'");
  EXPECT_EQ(Refusal("adaptive_probe_inf"), "'adaptive_probe_inf' is not a strategy: E must be a number >= 0, got 'inf'");
  EXPECT_EQ(Refusal("lpt_10"), "'lpt_10' is not a strategy: expected cC, got '10'");
  EXPECT_EQ(Refusal("replicate_0.1_8"), "'replicate_0.1_8' is not a strategy: expected rR, got '8'");
  EXPECT_EQ(Refusal("recluster_c0_p50"), "'recluster_c0_p50' is not a strategy: C must be a whole number >= 1, got 'c0'");
}

TEST(ParseStrategy, RefusesASecondSpellingOfANumber) {
  // One strategy, one name: rows of adaptive_probe_0.1 and adaptive_probe_0.10 would not group.
  EXPECT_EQ(Refusal("adaptive_probe_0.10"), "'adaptive_probe_0.10' is not a strategy: E must be written 0.1, not '0.10'");
  EXPECT_EQ(Refusal("replicate_1e-1"), "'replicate_1e-1' is not a strategy: E must be written 0.1, not '1e-1'");
  EXPECT_EQ(Refusal("lpt_c04"), "'lpt_c04' is not a strategy: C must be written c4");
}

TEST(ParseStrategy, RefusesNamesOfAnotherShape) {
  EXPECT_EQ(Refusal("lpt_c10_test"), "'lpt_c10_test' is not a strategy: expected the form lpt_cC[_train]");
  EXPECT_EQ(Refusal("recluster_c4"), "'recluster_c4' is not a strategy: expected the form recluster_cC_pP");
  EXPECT_EQ(Refusal("bounded_c10"), "'bounded_c10' is not a strategy: expected the form bounded_cC_B");
  const std::string unknown = Refusal("multiprobe_2");
  EXPECT_EQ(unknown.rfind("'multiprobe_2' is not a strategy: unknown name (expected decentralized, broadcast, "
                          "multi_probe_M, ",
                          0),
            0u)
      << unknown;
  EXPECT_NE(Refusal("Decentralized").find("unknown name"), std::string::npos);  // names are case-sensitive
  EXPECT_NE(Refusal("").find("unknown name"), std::string::npos);
}

TEST(ParseStrategy, RefusesCombinationsOtherThanTablePlusPlacement) {
  EXPECT_EQ(Refusal("multi_probe_2+lpt_c4").find("'multi_probe_2+lpt_c4' is not a strategy: before '+' comes a table"),
            0u);
  EXPECT_EQ(Refusal("lpt_c10+lpt_c4").find("'lpt_c10+lpt_c4' is not a strategy: after '+' comes a routing"), 0u);
  // Re-clustering routes by each robot's current table: no routing to combine with.
  EXPECT_NE(Refusal("recluster_c4_p50+replicate_0.1").find("before '+' comes a table"), std::string::npos);
  EXPECT_NE(Refusal("decentralized+multi_probe_2").find("before '+' comes a table"), std::string::npos);
  EXPECT_NE(Refusal("lpt_c4+decentralized").find("after '+' comes a routing"), std::string::npos);
  EXPECT_EQ(Refusal("lpt_c4+multi_probe_2+replicate_0.1"),
            "'lpt_c4+multi_probe_2+replicate_0.1' is not a strategy: at most one '+' (TABLE+ROUTING)");
}

}  // namespace
}  // namespace dvpr
