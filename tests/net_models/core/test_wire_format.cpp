#include "net_models/core/wire_format.h"

#include <gtest/gtest.h>

#include <stdexcept>
#include <string>
#include <vector>

namespace dvpr {
namespace {

TEST(WireFormat, UdpPayloadOf517BytesIsA547BytePppFrame) {
  // 517 + UDP 8 + IPv4 20 = 545-byte IP packet; + PPP 2 = 547.
  std::vector<Bytes> frames;
  const WireFootprint fp = FramesOfDatagram(Bytes(517), WireParams{}, &frames);
  EXPECT_EQ(fp.ip_packets, 1);
  EXPECT_EQ(fp.ip_bytes, Bytes(545));
  EXPECT_EQ(fp.wire_bytes, Bytes(547));
  EXPECT_EQ(frames, (std::vector<Bytes>{Bytes(547)}));
}

TEST(WireFormat, QueryOnTheBroadcastChannel) {
  // A query_t with a 128-float descriptor encodes to 8 (fingerprint) + 8 + 2
  // + 4 + 8 + 2 + 512 = 544 bytes. On "DVPR_QUERY_ALL" (14 characters):
  // LCM datagram 8 + 14 + 1 + 544 = 567; IP 567 + 28 = 595; PPP 597.
  const WireFootprint fp = ComputeWireFootprint(Bytes(544), 14, WireParams{});
  EXPECT_EQ(fp.lcm_datagrams, 1);
  EXPECT_EQ(fp.udp_payload_bytes, Bytes(567));
  EXPECT_EQ(fp.ip_packets, 1);
  EXPECT_EQ(fp.wire_bytes, Bytes(597));
}

TEST(WireFormat, ThirtyKilobyteMessageIsIpFragmented) {
  // 30 000 payload bytes on "DVPR_VREQ_3" (11 characters):
  //   LCM short datagram: 8 + 11 + 1 + 30 000 = 30 020 bytes (fits 65 499).
  //   IP data: UDP header + datagram = 30 028 bytes. At MTU 1500 a fragment
  //   carries (1500 - 20) rounded down to a multiple of 8 = 1480 data bytes:
  //   20 full fragments (29 600) + one of 428 -> 21 IP packets.
  //   IP bytes: 30 028 + 21 x 20 = 30 448. PPP: + 21 x 2 = 30 490.
  //   Overhead: 30 490 - 30 000 = 490 = LCM 8 + channel 12 + UDP 8 + IP 420 + PPP 42.
  std::vector<Bytes> frames;
  const WireFootprint fp = AppendLinkFrames(Bytes(30000), 11, WireParams{}, frames);
  EXPECT_EQ(fp.lcm_datagrams, 1);
  EXPECT_EQ(fp.ip_packets, 21);
  EXPECT_EQ(fp.ip_bytes, Bytes(30448));
  EXPECT_EQ(fp.wire_bytes, Bytes(30490));
  EXPECT_EQ(fp.largest_frame, Bytes(1502));
  ASSERT_EQ(frames.size(), 21u);
  for (int i = 0; i < 20; ++i) EXPECT_EQ(frames[i], Bytes(1502));
  EXPECT_EQ(frames[20], Bytes(428 + 20 + 2));
}

TEST(WireFormat, LcmFragmentsPastOneDatagram) {
  // Channel "X": the stream channel + NUL + payload is 65 499 bytes at most
  // for one short datagram.
  const WireParams p;
  EXPECT_EQ(ComputeWireFootprint(Bytes(65499 - 2), 1, p).lcm_datagrams, 1);
  const WireFootprint two = ComputeWireFootprint(Bytes(65499 - 1), 1, p);
  // 65 500-byte stream: fragments of 65 487 and 13, each + 20 header bytes.
  EXPECT_EQ(two.lcm_datagrams, 2);
  EXPECT_EQ(two.udp_payload_bytes, Bytes(65507 + 33));

  // 100 000 payload bytes: stream 100 002 = 65 487 + 34 515.
  //   Datagram 1: 65 507 bytes -> IP data 65 515 = 44 x 1480 + 395 -> 45 packets.
  //   Datagram 2: 34 535 bytes -> IP data 34 543 = 23 x 1480 + 503 -> 24 packets.
  //   Frames: 65 515 + 45 x 22 + 34 543 + 24 x 22 = 66 505 + 35 071 = 101 576 bytes.
  std::vector<Bytes> frames;
  const WireFootprint big = AppendLinkFrames(Bytes(100000), 1, p, frames);
  EXPECT_EQ(big.lcm_datagrams, 2);
  EXPECT_EQ(big.ip_packets, 69);
  EXPECT_EQ(big.wire_bytes, Bytes(101576));
  EXPECT_EQ(frames.size(), 69u);
  EXPECT_EQ(frames[44], Bytes(395 + 22));
  EXPECT_EQ(frames[68], Bytes(503 + 22));
}

TEST(WireFormat, SmallMtuRoundsFragmentDataToEightBytes) {
  // MTU 100: fragments carry (100 - 20) = 80 data bytes. A 200-byte datagram
  // is 208 IP data bytes = 80 + 80 + 48 -> 3 packets of 100, 100, 68 bytes.
  std::vector<Bytes> frames;
  const WireFootprint fp = FramesOfDatagram(Bytes(200), WireParams{Bytes(100), Bytes(0)}, &frames);
  EXPECT_EQ(frames, (std::vector<Bytes>{Bytes(100), Bytes(100), Bytes(68)}));
  // MTU 105 gives the same: 85 data bytes round down to 80.
  EXPECT_EQ(FramesOfDatagram(Bytes(200), WireParams{Bytes(105), Bytes(0)}, nullptr).ip_packets, 3);
  EXPECT_EQ(fp.ip_bytes, Bytes(268));
}

TEST(WireFormat, ValidateNamesTheFieldAndValue) {
  try {
    WireParams{Bytes(0), Bytes(2)}.Validate();
    FAIL() << "MTU 0 accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("mtu: too small: an IPv4 packet needs 20 header bytes plus at least 8 data bytes, got 0B"), std::string::npos) << e.what();
  }
  EXPECT_THROW((WireParams{Bytes(27), Bytes(2)}.Validate()), std::invalid_argument);
  EXPECT_NO_THROW((WireParams{Bytes(28), Bytes(2)}.Validate()));
}

}  // namespace
}  // namespace dvpr

