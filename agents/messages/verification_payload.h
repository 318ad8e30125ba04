#pragma once
// The payload of a verify_request_t: what a real robot would send for geometric verification,
// the query frame's keypoints and their local descriptors (tens of kilobytes). dvpr has no
// images, so the bytes stand for them: derived from the frame alone (its id and global
// descriptor), the same in every run and on every robot, and different from frame to frame, so
// a recorded log shows a payload that varies as real ones do instead of zeros.
//
// Bytes: SplitMix64 (sim/random_bits.h) seeded with the 64-bit FNV-1a hash of the frame id
// (int32, little-endian) followed by the descriptor's floats (little-endian IEEE 754), each
// 64-bit output written little-endian, cut to `size`.
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "agents/algorithms/ids.h"

namespace dvpr {

std::vector<std::uint8_t> VerificationPayload(FrameId frame, std::span<const float> descriptor, std::size_t size);
// The same bytes written over `out` (its size is the payload's): a robot fills the request it
// reuses, without a new buffer or zeroing one first.
void FillVerificationPayload(FrameId frame, std::span<const float> descriptor, std::span<std::uint8_t> out);

}  // namespace dvpr
