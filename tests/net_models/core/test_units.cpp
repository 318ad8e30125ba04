#include "net_models/core/units.h"

#include <gtest/gtest.h>

#include <limits>
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

TEST(ParseMeters, AcceptsLengthUnitsToTheMillimetre) {
  EXPECT_EQ(ParseMeters("200m"), 200.0);
  EXPECT_EQ(ParseMeters("250 m"), 250.0);
  EXPECT_EQ(ParseMeters("1.5km"), 1500.0);
  EXPECT_EQ(ParseMeters("30cm"), 0.3);
  EXPECT_EQ(ParseMeters("5mm"), 0.005);
  EXPECT_EQ(ParseMeters("0.0004m"), 0.0);  // 0.4 mm rounds to 0 mm
  EXPECT_EQ(FormatMeters(200.0), "200m");
  EXPECT_EQ(FormatMeters(1500.0), "1500m");
  EXPECT_EQ(FormatMeters(0.5), "500mm");
  for (const double m : {200.0, 1500.0, 0.5, 0.001}) EXPECT_EQ(ParseMeters(FormatMeters(m)), m) << m;
}

TEST(ParseMeters, RejectsUnitlessNegativeAndUnknownUnits) {
  EXPECT_THROW(ParseMeters("200"), std::invalid_argument);
  EXPECT_THROW(ParseMeters("-1m"), std::invalid_argument);
  EXPECT_THROW(ParseMeters("3 furlongs"), std::invalid_argument);
  EXPECT_THROW(ParseMeters("nanm"), std::invalid_argument);
  EXPECT_THROW(ParseMeters("1e3m"), std::invalid_argument);
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

namespace dvpr {
namespace {

// int64 max = 9'223'372'036'854'775'807; the largest whole hour count that fits is 2'562'047
// (x 3.6e12 ns = 9'223'369'200'000'000'000).
TEST(ParseQuantityLimits, DurationsUpToTheLargestSimTime) {
  EXPECT_EQ(ParseDuration("2562047h"), SimTime::Nanos(9'223'369'200'000'000'000));
  EXPECT_EQ(ParseDuration("9223372036854775807ns"), SimTime::Max());
  EXPECT_THROW(ParseDuration("2562048h"), QuantityTooLarge);
  EXPECT_THROW(ParseDuration("9223372036854775808ns"), QuantityTooLarge);
  // 30 digits: overflowed the __int128 product before (UBSan), now refused as too large.
  EXPECT_THROW(ParseDuration("999999999999999999999999999999h"), QuantityTooLarge);
  EXPECT_THROW(ParseDuration("1" + std::string(60, '0') + "ns"), QuantityTooLarge);
  // 43 significant digits cannot be held exactly: refused, but not as too large.
  try {
    ParseDuration("1.000000000000000000000000000000000000000001h");
    ADD_FAILURE() << "no error";
  } catch (const QuantityTooLarge&) {
    ADD_FAILURE() << "reported as too large";
  } catch (const std::invalid_argument& e) {
    EXPECT_STREQ(e.what(),
                 "invalid duration \"1.000000000000000000000000000000000000000001h\": expected at most 38 "
                 "significant digits");
  }
  // Leading zeros are not significant: 1.5 h.
  EXPECT_EQ(ParseDuration("0000000000000000000000001.5h"), SimTime::Nanos(5'400'000'000'000));
}

// An exponent is not part of the exact decimal syntax: the error says so instead of calling
// "e400bps" an unknown unit. "1 e" stays an unknown unit (no digit after the e).
TEST(ParseQuantityLimits, AnExponentIsNamed) {
  const auto expect_named = [](const auto& parse, const char* text) {
    SCOPED_TRACE(text);
    try {
      parse(text);
      ADD_FAILURE() << "no error";
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find("expected digits without an exponent"), std::string::npos) << e.what();
    }
  };
  for (const char* text : {"1e6bps", "1E6bps", "1e400bps"}) expect_named(ParseDataRate, text);
  for (const char* text : {"1e-3s", "2.5e+2ms"}) expect_named(ParseDuration, text);
  try {
    ParseDuration("1 e");
    ADD_FAILURE() << "no error";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("expected a known unit"), std::string::npos) << e.what();
  }
}

TEST(ParseQuantityLimits, TooLargeNamesTheLargestValue) {
  try {
    ParseDuration("2562048h");
    FAIL() << "no error";
  } catch (const QuantityTooLarge& e) {
    EXPECT_STREQ(e.what(), "invalid duration \"2562048h\": expected at most 9223372036854775807ns");
  }
}

TEST(ParseQuantityLimits, BytesAndRatesUpToInt64) {
  // 2^33 GiB = 2^63 bytes: one past the largest.
  EXPECT_EQ(ParseBytes("8589934591GiB"), Bytes(9'223'372'035'781'033'984));
  EXPECT_THROW(ParseBytes("8589934592GiB"), QuantityTooLarge);
  // 2^60 B/s x 8 = 2^63 bit/s.
  EXPECT_EQ(ParseDataRate("1152921504606846975Bps").bps(), 9'223'372'036'854'775'800);
  EXPECT_THROW(ParseDataRate("1152921504606846976Bps"), QuantityTooLarge);
  EXPECT_THROW(ParseDataRate("99999999999999999999999999999999999999Tbps"), QuantityTooLarge);
}

TEST(DataRateLimits, TxTimeBeyondTheLargestSimTimeThrows) {
  // 2^60 bytes at 1 bit/s take 2^63 s, far past int64 ns. 1 GiB at 1 kbit/s: 2^33 bits / 1e3
  // bit/s = 8'589'934.592 s.
  EXPECT_THROW(DataRate::BitsPerSecond(1).TxTime(Bytes(std::int64_t{1} << 60)), std::domain_error);
  EXPECT_EQ(DataRate::Kbps(1).TxTime(Bytes(std::int64_t{1} << 30)), SimTime::Nanos(8'589'934'592'000'000));
}

TEST(DataRateLimits, TxTimeIsTheSameOnEitherSideOfItsFastPath) {
  // Up to 2^30 bytes the quotient is taken in 64 bits, beyond in 128. At the largest rate,
  // 2^63 - 1 bit/s, 2^30 bytes = 2^33 bits take 2^33 x 1e9 / (2^63 - 1) = 0.93 ns: 1 ns rounded
  // up, and so do 2^30 + 1 bytes. At 3 bit/s, 2^30 bytes take 2^33 / 3 s = 2'863'311'530.667 s
  // and 2^30 + 1 bytes 8 bits = 2.667 s more, both rounded up to the next ns.
  const DataRate fastest = DataRate::BitsPerSecond(std::numeric_limits<std::int64_t>::max());
  EXPECT_EQ(fastest.TxTime(Bytes(std::int64_t{1} << 30)), SimTime::Nanos(1));
  EXPECT_EQ(fastest.TxTime(Bytes((std::int64_t{1} << 30) + 1)), SimTime::Nanos(1));
  const DataRate three = DataRate::BitsPerSecond(3);
  EXPECT_EQ(three.TxTime(Bytes(std::int64_t{1} << 30)), SimTime::Nanos(2'863'311'530'666'666'667));
  EXPECT_EQ(three.TxTime(Bytes((std::int64_t{1} << 30) + 1)), SimTime::Nanos(2'863'311'533'333'333'334));
}

}  // namespace
}  // namespace dvpr