namespace dvpr {
namespace {

// csma's DIX Ethernet framing, by hand: 14-byte header + 4-byte FCS around each IP packet, the
// packet padded to 46 bytes (ns-3's CsmaNetDevice; no preamble).
TEST(WireFormat, EthernetFramesAQueryInOne611ByteFrame) {
  // query_t (544 B) on "DVPR_QUERY_3" (12 characters): LCM 8 + 12 + 1 + 544 = 565; IP 565 + 28 =
  // 593; Ethernet 593 + 18 = 611.
  const WireParams dix = LinkWire(WireParams{}, LinkFraming::kEthernetDix);
  std::vector<Bytes> frames;
  const WireFootprint fp = AppendLinkFrames(Bytes(544), 12, dix, frames);
  EXPECT_EQ(fp.ip_bytes, Bytes(593));
  EXPECT_EQ(frames, (std::vector<Bytes>{Bytes(611)}));
  EXPECT_EQ(fp.wire_bytes, Bytes(611));
}

TEST(WireFormat, EthernetFramesAVerificationRequestIn17Frames) {
  // 25 032 B on "DVPR_VREQ_3" (11 characters): LCM 8 + 11 + 1 + 25 032 = 25 052; IP data 25 060 =
  // 16 x 1480 + 1380: 16 frames of 1480 + 20 + 18 = 1518 and one of 1380 + 38 = 1418, in all
  // 16 x 1518 + 1418 = 25 706 bytes on the wire.
  const WireParams dix = LinkWire(WireParams{}, LinkFraming::kEthernetDix);
  std::vector<Bytes> frames;
  const WireFootprint fp = AppendLinkFrames(Bytes(25032), 11, dix, frames);
  ASSERT_EQ(frames.size(), 17u);
  for (std::size_t i = 0; i < 16; ++i) EXPECT_EQ(frames[i], Bytes(1518)) << i;
  EXPECT_EQ(frames[16], Bytes(1418));
  EXPECT_EQ(fp.ip_packets, 17);
  EXPECT_EQ(fp.wire_bytes, Bytes(25706));
  EXPECT_EQ(fp.largest_frame, Bytes(1518));
}

TEST(WireFormat, EthernetPadsAShortLastFragmentTo46Bytes) {
  // 1470 B on "X": LCM 8 + 1 + 1 + 1470 = 1480; IP data 1488 = 1480 + 8: the last fragment is an
  // IP packet of 20 + 8 = 28 bytes, padded to 46: a 64-byte frame (Ethernet's minimum).
  const WireParams dix = LinkWire(WireParams{}, LinkFraming::kEthernetDix);
  std::vector<Bytes> frames;
  const WireFootprint fp = AppendLinkFrames(Bytes(1470), 1, dix, frames);
  EXPECT_EQ(frames, (std::vector<Bytes>{Bytes(1518), Bytes(64)}));
  EXPECT_EQ(fp.wire_bytes, Bytes(1582));
  EXPECT_EQ(fp.ip_bytes, Bytes(1488 + 2 * 20));  // padding is the link's, not IP's
}

TEST(WireFormat, WifiFramesAQueryWith36BytesOfMacHeaders) {
  // 802.11 data frame: MAC header 24 + LLC/SNAP 8 + FCS 4 = 36 around the 593-byte IP packet.
  std::vector<Bytes> frames;
  AppendLinkFrames(Bytes(544), 12, LinkWire(WireParams{}, LinkFraming::kWifi), frames);
  EXPECT_EQ(frames, (std::vector<Bytes>{Bytes(629)}));
  // PPP again, whatever came before.
  const WireParams ppp = LinkWire(LinkWire(WireParams{}, LinkFraming::kWifi), LinkFraming::kPpp);
  EXPECT_EQ(ppp, WireParams{});
}

}  // namespace
}  // namespace dvpr
