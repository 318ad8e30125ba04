#include "agents/recluster/recluster_agent.h"

#include <map>
#include <stdexcept>
#include <utility>
#include <vector>

#include "agents/algorithms/descriptor_index.h"
#include "agents/algorithms/frame_stream.h"
#include "agents/placement/placement.h"
#include "agents/recluster/recluster_messages.h"

namespace dvpr {

namespace {

void Append(descriptor_batch_t& b, RobotId robot, FrameId frame, const float* descriptor) {
  b.robots.push_back(static_cast<std::int16_t>(robot.value));
  b.frames.push_back(frame.value);
  b.descriptors.emplace_back(descriptor, descriptor + b.dim);
  ++b.count;
}

}  // namespace

ReclusterAgentPlacement::ReclusterAgentPlacement(const ReclusterPlan& plan) : plan_(plan), table_(plan.initial) {}

descriptor_batch_t ReclusterAgentPlacement::NewBatch(int epoch) const {
  descriptor_batch_t b;
  b.utime = transport_->Utime();
  b.epoch = epoch;
  b.sender = static_cast<std::int16_t>(self_.value);
  b.count = 0;
  b.dim = static_cast<std::int16_t>(store_->dim());
  return b;
}

void ReclusterAgentPlacement::Start(const AgentContext& robot) {
  if (plan_.initial->dim() != robot.store.dim()) {
    throw std::invalid_argument("re-clustering: the table and the robot's descriptors differ in dimension");
  }
  self_ = robot.self;
  transport_ = &robot.transport;
  store_ = &robot.store;
  subscriptions_.push_back(
      transport_->Subscribe<centroid_table_t>(channels::kTable, [this](const centroid_table_t& t) { OnTable(t); }));
  subscriptions_.push_back(transport_->Subscribe<descriptor_batch_t>(
      channels::Migrate(self_), [this](const descriptor_batch_t& b) { OnMigration(b); }));
  if (self_ == plan_.leader) {
    subscriptions_.push_back(transport_->Subscribe<descriptor_batch_t>(
        channels::Sample(self_), [this](const descriptor_batch_t& b) { OnSample(b); }));
  }
  // Scheduled now, at t = 0: at a boundary the sample goes before the frame taken at that instant.
  for (int e = 1; e <= plan_.epochs; ++e) {
    transport_->ScheduleAfter(robot.frames.TimeOf(e * plan_.params.period), [this, e] { OnEpochBoundary(e); });
  }
}

// The owner under this robot's current table searches and stores.
QueryPlan ReclusterAgentPlacement::Plan(const float* descriptor) const {
  const RobotId owner = table_->RouteOf(descriptor);
  return PlanOf(PlacementDecision{{owner}, {owner}}, self_, false);
}

void ReclusterAgentPlacement::Store(RobotId querier, FrameId frame, const float* descriptor) {
  const RobotId owner = table_->RouteOf(descriptor);
  if (owner == self_) {
    store_->Add(querier, frame, descriptor);
    return;
  }
  descriptor_batch_t b = NewBatch(epoch_);
  Append(b, querier, frame, descriptor);
  transport_->Publish(channels::Migrate(owner), b);
}

void ReclusterAgentPlacement::OnEpochBoundary(int epoch) {
  if (!online_) return;
  descriptor_batch_t sample = NewBatch(epoch);
  for (std::size_t i = 0; i < store_->size(); ++i) {
    const IndexEntry& e = store_->entries()[i];
    if (InReclusterSample(plan_.StepOf(e.robot, e.frame), epoch, plan_.params)) {
      Append(sample, e.robot, e.frame, store_->Descriptor(i));
    }
  }
  if (self_ != plan_.leader) {
    transport_->Publish(channels::Sample(plan_.leader), sample);
    return;
  }
  Pending& pending = pending_[epoch];
  pending.own_taken = true;
  pending.from[self_.value] = std::move(sample);
  transport_->ScheduleAfter(plan_.sample_timeout, [this, epoch] { LeaderCompute(epoch, true); });
  LeaderCompute(epoch, false);
}

void ReclusterAgentPlacement::OnSample(const descriptor_batch_t& b) {
  if (!online_ || b.epoch < 1 || b.epoch > plan_.epochs || b.dim != store_->dim()) return;
  if (b.sender < 0 || b.sender >= plan_.initial->num_robots()) return;
  Pending& pending = pending_[b.epoch];
  if (pending.done) return;  // late: the table went out without it
  pending.from[b.sender] = b;
  LeaderCompute(b.epoch, false);
}

// Waits for the leader's own sample and every robot's, or for the timeout; then clusters the
// union (frame-id order, each frame once) and publishes the table before moving its own store.
void ReclusterAgentPlacement::LeaderCompute(int epoch, bool timed_out) {
  if (!online_) return;
  const auto it = pending_.find(epoch);
  if (it == pending_.end()) return;
  Pending& pending = it->second;
  const int robots = plan_.initial->num_robots();
  if (pending.done || !pending.own_taken) return;
  if (!timed_out && static_cast<int>(pending.from.size()) < robots) return;
  pending.done = true;
  std::map<int, const float*> rows;  // frame -> descriptor
  std::vector<RobotId> live;
  for (const auto& [sender, batch] : pending.from) {
    live.push_back(RobotId(sender));
    for (int i = 0; i < batch.count; ++i) rows.emplace(batch.frames[i], batch.descriptors[i].data());
  }
  if (epoch > epoch_ && !rows.empty()) {  // else keep the table
    const int dim = store_->dim();
    DescriptorMatrix sample(static_cast<Eigen::Index>(rows.size()), dim);
    Eigen::Index r = 0;
    for (const auto& [frame, d] : rows) sample.row(r++) = Eigen::Map<const Eigen::RowVectorXf>(d, dim);
    PublishTable(std::make_shared<const CentroidTable>(ReclusterTable(sample, live, robots, plan_.params, epoch)),
                 epoch);
  }
  pending.from.clear();
}

void ReclusterAgentPlacement::PublishTable(std::shared_ptr<const CentroidTable> table, int epoch) {
  centroid_table_t msg;
  msg.utime = transport_->Utime();
  msg.epoch = epoch;
  msg.leader = static_cast<std::int16_t>(self_.value);
  msg.k = static_cast<std::int16_t>(table->num_centroids());
  msg.dim = static_cast<std::int16_t>(table->dim());
  for (int c = 0; c < table->num_centroids(); ++c) {
    const auto row = table->centroids().row(c);
    msg.centroids.emplace_back(row.data(), row.data() + row.size());
    msg.owners.push_back(static_cast<std::int16_t>(table->OwnerOf(c).value));
  }
  transport_->Publish(channels::kTable, msg);
  AdoptTable(std::move(table), epoch);
}

void ReclusterAgentPlacement::OnTable(const centroid_table_t& t) {
  if (!online_ || t.epoch <= epoch_ || t.dim != store_->dim() || t.k < 1) return;
  CentroidMatrix centroids(t.k, t.dim);
  std::vector<RobotId> owners;
  for (int c = 0; c < t.k; ++c) {
    centroids.row(c) = Eigen::Map<const Eigen::RowVectorXf>(t.centroids[static_cast<std::size_t>(c)].data(), t.dim);
    owners.push_back(RobotId(t.owners[static_cast<std::size_t>(c)]));
  }
  std::shared_ptr<const CentroidTable> table;
  try {
    table = std::make_shared<const CentroidTable>(std::move(centroids), std::move(owners), plan_.initial->num_robots());
  } catch (const std::invalid_argument&) {
    return;  // an owner outside the team or a non-finite value: not a table of ours
  }
  AdoptTable(std::move(table), t.epoch);
}

// Switches to the table and sends every stored descriptor it now routes elsewhere to that
// owner, one batch per destination (destinations in id order, descriptors in store order).
void ReclusterAgentPlacement::AdoptTable(std::shared_ptr<const CentroidTable> table, int epoch) {
  table_ = std::move(table);
  epoch_ = epoch;
  std::map<int, descriptor_batch_t> moves;
  std::vector<bool> moved(store_->size(), false);
  for (std::size_t i = 0; i < store_->size(); ++i) {
    const RobotId owner = table_->RouteOf(store_->Descriptor(i));
    if (owner == self_) continue;
    auto [it, fresh] = moves.try_emplace(owner.value);
    if (fresh) it->second = NewBatch(epoch);
    const IndexEntry& e = store_->entries()[i];
    Append(it->second, e.robot, e.frame, store_->Descriptor(i));
    moved[i] = true;
  }
  for (const auto& [dst, batch] : moves) transport_->Publish(channels::Migrate(RobotId(dst)), batch);
  store_->RemoveIf([&moved](std::size_t i) { return moved[i]; });
}

// A batch from a newer epoch is kept whole (this robot re-routes it when that table arrives);
// otherwise each descriptor is kept if this robot owns it under its own table, else forwarded.
void ReclusterAgentPlacement::OnMigration(const descriptor_batch_t& b) {
  if (!online_ || b.dim != store_->dim()) return;
  std::map<int, descriptor_batch_t> forward;
  for (int i = 0; i < b.count; ++i) {
    const auto row = static_cast<std::size_t>(i);
    const float* d = b.descriptors[row].data();
    const RobotId owner = b.epoch > epoch_ ? self_ : table_->RouteOf(d);
    if (owner == self_) {
      store_->Add(RobotId(b.robots[row]), FrameId(b.frames[row]), d);
      continue;
    }
    auto [it, fresh] = forward.try_emplace(owner.value);
    if (fresh) it->second = NewBatch(epoch_);
    Append(it->second, RobotId(b.robots[row]), FrameId(b.frames[row]), d);
  }
  for (const auto& [dst, batch] : forward) transport_->Publish(channels::Migrate(RobotId(dst)), batch);
}

}  // namespace dvpr
