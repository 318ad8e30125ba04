// The LCM decoders as the agents use them: a datagram from the network goes to Decode<Msg>
// (agents/messages/lcm_codec.h) of the type its channel carries. The input is the datagram, decoded as
// every dvpr message type. Properties:
// - Decode never crashes, reads out of bounds or allocates more than the datagram can describe
//   (libFuzzer's -malloc_limit_mb turns a huge allocation into a failure);
// - a datagram that decodes is exactly what Encode writes for the decoded message.
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <span>
#include <string>

#include <dvpr/agent_status_t.hpp>

#include "agents/messages/lcm_codec.h"
#include "tests/fuzz/fuzz_support.h"

namespace {

template <typename Msg>
void DecodeAs(std::span<const std::uint8_t> datagram) {
  const auto msg = dvpr::Decode<Msg>(datagram);
  if (!msg) return;
  const auto encoded = dvpr::Encode(*msg);
  if (!std::equal(encoded.begin(), encoded.end(), datagram.begin(), datagram.end())) {
    dvpr::fuzz::Violated(std::string("a decoded ") + Msg::getTypeName() + " encodes differently");
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::span<const std::uint8_t> datagram(data, size);
  DecodeAs<dvpr::query_t>(datagram);
  DecodeAs<dvpr::match_t>(datagram);
  DecodeAs<dvpr::verify_request_t>(datagram);
  DecodeAs<dvpr::verify_result_t>(datagram);
  DecodeAs<dvpr::descriptor_batch_t>(datagram);
  DecodeAs<dvpr::centroid_table_t>(datagram);
  DecodeAs<dvpr::agent_status_t>(datagram);
  DecodeAs<dvpr::bow_query_t>(datagram);
  DecodeAs<dvpr::bow_match_t>(datagram);
  return 0;
}
