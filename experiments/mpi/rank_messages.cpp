#include "experiments/mpi/rank_messages.h"

#include <cstring>
#include <optional>
#include <stdexcept>
#include <type_traits>

namespace dvpr {

namespace {

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
  void Put(const NetworkLabel& n) { Put(n.variant), Put(n.model), Put(n.bandwidth_bps), Put(n.latency_ms), Put(n.loss); }
  void Put(const RunKey& k) { Put(k.protocol), Put(k.strategy), Put(k.robots), Put(k.run), Put(k.network); }
  void Put(const RunResult& r) {
    Put(r.key), Put(r.seed), Put(r.auc), Put(r.auc_reference), Put(r.relative_auc), Put(r.worst_balance_ratio);
    Put(r.queries), Put(r.messages), Put(r.payload_bytes), Put(r.wire_bytes), Put(r.bytes_per_query);
    Put(r.mean_latency_ms), Put(r.p99_latency_ms), Put(r.dropped_messages);
  }
  void Put(const RobotLoadRow& r) {
    Put(r.key), Put(r.robot), Put(r.queries_received), Put(r.comparisons), Put(r.stored), Put(r.busy_fraction),
        Put(r.max_queue);
  }
  void Put(const LinkRow& r) {
    Put(r.key), Put(r.src), Put(r.dst), Put(r.messages), Put(r.payload_bytes), Put(r.wire_bytes), Put(r.dropped);
  }
  void Put(const QueryRow& r) {
    Put(r.key), Put(r.robot), Put(r.frame), Put(r.sent_ns), Put(r.match_robot), Put(r.match_frame);
    Put(r.distance), Put(r.latency_ns), Put(r.relevant), Put(r.correct);
  }
  void Put(const MessageRow& r) {
    Put(r.key), Put(r.sent_ns), Put(r.delivered_ns), Put(r.src), Put(r.dst), Put(r.channel), Put(r.type);
    Put(r.payload_bytes), Put(r.wire_bytes), Put(r.dropped);
  }
  void Put(const PrCurve& c) { Put(c.label), Put(c.robots), Put(c.run), Put(c.recall), Put(c.precision); }

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
  void Get(NetworkLabel& n) { Get(n.variant), Get(n.model), Get(n.bandwidth_bps), Get(n.latency_ms), Get(n.loss); }
  void Get(RunKey& k) { Get(k.protocol), Get(k.strategy), Get(k.robots), Get(k.run), Get(k.network); }
  void Get(RunResult& r) {
    Get(r.key), Get(r.seed), Get(r.auc), Get(r.auc_reference), Get(r.relative_auc), Get(r.worst_balance_ratio);
    Get(r.queries), Get(r.messages), Get(r.payload_bytes), Get(r.wire_bytes), Get(r.bytes_per_query);
    Get(r.mean_latency_ms), Get(r.p99_latency_ms), Get(r.dropped_messages);
  }
  void Get(RobotLoadRow& r) {
    Get(r.key), Get(r.robot), Get(r.queries_received), Get(r.comparisons), Get(r.stored), Get(r.busy_fraction),
        Get(r.max_queue);
  }
  void Get(LinkRow& r) {
    Get(r.key), Get(r.src), Get(r.dst), Get(r.messages), Get(r.payload_bytes), Get(r.wire_bytes), Get(r.dropped);
  }
  void Get(QueryRow& r) {
    Get(r.key), Get(r.robot), Get(r.frame), Get(r.sent_ns), Get(r.match_robot), Get(r.match_frame);
    Get(r.distance), Get(r.latency_ns), Get(r.relevant), Get(r.correct);
  }
  void Get(MessageRow& r) {
    Get(r.key), Get(r.sent_ns), Get(r.delivered_ns), Get(r.src), Get(r.dst), Get(r.channel), Get(r.type);
    Get(r.payload_bytes), Get(r.wire_bytes), Get(r.dropped);
  }
  void Get(PrCurve& c) { Get(c.label), Get(c.robots), Get(c.run), Get(c.recall), Get(c.precision); }

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
  w.Put(o.runs), w.Put(o.per_robot), w.Put(o.links), w.Put(o.queries), w.Put(o.messages), w.Put(o.curves);
  return w.Take();
}

IndexedOutput DecodeOutput(const Bytes8& bytes) {
  ByteReader r(bytes, "run output");
  std::uint64_t index = 0;
  IndexedOutput out;
  RunOutput& o = out.output;
  r.Get(index);
  r.Get(o.runs), r.Get(o.per_robot), r.Get(o.links), r.Get(o.queries), r.Get(o.messages), r.Get(o.curves);
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
