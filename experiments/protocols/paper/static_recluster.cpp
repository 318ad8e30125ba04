#include "experiments/protocols/paper/static_recluster.h"

#include <algorithm>
#include <map>
#include <stdexcept>
#include <string>
#include <utility>

#include "agents/recluster/recluster_messages.h"
#include "experiments/domain/data/split.h"

namespace dvpr {

bool StaticReclusterPlan::Candidates(std::int64_t i, std::int64_t j) const {
  const auto ui = static_cast<std::size_t>(i), uj = static_cast<std::size_t>(j);
  const auto& r = route[static_cast<std::size_t>(std::max(epoch[ui], epoch[uj]))];
  return r[ui] == r[uj];
}

std::vector<int> ReclusterSampleFrames(const std::vector<int>& step, int epoch, const ReclusterParams& params) {
  std::vector<int> frames;
  for (std::size_t i = 0; i < step.size(); ++i) {
    if (InReclusterSample(step[i], epoch, params)) frames.push_back(static_cast<int>(i));
  }
  return frames;
}

namespace {

// Steps of every frame and the longest stream.
std::pair<std::vector<int>, int> Steps(int frames, int robots) {
  const SequenceSplit split = SplitSequence(frames, robots);
  std::vector<int> step(static_cast<std::size_t>(frames));
  int longest = 0;
  for (const FrameRange& r : split.ranges) {
    longest = std::max(longest, r.size());
    for (int f = r.begin.value; f < r.end.value; ++f) step[static_cast<std::size_t>(f)] = f - r.begin.value;
  }
  return {std::move(step), longest};
}

DescriptorMatrix Rows(const DescriptorMatrix& x, const std::vector<int>& frames) {
  DescriptorMatrix out(static_cast<Eigen::Index>(frames.size()), x.cols());
  for (std::size_t r = 0; r < frames.size(); ++r) out.row(static_cast<Eigen::Index>(r)) = x.row(frames[r]);
  return out;
}

}  // namespace

StaticReclusterPlan MakeStaticReclusterPlan(const DescriptorMatrix& deployment, int robots,
                                            std::vector<std::shared_ptr<const CentroidTable>> tables,
                                            const ReclusterParams& params) {
  params.Validate();
  auto [step, longest] = Steps(static_cast<int>(deployment.rows()), robots);
  const int epochs = ReclusterEpochs(longest, params);
  if (static_cast<int>(tables.size()) != epochs + 1) {
    throw std::invalid_argument("re-clustering plan: " + std::to_string(epochs + 1) + " tables needed, got " +
                                std::to_string(tables.size()));
  }
  StaticReclusterPlan plan;
  plan.params = params;
  plan.robots = robots;
  plan.tables = std::move(tables);
  plan.step = std::move(step);
  for (int s : plan.step) plan.epoch.push_back(ReclusterEpochOf(s, params));
  for (const auto& t : plan.tables) plan.route.push_back(t->RouteAll(deployment));
  return plan;
}

StaticReclusterPlan PlanStaticRecluster(const DescriptorMatrix& deployment, std::shared_ptr<const CentroidTable> initial,
                                        const ReclusterParams& params) {
  const int robots = initial->num_robots();
  const auto [step, longest] = Steps(static_cast<int>(deployment.rows()), robots);
  std::vector<RobotId> live;
  for (int r = 0; r < robots; ++r) live.push_back(RobotId(r));
  std::vector<std::shared_ptr<const CentroidTable>> tables{std::move(initial)};
  for (int e = 1; e <= ReclusterEpochs(longest, params); ++e) {
    const DescriptorMatrix sample = Rows(deployment, ReclusterSampleFrames(step, e, params));
    tables.push_back(std::make_shared<const CentroidTable>(ReclusterTable(sample, live, robots, params, e)));
  }
  return MakeStaticReclusterPlan(deployment, robots, std::move(tables), params);
}

ReclusterTraffic CountReclusterTraffic(const StaticReclusterPlan& plan, int dim, RobotId leader) {
  ReclusterTraffic t;
  const int n = plan.robots;
  for (int e = 1; e <= plan.epochs(); ++e) {
    const auto& before = plan.route[static_cast<std::size_t>(e - 1)];
    const auto& after = plan.route[static_cast<std::size_t>(e)];
    std::vector<std::int64_t> held(static_cast<std::size_t>(n), 0);  // sample frames per robot
    std::map<std::pair<int, int>, std::int64_t> moves;                // (from, to) -> frames
    for (std::size_t f = 0; f < plan.step.size(); ++f) {
      if (plan.epoch[f] >= e) continue;  // not taken yet at the boundary
      if (InReclusterSample(plan.step[f], e, plan.params)) ++held[static_cast<std::size_t>(before[f].value)];
      if (before[f] != after[f]) ++moves[{before[f].value, after[f].value}];
    }
    for (int r = 0; r < n; ++r) {
      if (r == leader.value) continue;
      ++t.sample_messages;
      t.sample_bytes += DescriptorBatchBytes(held[static_cast<std::size_t>(r)], dim);
    }
    t.table_messages += n - 1;
    t.table_bytes += (n - 1) * CentroidTableBytes(plan.tables[static_cast<std::size_t>(e)]->num_centroids(), dim);
    for (const auto& [pair, count] : moves) {
      ++t.migration_messages;
      t.migration_bytes += DescriptorBatchBytes(count, dim);
      t.migrated += count;
    }
  }
  return t;
}

PaperRunResult EvaluateRecluster(const PaperEvaluator& evaluator, const StaticReclusterPlan& plan,
                                 const std::string& name, bool keep_curve) {
  const Dataset& data = evaluator.deployment();
  const std::int64_t n_frames = data.size();
  if (static_cast<std::int64_t>(plan.step.size()) != n_frames) {
    throw std::invalid_argument("EvaluateRecluster: the plan is for another sequence");
  }
  const auto candidate = [&plan](std::int64_t i, std::int64_t j) { return plan.Candidates(i, j); };
  PaperRunResult result;
  const auto matches = evaluator.neighbours().BestMatchesWhere(candidate, &result.fallback_scans);
  PrResult pr = EvaluatePr(matches, data.trajectory.positions, evaluator.evaluation().radius_m, evaluator.relevant());
  const auto robots = static_cast<std::size_t>(plan.robots);
  std::vector<std::int64_t> searches(robots, 0), stored(robots, 0), comparisons(robots, 0);
  const int window = evaluator.evaluation().suppression_frames;
  for (std::int64_t i = 0; i < n_frames; ++i) {
    const auto at = static_cast<std::size_t>(plan.SearchedAt(static_cast<std::size_t>(i)).value);
    ++searches[at];
    ++stored[static_cast<std::size_t>(plan.FinalOwner(static_cast<std::size_t>(i)).value)];
    for (std::int64_t j = 0; j < n_frames; ++j) {
      if ((j < i - window || j > i + window) && candidate(i, j)) ++comparisons[at];
    }
  }
  const ReclusterTraffic traffic = CountReclusterTraffic(plan, static_cast<int>(data.descriptors.cols()));
  evaluator.FillResult(name, std::move(pr), searches, comparisons, stored, keep_curve, result);
  result.row.messages = traffic.messages();
  result.row.payload_bytes = traffic.bytes();
  return result;
}

}  // namespace dvpr
