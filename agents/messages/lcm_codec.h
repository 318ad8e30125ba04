#pragma once
// Encoding and defensive decoding of dvpr's LCM messages.
//
// The simulator reports the bytes that Encode() produces: the LCM encoding with
// its 8-byte type fingerprint. Decode() never trusts its input: it is also used
// on datagrams received from a real network, where a truncated, foreign or
// garbage buffer must be rejected, not crash the agent or make it allocate the
// gigabytes a garbage length field may claim.
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

#include <dvpr/bow_match_t.hpp>
#include <dvpr/bow_query_t.hpp>
#include <dvpr/centroid_table_t.hpp>
#include <dvpr/descriptor_batch_t.hpp>
#include <dvpr/match_t.hpp>
#include <dvpr/query_t.hpp>
#include <dvpr/verify_request_t.hpp>
#include <dvpr/verify_result_t.hpp>

namespace dvpr {

// Encodes msg over `buf`, resized to the encoding's size (a buffer reused from an earlier
// message keeps its allocation).
template <typename Msg>
void EncodeInto(const Msg& msg, std::vector<std::uint8_t>& buf) {
  buf.resize(static_cast<std::size_t>(msg.getEncodedSize()));
  const int n = msg.encode(buf.data(), 0, static_cast<int>(buf.size()));
  if (n != static_cast<int>(buf.size())) {
    throw std::runtime_error(std::string("LCM encoding of ") + Msg::getTypeName() +
                             " failed (a length field disagrees with its array?)");
  }
}

template <typename Msg>
std::vector<std::uint8_t> Encode(const Msg& msg) {
  std::vector<std::uint8_t> buf;
  EncodeInto(msg, buf);
  return buf;
}

namespace codec_detail {
// Reads a big-endian integer of LCM's encoding at `offset`, if it is there.
inline std::optional<std::int64_t> ReadBigEndian(std::span<const std::uint8_t> buf,
                                                 std::size_t offset, std::size_t width) {
  if (offset + width > buf.size()) return std::nullopt;
  std::uint64_t v = 0;
  for (std::size_t i = 0; i < width; ++i) v = (v << 8) | buf[offset + i];
  if (width == 2) return static_cast<std::int16_t>(v);
  if (width == 4) return static_cast<std::int32_t>(v);
  return static_cast<std::int64_t>(v);
}

// True when the message's variable-length field claims no more elements than
// the buffer can hold. Generated decoders resize the array before checking
// the buffer length, so this check must come first.
template <typename Msg>
bool LengthFieldFits(std::span<const std::uint8_t>) { return true; }

template <>
inline bool LengthFieldFits<query_t>(std::span<const std::uint8_t> buf) {
  constexpr std::size_t kDimOffset = 8 + 8 + 2 + 4 + 8;  // fingerprint, utime, robot, frame, capture_utime
  const auto dim = ReadBigEndian(buf, kDimOffset, 2);
  if (!dim) return false;
  const auto room = (buf.size() - (kDimOffset + 2)) / sizeof(float);
  return *dim >= 0 && static_cast<std::size_t>(*dim) <= room;
}

template <>
inline bool LengthFieldFits<verify_request_t>(std::span<const std::uint8_t> buf) {
  constexpr std::size_t kSizeOffset = 8 + 8 + 2 + 4 + 2 + 4;  // ... match_robot, match_frame
  const auto size = ReadBigEndian(buf, kSizeOffset, 4);
  if (!size) return false;
  return *size >= 0 && static_cast<std::size_t>(*size) <= buf.size() - (kSizeOffset + 4);
}
// Re-clustering messages (agents/recluster/recluster_messages.h): rows x (per-row bytes) must fit.
inline bool RowsFit(std::span<const std::uint8_t> buf, std::size_t header, std::optional<std::int64_t> rows,
                    std::optional<std::int64_t> dim, std::int64_t fixed_per_row) {
  if (!rows || !dim || *rows < 0 || *dim < 0 || buf.size() < header) return false;
  const auto per_row = static_cast<std::uint64_t>(fixed_per_row + 4 * *dim);
  return static_cast<std::uint64_t>(*rows) * per_row <= buf.size() - header;
}

template <>
inline bool LengthFieldFits<descriptor_batch_t>(std::span<const std::uint8_t> buf) {
  constexpr std::size_t kCountOffset = 8 + 8 + 4 + 2;  // fingerprint, utime, epoch, sender
  return RowsFit(buf, kCountOffset + 6, ReadBigEndian(buf, kCountOffset, 4), ReadBigEndian(buf, kCountOffset + 4, 2),
                 2 + 4);
}

template <>
inline bool LengthFieldFits<centroid_table_t>(std::span<const std::uint8_t> buf) {
  constexpr std::size_t kKOffset = 8 + 8 + 4 + 2;  // fingerprint, utime, epoch, leader
  return RowsFit(buf, kKOffset + 4, ReadBigEndian(buf, kKOffset, 2), ReadBigEndian(buf, kKOffset + 2, 2), 2);
}

// bow_query_t (docs/bow.md): count words and count weights, 8 bytes per entry, must fit.
template <>
inline bool LengthFieldFits<bow_query_t>(std::span<const std::uint8_t> buf) {
  constexpr std::size_t kCountOffset = 8 + 8 + 2 + 4;  // fingerprint, utime, robot, frame
  const auto count = ReadBigEndian(buf, kCountOffset, 4);
  if (!count || *count < 0) return false;
  return static_cast<std::uint64_t>(*count) * 8 <= buf.size() - (kCountOffset + 4);
}
}  // namespace codec_detail

namespace codec_detail {
// What decoding into a message decoded before takes. Generated decoders resize an array only
// when its length is not zero, so an array left from the last message would survive an empty
// one: the types with arrays on a hot path empty it afterwards when the length is 0 (and keep
// their capacity, a same-sized array is not even refilled with zeros first); every other type
// starts afresh.
template <typename Msg>
struct ReuseForDecode {
  static void Before(Msg& msg) { msg = Msg(); }
  static void After(Msg&) {}
};
template <>
struct ReuseForDecode<query_t> {
  static void Before(query_t&) {}
  static void After(query_t& msg) {
    if (msg.dim == 0) msg.descriptor.clear();
  }
};
template <>
struct ReuseForDecode<verify_request_t> {
  static void Before(verify_request_t&) {}
  static void After(verify_request_t& msg) {
    if (msg.payload_size == 0) msg.payload.clear();
  }
};
}  // namespace codec_detail

// Decodes a whole buffer into `msg`, reusing what it holds (its arrays' capacity): no
// allocation per message once warm. False when the buffer is truncated, too long, of another
// type (fingerprint mismatch) or inconsistent; `msg` is then unspecified.
template <typename Msg>
bool DecodeInto(std::span<const std::uint8_t> buf, Msg& msg) {
  if (buf.size() > static_cast<std::size_t>(INT32_MAX)) return false;
  if (!codec_detail::LengthFieldFits<Msg>(buf)) return false;
  codec_detail::ReuseForDecode<Msg>::Before(msg);
  int n = -1;
  try {
    n = msg.decode(buf.data(), 0, static_cast<int>(buf.size()));
  } catch (const std::exception&) {
    return false;
  }
  if (n != static_cast<int>(buf.size())) return false;
  codec_detail::ReuseForDecode<Msg>::After(msg);
  return true;
}

namespace codec_detail {
// LCM's integers are big-endian.
inline std::uint16_t Load16(const std::uint8_t* p) {
  std::uint16_t v;
  std::memcpy(&v, p, sizeof v);
  return __builtin_bswap16(v);
}
inline std::uint32_t Load32(const std::uint8_t* p) {
  std::uint32_t v;
  std::memcpy(&v, p, sizeof v);
  return __builtin_bswap32(v);
}
inline std::uint64_t Load64(const std::uint8_t* p) {
  std::uint64_t v;
  std::memcpy(&v, p, sizeof v);
  return __builtin_bswap64(v);
}
}  // namespace codec_detail

// query_t, the message every search starts from (99 copies of each broadcast frame): its fields
// read as its generated decoder reads them, the descriptor in one loop the compiler vectorises
// (the generated one assembles each float from 4 shifted bytes: 6 % of the 100-robot broadcast's
// instructions). The same values and the same rejections (truncated, trailing bytes, another
// type, a negative dim); tests compare it with the generated decoder.
template <>
inline bool DecodeInto<query_t>(std::span<const std::uint8_t> buf, query_t& msg) {
  using namespace codec_detail;
  constexpr std::size_t kHeader = 8 + 8 + 2 + 4 + 8 + 2;  // fingerprint, utime, robot, frame, capture_utime, dim
  if (buf.size() < kHeader) return false;
  const std::uint8_t* p = buf.data();
  if (static_cast<std::int64_t>(Load64(p)) != query_t::getHash()) return false;
  const auto dim = static_cast<std::int16_t>(Load16(p + 30));
  if (dim < 0 || buf.size() != kHeader + 4 * static_cast<std::size_t>(dim)) return false;
  msg.utime = static_cast<std::int64_t>(Load64(p + 8));
  msg.robot = static_cast<std::int16_t>(Load16(p + 16));
  msg.frame = static_cast<std::int32_t>(Load32(p + 18));
  msg.capture_utime = static_cast<std::int64_t>(Load64(p + 22));
  msg.dim = dim;
  msg.descriptor.resize(static_cast<std::size_t>(dim));
  float* out = msg.descriptor.data();
  for (std::size_t i = 0; i < static_cast<std::size_t>(dim); ++i) {
    const std::uint32_t bits = Load32(p + kHeader + 4 * i);
    std::memcpy(out + i, &bits, sizeof bits);
  }
  return true;
}

// match_t, the reply to every search (99 a broadcast frame), read field by field as its
// generated decoder reads it (which calls a function per field: 3 % of the 100-robot broadcast's
// samples): the same values and the same rejections (not 35 bytes, another type); tests compare
// it with the generated decoder.
template <>
inline bool DecodeInto<match_t>(std::span<const std::uint8_t> buf, match_t& msg) {
  using namespace codec_detail;
  // fingerprint, utime, query_robot, query_frame, responder, has_match, match_robot, match_frame, distance
  constexpr std::size_t kSize = 8 + 8 + 2 + 4 + 2 + 1 + 2 + 4 + 4;
  if (buf.size() != kSize) return false;
  const std::uint8_t* p = buf.data();
  if (static_cast<std::int64_t>(Load64(p)) != match_t::getHash()) return false;
  msg.utime = static_cast<std::int64_t>(Load64(p + 8));
  msg.query_robot = static_cast<std::int16_t>(Load16(p + 16));
  msg.query_frame = static_cast<std::int32_t>(Load32(p + 18));
  msg.responder = static_cast<std::int16_t>(Load16(p + 22));
  msg.has_match = static_cast<std::int8_t>(p[24]);
  msg.match_robot = static_cast<std::int16_t>(Load16(p + 25));
  msg.match_frame = static_cast<std::int32_t>(Load32(p + 27));
  const std::uint32_t bits = Load32(p + 31);
  std::memcpy(&msg.distance, &bits, sizeof bits);
  return true;
}

// Decodes a whole buffer into a new Msg. Empty when DecodeInto fails.
template <typename Msg>
std::optional<Msg> Decode(std::span<const std::uint8_t> buf) {
  Msg msg;
  if (!DecodeInto(buf, msg)) return std::nullopt;
  return msg;
}

}  // namespace dvpr
