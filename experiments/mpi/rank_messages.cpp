#include "experiments/mpi/rank_messages.h"

#include <array>
#include <cstring>
#include <optional>
#include <stdexcept>
#include <type_traits>

namespace dvpr {

namespace {

// Each row type's fields, listed once: `f` is called with every field in order, so the writer
// and the reader cannot disagree and a field added to a row needs one line here. (A field left
// out would not travel, and the writing rank's folder would differ from a single process's;
// tests/mpi compares whole folders.)
template <typename F> void Fields(NetworkLabel& n, F&& f) { f(n.variant, n.model, n.bandwidth_bps, n.latency_ms, n.loss, n.queue_packets, n.mtu_bytes, n.propagation, n.range_m,
    n.next_hop); }
template <typename F> void Fields(RunKey& k, F&& f) { f(k.protocol, k.strategy, k.robots, k.run, k.network); }
template <typename F> void Fields(CopyBytes& c, F&& f) { f(c.payload, c.wire, c.delivered_payload, c.delivered_wire); }
template <typename F> void Fields(RunRoleBytes& r, F&& f) { f(r.copies, r.medium); }
template <typename F>
void Fields(RunClosures& r, F&& f) {
  f(r.inter_queries, r.intra_queries, r.inter_recognised, r.intra_recognised, r.inter_auc, r.intra_auc,
    r.inter_candidates, r.inter_closures, r.pairs_closed, r.median_first_closure_ns);
}
template <typename F>
void Fields(RunResult& r, F&& f) {
  f(r.key, r.seed, r.auc, r.auc_reference, r.relative_auc, r.worst_balance_ratio, r.queries, r.messages,
    r.payload_bytes, r.wire_bytes, r.bytes_per_query, r.mean_latency_ms, r.p99_latency_ms, r.dropped_messages,
    r.roles, r.duration_s, r.closures);
}
template <typename F>
void Fields(RobotLoadRow& r, F&& f) {
  f(r.key, r.robot, r.queries_received, r.comparisons, r.stored, r.busy_fraction, r.max_queue,
    r.relay_transmissions, r.relay_bytes, r.routing_transmissions, r.routing_bytes, r.mac_attempts, r.mac_backoffs,
    r.mac_collisions, r.mac_retries, r.mac_dropped_queue_full, r.mac_dropped_retry_limit, r.airtime_share);
}
template <typename F>
void Fields(LinkRow& r, F&& f) {
  f(r.key, r.src, r.dst, r.messages, r.payload_bytes, r.wire_bytes, r.dropped, r.roles);
}
template <typename F>
void Fields(QueryRow& r, F&& f) {
  f(r.key, r.robot, r.frame, r.sent_ns, r.match_robot, r.match_frame, r.distance, r.latency_ns, r.relevant,
    r.correct, r.query_class, r.hops);
}
template <typename F>
void Fields(MessageRow& r, F&& f) {
  f(r.key, r.sent_ns, r.delivered_ns, r.src, r.dst, r.channel, r.type, r.payload_bytes, r.wire_bytes, r.dropped,
    r.role, r.hops);
}
template <typename F> void Fields(PrCurve& c, F&& f) { f(c.label, c.robots, c.run, c.recall, c.precision); }
template <typename F>
void Fields(FailoverRow& r, F&& f) {
  f(r.key, r.robot, r.at_ns, r.detected_ns, r.stored, r.kept, r.incomplete_queries);
}
template <typename F>
void Fields(BowRow& r, F&& f) {
  f(r.key, r.queries, r.partial_queries, r.payload_bytes, r.mean_words, r.mean_part_words, r.part_bytes_p50,
    r.part_bytes_p90, r.part_bytes_max, r.voted, r.vote_not_centralized);
}
template <typename F> void Fields(BowSizeRow& r, F&& f) { f(r.key, r.payload_bytes, r.messages); }
template <typename F>
void Fields(RadioRow& r, F&& f) {
  f(r.key, r.delivered_copies, r.mean_hops, r.max_hops, r.relay_transmissions, r.relay_bytes, r.held_copies,
    r.routing_transmissions, r.routing_bytes, r.dropped, r.delivered_by_hops);
}
template <typename F>
void Fields(MediumRow& r, F&& f) {
  f(r.key, r.delivered_copies, r.attempts, r.backoffs, r.collisions, r.retries, r.airtime_ns, r.busy_ns,
    r.utilisation, r.dropped);
}
template <typename F>
void Fields(ConnectivityRow& r, F&& f) {
  f(r.key, r.time_ns, r.pairs_in_range, r.components, r.largest_component, r.mean_hops, r.max_hops,
    r.robots_in_range);
}
template <typename F> void Fields(ClosurePairRow& r, F&& f) { f(r.key, r.robot_a, r.robot_b, r.first_closure_ns); }
template <typename F>
void Fields(RunOutput& o, F&& f) {
  f(o.runs, o.per_robot, o.links, o.queries, o.messages, o.curves, o.failover, o.bow, o.bow_sizes, o.radio,
    o.medium, o.connectivity, o.closure_pairs);
}

template <typename T>
concept HasFields = requires(T& t) { Fields(t, [](auto&...) {}); };

class ByteWriter {
 public:
  template <typename T>
    requires std::is_arithmetic_v<T>
  void Put(T v) {
    const auto* p = reinterpret_cast<const std::byte*>(&v);
    bytes_.insert(bytes_.end(), p, p + sizeof v);
  }
  void Put(const std::string& s) {
    Put(static_cast<std::uint64_t>(s.size()));
    const auto* p = reinterpret_cast<const std::byte*>(s.data());
    bytes_.insert(bytes_.end(), p, p + s.size());
  }
  template <typename T>
  void Put(const std::optional<T>& v) {
    Put(v.has_value());
    if (v) Put(*v);
  }
  template <typename T>
  void Put(const std::vector<T>& v) {
    Put(static_cast<std::uint64_t>(v.size()));
    for (const T& x : v) Put(x);
  }
  template <typename T, std::size_t N>
  void Put(const std::array<T, N>& a) {
    for (const T& x : a) Put(x);
  }
  template <typename T>
    requires HasFields<T>
  void Put(const T& row) {
    // Fields() lists a row's members for reading and writing alike; the writer only reads them.
    Fields(const_cast<T&>(row), [this](const auto&... field) { (Put(field), ...); });
  }

