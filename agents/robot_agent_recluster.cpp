// RobotAgent's part in adaptive re-clustering (agents/recluster_agent.h). Only agents built with
// a ReclusterRouting run any of this.
#include <map>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "agents/recluster_agent.h"
#include "agents/robot_agent.h"

namespace dvpr {

void ReclusterPlan::Validate() const {
  auto fail = [](const std::string& what) { throw std::invalid_argument("re-clustering plan: " + what); };
  params.Validate();
  if (!initial) fail("no initial table");
  if (static_cast<int>(stream_first.size()) != initial->num_robots()) {
    fail("stream_first has " + std::to_string(stream_first.size()) + " robots, the table " +
         std::to_string(initial->num_robots()));
  }
  if (epochs < 0) fail("epochs must be >= 0");
  if (leader.value < 0 || leader.value >= initial->num_robots()) fail("leader is not a robot of the team");
  if (sample_timeout < SimTime::Zero()) fail("sample_timeout must be >= 0");
}

ReclusterRouting::ReclusterRouting(ReclusterPlan plan)
    : RoutingStrategy(plan.initial ? plan.initial->num_robots() : 1), plan_(std::move(plan)) {
  plan_.Validate();
}

namespace {

descriptor_batch_t NewBatch(SimTime now, int epoch, RobotId sender, int dim) {
  descriptor_batch_t b;
  b.utime = now.us();
  b.epoch = epoch;
  b.sender = static_cast<std::int16_t>(sender.value);
  b.count = 0;
  b.dim = static_cast<std::int16_t>(dim);
  return b;
}

void Append(descriptor_batch_t& b, RobotId robot, FrameId frame, const float* descriptor) {
  b.robots.push_back(static_cast<std::int16_t>(robot.value));
  b.frames.push_back(frame.value);
  b.descriptors.emplace_back(descriptor, descriptor + b.dim);
  ++b.count;
}

}  // namespace

RobotAgent::~RobotAgent() = default;

int RobotAgent::recluster_epoch() const { return recluster_ ? recluster_->epoch : 0; }
const CentroidTable* RobotAgent::recluster_table() const { return recluster_ ? recluster_->table.get() : nullptr; }

void RobotAgent::InitRecluster() {
  const auto* routing = dynamic_cast<const ReclusterRouting*>(&routing_);
  if (routing == nullptr) return;
  if (routing->plan().initial->dim() != frames_.descriptors->cols()) {
    throw std::invalid_argument("RobotAgent: re-clustering table and descriptors differ in dimension");
  }
  recluster_ = std::make_unique<ReclusterState>();
  recluster_->plan = &routing->plan();
  recluster_->table = routing->plan().initial;
}

void RobotAgent::StartRecluster() {
  const ReclusterPlan& plan = *recluster_->plan;
  subscriptions_.push_back(
      transport_.Subscribe<centroid_table_t>(channels::kTable, [this](const centroid_table_t& t) { OnTable(t); }));
  subscriptions_.push_back(transport_.Subscribe<descriptor_batch_t>(
      channels::Migrate(id_), [this](const descriptor_batch_t& b) { OnMigration(b); }));
  if (id_ == plan.leader) {
    subscriptions_.push_back(transport_.Subscribe<descriptor_batch_t>(
        channels::Sample(id_), [this](const descriptor_batch_t& b) { OnSample(b); }));
  }
  // Scheduled now, at t = 0: at a boundary the sample goes before the frame taken at that instant.
  for (int e = 1; e <= plan.epochs; ++e) {
    transport_.ScheduleAfter(frames_.TimeOf(e * plan.params.period), [this, e] { OnEpochBoundary(e); });
  }
}

RoutingDecision RobotAgent::ReclusterRoute(const float* descriptor) const {
  const RobotId owner = recluster_->table->RouteOf(descriptor);
  return RoutingDecision{{owner}, {owner}};
}

void RobotAgent::StoreOrForward(RobotId robot, FrameId frame, const float* descriptor) {
  const RobotId owner = recluster_->table->RouteOf(descriptor);
  if (owner == id_) {
    index_.Add(robot, frame, descriptor);
    ++load_.stored;
    return;
  }
  descriptor_batch_t b = NewBatch(transport_.Now(), recluster_->epoch, id_, index_.dim());
  Append(b, robot, frame, descriptor);
  transport_.Publish(channels::Migrate(owner), b);
}

void RobotAgent::OnEpochBoundary(int epoch) {
  if (!online_) return;
  const ReclusterPlan& plan = *recluster_->plan;
  descriptor_batch_t sample = NewBatch(transport_.Now(), epoch, id_, index_.dim());
  for (std::size_t i = 0; i < index_.size(); ++i) {
    const IndexEntry& e = index_.entries()[i];
    if (InReclusterSample(plan.StepOf(e.robot, e.frame), epoch, plan.params)) {
      Append(sample, e.robot, e.frame, index_.Descriptor(i));
    }
  }
  if (id_ != plan.leader) {
    transport_.Publish(channels::Sample(plan.leader), sample);
    return;
  }
  ReclusterState::Pending& pending = recluster_->pending[epoch];
  pending.own_taken = true;
  pending.from[id_.value] = std::move(sample);
  transport_.ScheduleAfter(plan.sample_timeout, [this, epoch] { LeaderCompute(epoch, true); });
  LeaderCompute(epoch, false);
}

void RobotAgent::OnSample(const descriptor_batch_t& b) {
  if (!online_ || b.epoch < 1 || b.epoch > recluster_->plan->epochs || b.dim != index_.dim()) return;
  if (b.sender < 0 || b.sender >= routing_.num_robots()) return;
  ReclusterState::Pending& pending = recluster_->pending[b.epoch];
  if (pending.done) return;  // late: the table went out without it
  pending.from[b.sender] = b;
  LeaderCompute(b.epoch, false);
}

// Waits for the leader's own sample and every robot's, or for the timeout; then clusters the
// union (frame-id order, each frame once) and publishes the table before moving its own store.
void RobotAgent::LeaderCompute(int epoch, bool timed_out) {
  if (!online_) return;
  const auto it = recluster_->pending.find(epoch);
  if (it == recluster_->pending.end()) return;
  ReclusterState::Pending& pending = it->second;
  if (pending.done || !pending.own_taken) return;
  if (!timed_out && static_cast<int>(pending.from.size()) < routing_.num_robots()) return;
  pending.done = true;
  std::map<int, const float*> rows;  // frame -> descriptor
  std::vector<RobotId> live;
  for (const auto& [sender, batch] : pending.from) {
    live.push_back(RobotId(sender));
    for (int i = 0; i < batch.count; ++i) rows.emplace(batch.frames[i], batch.descriptors[i].data());
  }
  if (epoch > recluster_->epoch && !rows.empty()) {  // else keep the table
    DescriptorMatrix sample(static_cast<Eigen::Index>(rows.size()), index_.dim());
    Eigen::Index r = 0;
    for (const auto& [frame, d] : rows) sample.row(r++) = Eigen::Map<const Eigen::RowVectorXf>(d, index_.dim());
    auto table = std::make_shared<const CentroidTable>(
        ReclusterTable(sample, live, routing_.num_robots(), recluster_->plan->params, epoch));
    centroid_table_t msg;
    msg.utime = transport_.Now().us();
    msg.epoch = epoch;
    msg.leader = static_cast<std::int16_t>(id_.value);
    msg.k = static_cast<std::int16_t>(table->num_centroids());
    msg.dim = static_cast<std::int16_t>(table->dim());
    for (int c = 0; c < table->num_centroids(); ++c) {
      const auto row = table->centroids().row(c);
      msg.centroids.emplace_back(row.data(), row.data() + row.size());
      msg.owners.push_back(static_cast<std::int16_t>(table->OwnerOf(c).value));
    }
    transport_.Publish(channels::kTable, msg);
    AdoptTable(std::move(table), epoch);
  }
  pending.from.clear();
}

void RobotAgent::OnTable(const centroid_table_t& t) {
  if (!online_ || t.epoch <= recluster_->epoch || t.dim != index_.dim() || t.k < 1) return;
  CentroidMatrix centroids(t.k, t.dim);
  std::vector<RobotId> owners;
  for (int c = 0; c < t.k; ++c) {
    centroids.row(c) = Eigen::Map<const Eigen::RowVectorXf>(t.centroids[static_cast<std::size_t>(c)].data(), t.dim);
    owners.push_back(RobotId(t.owners[static_cast<std::size_t>(c)]));
  }
  std::shared_ptr<const CentroidTable> table;
  try {
    table = std::make_shared<const CentroidTable>(std::move(centroids), std::move(owners), routing_.num_robots());
  } catch (const std::invalid_argument&) {
    return;  // an owner outside the team or a non-finite value: not a table of ours
  }
  AdoptTable(std::move(table), t.epoch);
}

// Switches to the table and sends every stored descriptor it now routes elsewhere to that
// owner, one batch per destination (destinations in id order, descriptors in store order).
void RobotAgent::AdoptTable(std::shared_ptr<const CentroidTable> table, int epoch) {
  recluster_->table = std::move(table);
  recluster_->epoch = epoch;
  std::map<int, descriptor_batch_t> moves;
  std::vector<bool> moved(index_.size(), false);
  for (std::size_t i = 0; i < index_.size(); ++i) {
    const RobotId owner = recluster_->table->RouteOf(index_.Descriptor(i));
    if (owner == id_) continue;
    auto [it, fresh] = moves.try_emplace(owner.value);
    if (fresh) it->second = NewBatch(transport_.Now(), epoch, id_, index_.dim());
    const IndexEntry& e = index_.entries()[i];
    Append(it->second, e.robot, e.frame, index_.Descriptor(i));
    moved[i] = true;
  }
  for (const auto& [dst, batch] : moves) {
    transport_.Publish(channels::Migrate(RobotId(dst)), batch);
    load_.stored -= batch.count;
  }
  index_.RemoveIf([&moved](std::size_t i) { return moved[i]; });
}

// A batch from a newer epoch is kept whole (this robot re-routes it when that table arrives);
// otherwise each descriptor is kept if this robot owns it under its own table, else forwarded.
void RobotAgent::OnMigration(const descriptor_batch_t& b) {
  if (!online_ || b.dim != index_.dim()) return;
  std::map<int, descriptor_batch_t> forward;
  for (int i = 0; i < b.count; ++i) {
    const float* d = b.descriptors[static_cast<std::size_t>(i)].data();
    const RobotId owner = b.epoch > recluster_->epoch ? id_ : recluster_->table->RouteOf(d);
    if (owner == id_) {
      index_.Add(RobotId(b.robots[static_cast<std::size_t>(i)]), FrameId(b.frames[static_cast<std::size_t>(i)]), d);
      ++load_.stored;
      continue;
    }
    auto [it, fresh] = forward.try_emplace(owner.value);
    if (fresh) it->second = NewBatch(transport_.Now(), recluster_->epoch, id_, index_.dim());
    Append(it->second, RobotId(b.robots[static_cast<std::size_t>(i)]), FrameId(b.frames[static_cast<std::size_t>(i)]), d);
  }
  for (const auto& [dst, batch] : forward) transport_.Publish(channels::Migrate(RobotId(dst)), batch);
}

}  // namespace dvpr
