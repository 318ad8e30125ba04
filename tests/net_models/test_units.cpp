#include "net_models/units.h"

#include <gtest/gtest.h>

#include <stdexcept>
#include <string>

namespace dvpr {
namespace {

TEST(ParseDataRate, AcceptsCommonSpellings) {
  EXPECT_EQ(ParseDataRate("10Mbps").bps(), 10'000'000);
  EXPECT_EQ(ParseDataRate("54Mbit/s").bps(), 54'000'000);
  EXPECT_EQ(ParseDataRate("1.5Gbps").bps(), 1'500'000'000);
  EXPECT_EQ(ParseDataRate("800kbps").bps(), 800'000);
  EXPECT_EQ(ParseDataRate("100 kbit/s").bps(), 100'000);
  EXPECT_EQ(ParseDataRate("2MBps").bps(), 16'000'000);  // bytes per second
  EXPECT_EQ(ParseDataRate("1Kibps").bps(), 1024);
  EXPECT_EQ(ParseDataRate("  7bps ").bps(), 7);
}

TEST(ParseDataRate, RejectsMissingOrUnknownUnitNamingTheValue) {
  for (const char* bad : {"10", "10 furlongs", "Mbps", "", "-5Mbps", "10mbps", "1.2.3Mbps"}) {
    try {
      ParseDataRate(bad);
      ADD_FAILURE() << "accepted " << bad;
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find(std::string("\"") + bad + "\""), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find("Mbps"), std::string::npos) << e.what();
    }
  }
}

TEST(ParseDuration, AcceptsUnits) {
  EXPECT_EQ(ParseDuration("5ms"), SimTime::Millis(5));
  EXPECT_EQ(ParseDuration("50us"), SimTime::Micros(50));
  EXPECT_EQ(ParseDuration("20ns"), SimTime::Nanos(20));
  EXPECT_EQ(ParseDuration("1.5s"), SimTime::Millis(1500));
  EXPECT_EQ(ParseDuration("0.0000000015s"), SimTime::Nanos(2));  // 1.5 ns rounds half up
  EXPECT_EQ(ParseDuration("2min"), SimTime::Millis(120'000));
}

TEST(ParseDuration, RejectsUnitless) {
  EXPECT_THROW(ParseDuration("5"), std::invalid_argument);
  EXPECT_THROW(ParseDuration("5 parsecs"), std::invalid_argument);
  EXPECT_THROW(ParseDuration("-1ms"), std::invalid_argument);
}

TEST(ParseBytes, AcceptsSiAndIecUnits) {
  EXPECT_EQ(ParseBytes("64KiB"), Bytes(65'536));
  EXPECT_EQ(ParseBytes("1500B"), Bytes(1500));
  EXPECT_EQ(ParseBytes("1.5KiB"), Bytes(1536));
  EXPECT_EQ(ParseBytes("25kB"), Bytes(25'000));
  EXPECT_EQ(ParseBytes("1MiB"), Bytes(1'048'576));
}

TEST(ParseBytes, RejectsUnitlessAndAmbiguous) {
  EXPECT_THROW(ParseBytes("1500"), std::invalid_argument);
  EXPECT_THROW(ParseBytes("1KB"), std::invalid_argument);  // kB or KiB?
}

TEST(DataRate, TxTimeIsExactAndRoundsUp) {
  // 547 bytes = 4376 bits; at 1 Mbit/s that is 4376 us exactly.
  EXPECT_EQ(DataRate::Mbps(1).TxTime(Bytes(547)), SimTime::Micros(4376));
  // 1 byte at 3 bit/s = 8/3 s = 2.666...e9 ns, rounded up.
  EXPECT_EQ(DataRate::BitsPerSecond(3).TxTime(Bytes(1)), SimTime::Nanos(2'666'666'667));
  EXPECT_THROW(DataRate().TxTime(Bytes(1)), std::domain_error);
}

TEST(Units, ToStringParsesBack) {
  for (const char* s : {"10Mbps", "1500bps", "3Gbps"}) {
    EXPECT_EQ(ToString(ParseDataRate(s)), s);
  }
  for (const char* s : {"1500B", "64KiB", "25kB"}) {
    EXPECT_EQ(ToString(ParseBytes(s)), s);
  }
}

TEST(Units, FormatDurationUsesTheLargestWholeUnit) {
  EXPECT_EQ(FormatDuration(SimTime::Millis(2)), "2ms");
  EXPECT_EQ(FormatDuration(SimTime::Micros(250)), "250us");
  EXPECT_EQ(FormatDuration(SimTime::Nanos(1'500)), "1500ns");  // 1.5us is not whole
  EXPECT_EQ(FormatDuration(SimTime::Seconds(120)), "2min");
  EXPECT_EQ(FormatDuration(SimTime::Zero()), "0ns");
  for (const char* s : {"12s", "7ns", "1h", "50us"}) {
    EXPECT_EQ(FormatDuration(ParseDuration(s)), s);
  }
}

}  // namespace
}  // namespace dvpr
