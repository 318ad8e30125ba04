// The verification request's payload: bytes derived from the frame (id and descriptor), not zeros.
// Expected bytes from an independent implementation in python3 (struct, 64-bit FNV-1a over
// pack('<i', frame) + pack('<2f', *descriptor), then SplitMix64 words packed '<Q'):
//   frame 3, (1.0, 2.0): 5d 09 d1 99 ea 69 0a aa b7 e0 c0 ce
//   frame 4, (1.0, 2.0): 77 5f 7b 0a d2 13 44 ea 74 ad ca 14
//   frame 3, (1.0, 2.5): a2 44 d4 7a 86 95 37 e2 e1 5b 47 5c
// and, of frame 3, (1.0, 2.0) at 25000 bytes, the 16 bytes at 56, 120, 12296 and 24984 (words
// mixed 16 at a time where the CPU has 64-bit vector multiplies, one at a time elsewhere): the
// python3 stream compared byte for byte.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <vector>

#include "agents/messages/verification_payload.h"

namespace dvpr {
namespace {

using Bytes12 = std::vector<std::uint8_t>;

TEST(VerificationPayload, BytesComeFromTheFrameIdAndDescriptor) {
  const std::array<float, 2> d{1.0f, 2.0f}, other{1.0f, 2.5f};
  EXPECT_EQ(VerificationPayload(FrameId(3), d, 12),
            (Bytes12{0x5d, 0x09, 0xd1, 0x99, 0xea, 0x69, 0x0a, 0xaa, 0xb7, 0xe0, 0xc0, 0xce}));
  EXPECT_EQ(VerificationPayload(FrameId(4), d, 12),
            (Bytes12{0x77, 0x5f, 0x7b, 0x0a, 0xd2, 0x13, 0x44, 0xea, 0x74, 0xad, 0xca, 0x14}));
  EXPECT_EQ(VerificationPayload(FrameId(3), other, 12),
            (Bytes12{0xa2, 0x44, 0xd4, 0x7a, 0x86, 0x95, 0x37, 0xe2, 0xe1, 0x5b, 0x47, 0x5c}));
}

TEST(VerificationPayload, HasTheRequestedSizeAndALongerOneExtendsAShorter) {
  const std::array<float, 2> d{1.0f, 2.0f};
  for (std::size_t size : {0u, 1u, 7u, 8u, 9u, 25000u}) EXPECT_EQ(VerificationPayload(FrameId(3), d, size).size(), size);
  const auto longer = VerificationPayload(FrameId(3), d, 25000);
  const auto shorter = VerificationPayload(FrameId(3), d, 12);
  EXPECT_TRUE(std::equal(shorter.begin(), shorter.end(), longer.begin()));
  // Not zeros: of 25000 bytes from a 64-bit mixer, each value 0..255 appears about 98 times.
  EXPECT_LT(std::count(longer.begin(), longer.end(), 0), 200);
}

TEST(VerificationPayload, FillWritesTheSameBytesOverABufferOfAnySize) {
  const std::array<float, 2> d{1.0f, 2.0f};
  std::vector<std::uint8_t> out(12, 0xee);  // 12 bytes: a whole word and a part of one
  FillVerificationPayload(FrameId(3), d, out);
  EXPECT_EQ(out, (Bytes12{0x5d, 0x09, 0xd1, 0x99, 0xea, 0x69, 0x0a, 0xaa, 0xb7, 0xe0, 0xc0, 0xce}));
  for (std::size_t size : {0u, 1u, 7u, 8u, 9u, 16u, 25000u}) {
    std::vector<std::uint8_t> filled(size, 0xee);
    FillVerificationPayload(FrameId(3), d, filled);
    EXPECT_EQ(filled, VerificationPayload(FrameId(3), d, size)) << size;
  }
}

TEST(VerificationPayload, LongPayloadsMatchTheReferenceStreamAcrossItsBlocks) {
  const std::array<float, 2> d{1.0f, 2.0f};
  const auto bytes = VerificationPayload(FrameId(3), d, 25000);
  const auto at = [&](std::size_t from) { return Bytes12(bytes.begin() + from, bytes.begin() + from + 16); };
  EXPECT_EQ(at(56), (Bytes12{0x81, 0x03, 0x9c, 0x30, 0xd2, 0x9d, 0x2e, 0x53, 0xfe, 0x4c, 0x00, 0x68, 0xad, 0xfe,
                             0x94, 0x57}));
  EXPECT_EQ(at(120), (Bytes12{0x44, 0xb2, 0x64, 0x34, 0xcc, 0x80, 0x60, 0xad, 0xed, 0xed, 0x3d, 0x13, 0xa3, 0xbe,
                              0x74, 0x9e}));
  EXPECT_EQ(at(12296), (Bytes12{0x9f, 0x2e, 0xa9, 0x79, 0x73, 0xcc, 0x6a, 0x24, 0xc0, 0xee, 0xb1, 0x96, 0x8b, 0xcb,
                                0x35, 0xbd}));
  EXPECT_EQ(at(24984), (Bytes12{0x35, 0xb3, 0x90, 0x60, 0x2f, 0x37, 0x4c, 0xa5, 0xcc, 0xae, 0xb1, 0x8a, 0xc9, 0xae,
                                0x11, 0xa1}));
  // Every size around a block of 16 words ends where the longer payload's stream is.
  for (std::size_t size = 100; size < 400; ++size) {
    const auto shorter = VerificationPayload(FrameId(3), d, size);
    ASSERT_TRUE(std::equal(shorter.begin(), shorter.end(), bytes.begin())) << size;
  }
}

}  // namespace
}  // namespace dvpr