  Bytes8 Take() { return std::move(bytes_); }

 private:
  Bytes8 bytes_;
};

class ByteReader {
 public:
  ByteReader(const Bytes8& bytes, const char* what) : bytes_(bytes), what_(what) {}

  template <typename T>
    requires std::is_arithmetic_v<T>
  void Get(T& v) {
    std::memcpy(&v, Take(sizeof v), sizeof v);
  }
  void Get(std::string& s) {
    const std::size_t n = Count(1);
    s.assign(reinterpret_cast<const char*>(Take(n)), n);
  }
  template <typename T>
  void Get(std::optional<T>& v) {
    bool has = false;
    Get(has);
    v.reset();
    if (has) Get(v.emplace());
  }
  template <typename T>
  void Get(std::vector<T>& v) {
    v.resize(Count(1));  // every element takes at least one byte: a corrupt count fails here
    for (T& x : v) Get(x);
  }
  template <typename T, std::size_t N>
  void Get(std::array<T, N>& a) {
    for (T& x : a) Get(x);
  }
  template <typename T>
    requires HasFields<T>
  void Get(T& row) {
    Fields(row, [this](auto&... field) { (Get(field), ...); });
  }

  // Every byte has been read.
  void End() const {
    if (at_ != bytes_.size()) Fail(std::to_string(bytes_.size() - at_) + " bytes left over");
  }

 private:
  // A count of elements of at least `min_size` bytes each that the remaining bytes can hold.
  std::size_t Count(std::size_t min_size) {
    std::uint64_t n = 0;
    Get(n);
    if (n > (bytes_.size() - at_) / min_size) Fail("a count of " + std::to_string(n) + " past the end");
    return static_cast<std::size_t>(n);
  }
  const std::byte* Take(std::size_t n) {
    if (n > bytes_.size() - at_) Fail("short by " + std::to_string(n - (bytes_.size() - at_)) + " bytes");
    const std::byte* p = bytes_.data() + at_;
    at_ += n;
    return p;
  }
  [[noreturn]] void Fail(const std::string& why) const {
    throw std::logic_error(std::string("a malformed ") + what_ + " message from another rank: " + why);
  }

  const Bytes8& bytes_;
  const char* what_;
  std::size_t at_ = 0;
};

}  // namespace

Bytes8 EncodeOutput(std::size_t index, const RunOutput& o) {
  ByteWriter w;
  w.Put(static_cast<std::uint64_t>(index));
  w.Put(o);
  return w.Take();
}

IndexedOutput DecodeOutput(const Bytes8& bytes) {
  ByteReader r(bytes, "run output");
  std::uint64_t index = 0;
  IndexedOutput out;
  RunOutput& o = out.output;
  r.Get(index);
  r.Get(o);
  r.End();
  out.index = static_cast<std::size_t>(index);
  return out;
}

Bytes8 EncodeFile(const RunFile& file) {
  ByteWriter w;
  w.Put(file.path), w.Put(file.contents);
  return w.Take();
}

RunFile DecodeFile(const Bytes8& bytes) {
  ByteReader r(bytes, "file");
  RunFile file;
  r.Get(file.path), r.Get(file.contents);
  r.End();
  return file;
}

Bytes8 EncodeFailure(const RankFailure& failure) {
  ByteWriter w;
  w.Put(static_cast<std::int32_t>(failure.kind)), w.Put(failure.message);
  return w.Take();
}

RankFailure DecodeFailure(const Bytes8& bytes) {
  ByteReader r(bytes, "failure");
  std::int32_t kind = 0;
  RankFailure failure;
  r.Get(kind), r.Get(failure.message);
  r.End();
  if (kind != 0 && kind != 1) throw std::logic_error("a failure message of unknown kind " + std::to_string(kind));
  failure.kind = static_cast<FailureKind>(kind);
  return failure;
}

}  // namespace dvpr
