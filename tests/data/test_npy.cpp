#include "experiments/domain/data/npy.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <stdexcept>
#include <string>

namespace dvpr {
namespace {

namespace fs = std::filesystem;

class NpyTest : public ::testing::Test {
 protected:
  static fs::path Fixture(const std::string& name) {
    return fs::path(DVPR_SOURCE_DIR) / "tests/data/fixtures" / name;
  }
  fs::path Tmp(const std::string& name) const {
    const fs::path dir = fs::path(DVPR_TEST_TMP) / "npy";
    fs::create_directories(dir);
    return dir / name;
  }
  static std::string Bytes(const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  }
  // The fixture array: np.arange(12).reshape(3, 4) * 0.5 - 1.
  static DescriptorMatrix Expected() {
    DescriptorMatrix m(3, 4);
    for (int i = 0; i < 12; ++i) m(i / 4, i % 4) = static_cast<float>(i) * 0.5f - 1.0f;
    return m;
  }
  static void ExpectThrowContaining(const fs::path& p, const std::string& needle) {
    try {
      ReadNpyMatrix(p);
      FAIL() << "no exception for " << p;
    } catch (const std::runtime_error& e) {
      const std::string what = e.what();
      EXPECT_NE(what.find(needle), std::string::npos) << what;
      EXPECT_NE(what.find(p.filename().string()), std::string::npos) << what;
    }
  }
};

TEST_F(NpyTest, ReadsNumpyFilesInBothOrdersAndDtypesAndVersions) {
  for (const char* name :
       {"f4_c.npy", "f8_c.npy", "f4_f.npy", "f8_f.npy", "f4_v2.npy", "f8_v3.npy"}) {
    const DescriptorMatrix m = ReadNpyMatrix(Fixture(name));
    EXPECT_EQ(m, Expected()) << name;
  }
}

TEST_F(NpyTest, ReadsEmptyMatrix) {
  const DescriptorMatrix m = ReadNpyMatrix(Fixture("empty_f4.npy"));
  EXPECT_EQ(m.rows(), 0);
  EXPECT_EQ(m.cols(), 5);
}

TEST_F(NpyTest, WriterMatchesNumpyByteForByte) {
  WriteNpy(Tmp("w.npy"), Expected());
  EXPECT_EQ(Bytes(Tmp("w.npy")), Bytes(Fixture("f4_c.npy")));
}

TEST_F(NpyTest, WriterHeaderForPaperSizedMatrixMatchesNumpy) {
  // numpy 1.24.2: np.save(f, np.zeros((4541, 128), np.float32)); header is 128 bytes.
  std::string expected = std::string("\x93NUMPY\x01\x00v\x00", 10) +
                         "{'descr': '<f4', 'fortran_order': False, 'shape': (4541, 128), }";
  expected.append(128 - 1 - expected.size(), ' ');
  expected.push_back('\n');
  WriteNpy(Tmp("big.npy"), DescriptorMatrix::Zero(4541, 128));
  const std::string bytes = Bytes(Tmp("big.npy"));
  ASSERT_EQ(bytes.size(), 128u + 4541u * 128u * 4u);
  EXPECT_EQ(bytes.substr(0, 128), expected);
}

TEST_F(NpyTest, RoundTripKeepsValuesAndLeavesNoTemporaryFile) {
  DescriptorMatrix m = DescriptorMatrix::Random(7, 33);
  WriteNpy(Tmp("rt.npy"), m);
  WriteNpy(Tmp("rt.npy"), m);  // overwriting an existing file works too
  EXPECT_EQ(ReadNpyMatrix(Tmp("rt.npy")), m);
  int files = 0;
  for (const auto& entry : fs::directory_iterator(Tmp("rt.npy").parent_path())) {
    files += entry.path().filename().string().starts_with("rt.npy") ? 1 : 0;
  }
  EXPECT_EQ(files, 1);
}

TEST_F(NpyTest, WriteToMissingDirectoryThrows) {
  EXPECT_THROW(WriteNpy(Tmp("no_such_dir/x.npy"), Expected()), std::runtime_error);
}

TEST_F(NpyTest, RejectsWrongRank) {
  ExpectThrowContaining(Fixture("one_d.npy"), "2-D");
  ExpectThrowContaining(Fixture("three_d.npy"), "2-D");
}

TEST_F(NpyTest, RejectsUnsupportedDtypes) {
  ExpectThrowContaining(Fixture("int32.npy"), "'<i4'");
  ExpectThrowContaining(Fixture("big_endian.npy"), "'>f4'");
}

TEST_F(NpyTest, RejectsTruncatedData) { ExpectThrowContaining(Fixture("truncated.npy"), "truncated"); }

TEST_F(NpyTest, RejectsBadMagicAndBadHeaders) {
  std::ofstream(Tmp("magic.npy"), std::ios::binary) << "PK\x03\x04 not numpy at all";
  ExpectThrowContaining(Tmp("magic.npy"), "bad magic");

  std::string bytes = Bytes(Fixture("f4_c.npy"));
  std::ofstream(Tmp("short_header.npy"), std::ios::binary) << bytes.substr(0, 40);
  ExpectThrowContaining(Tmp("short_header.npy"), "truncated header");

  bytes.replace(bytes.find("'shape'"), 7, "'shope'");
  std::ofstream(Tmp("bad_key.npy"), std::ios::binary) << bytes;
  ExpectThrowContaining(Tmp("bad_key.npy"), "bad header");

  ExpectThrowContaining(Tmp("does_not_exist.npy"), "cannot open");
}

TEST_F(NpyTest, RejectsTrailingBytes) {
  std::ofstream(Tmp("trailing.npy"), std::ios::binary) << Bytes(Fixture("f4_c.npy")) << "xyz";
  ExpectThrowContaining(Tmp("trailing.npy"), "after the data");
}

// A header is the file's bytes: whatever they hold, the error is one line that quotes them
// escaped. The header below is numpy's for shape (3, 4) with the key 'shape' changed to 's',
// a newline, 'ap' and the byte 0x01 (as long, so the header length holds): the parser stops there.
TEST_F(NpyTest, HeaderErrorsAreOneLineWithTheBytesEscaped) {
  std::string bytes = Bytes(Fixture("f4_c.npy"));
  bytes.replace(bytes.find("'shape'"), 7, std::string("'s\nap\x01'"));
  std::ofstream(Tmp("newline_key.npy"), std::ios::binary) << bytes;
  try {
    ReadNpyMatrix(Tmp("newline_key.npy"));
    FAIL() << "no exception";
  } catch (const std::runtime_error& e) {
    const std::string what = e.what();
    EXPECT_EQ(what.find('\n'), std::string::npos) << what;
    EXPECT_EQ(what.rfind("npy file " + Tmp("newline_key.npy").string() +
                             ": bad header (unknown key 's\\nap\\x01'): '{'descr': '<f4', 'fortran_order': False, "
                             "'s\\nap\\x01': (3, 4), }",
                         0),
              0u)
        << what;
  }
}

TEST_F(NpyTest, AnUnsupportedDtypeIsQuotedEscaped) {
  std::string bytes = Bytes(Fixture("f4_c.npy"));
  bytes.replace(bytes.find("'<f4'"), 5, std::string("'<\tX'"));
  std::ofstream(Tmp("tab_dtype.npy"), std::ios::binary) << bytes;
  ExpectThrowContaining(Tmp("tab_dtype.npy"), "unsupported dtype '<\\tX' (expected");
}

}  // namespace
}  // namespace dvpr
