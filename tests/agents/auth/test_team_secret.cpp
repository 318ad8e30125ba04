// The team's secret file (agents/auth/team_secret.h): what the launcher writes reads back, and
// every file an agent must not trust is refused with the file and the reason in one line.
#include <sys/stat.h>
#include <unistd.h>

#include <cctype>
#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>

#include "agents/auth/team_secret.h"

namespace dvpr::auth {
namespace {

namespace fs = std::filesystem;

class TeamSecretTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::path(DVPR_TEST_TMP) / "auth" / ::testing::UnitTest::GetInstance()->current_test_info()->name();
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  // A file with `text` and `mode`.
  fs::path File(const std::string& name, const std::string& text, mode_t mode = 0600) const {
    const fs::path p = dir_ / name;
    std::ofstream(p) << text;
    chmod(p.c_str(), mode);
    return p;
  }
  // The one-line error reading `p` gives.
  static std::string Error(const fs::path& p) {
    try {
      ReadSecretFile(p);
    } catch (const std::invalid_argument& e) {
      return e.what();
    }
    return "(accepted)";
  }
  fs::path dir_;
};

const std::string kDigits = "000102030405060708090a0b0c0d0e0f101112131415161718191a1b1c1d1e1f";

TEST_F(TeamSecretTest, WhatIsWrittenReadsBackAndIsTheOwnersAlone) {
  const Secret s = DrawSecret();
  const fs::path p = dir_ / "team.secret";
  WriteSecretFile(p, s);
  EXPECT_EQ(ReadSecretFile(p), s);
  struct stat st{};
  ASSERT_EQ(stat(p.c_str(), &st), 0);
  EXPECT_EQ(st.st_mode & 07777, 0600u);
  EXPECT_THROW(WriteSecretFile(p, s), std::runtime_error);  // never over an existing file
  EXPECT_NE(DrawSecret(), DrawSecret());
  // Hexadecimal in either case, with or without one newline.
  Secret counting{};
  for (std::size_t i = 0; i < counting.size(); ++i) counting[i] = static_cast<std::uint8_t>(i);
  EXPECT_EQ(ReadSecretFile(File("plain", kDigits)), counting);
  std::string upper = kDigits;
  for (char& c : upper) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  EXPECT_EQ(ReadSecretFile(File("upper", upper + "\n", 0400)), counting);
}

TEST_F(TeamSecretTest, EveryFileAnAgentMustNotTrustIsOneLineNamingItAndWhy) {
  const fs::path good = File("good", kDigits + "\n");
  const auto expect = [&](const fs::path& p, const std::string& why) {
    const std::string e = Error(p);
    EXPECT_NE(e.find("--team-secret: " + p.string() + ": "), std::string::npos) << e;
    EXPECT_NE(e.find(why), std::string::npos) << e;
    EXPECT_EQ(e.find('\n'), std::string::npos) << e;
  };
  expect(dir_ / "missing", "no such file");
  expect(dir_, "is a folder, not a regular file");
  ASSERT_EQ(mkfifo((dir_ / "fifo").c_str(), 0600), 0);
  expect(dir_ / "fifo", "is a FIFO, not a regular file");  // and no hang waiting for a writer
  expect("/dev/zero", "is a device, not a regular file");
  fs::create_symlink(good, dir_ / "link");
  expect(dir_ / "link", "is a symbolic link");
  fs::create_symlink(dir_ / "loop_b", dir_ / "loop_a");
  fs::create_symlink(dir_ / "loop_a", dir_ / "loop_b");
  expect(dir_ / "loop_a", "is a symbolic link (or a loop of them)");
  expect(File("readable", kDigits, 0644), "may be read or written by others (mode 0644)");
  expect(File("group", kDigits, 0640), "(mode 0640)");
  expect(File("short", kDigits.substr(2)), "expected 64 hexadecimal digits (and at most one newline), got 62 bytes");
  expect(File("long", kDigits + "0000"), "got more than 65 bytes");
  expect(File("two_newlines", kDigits + "\n\n"), "got 66 bytes");
  expect(File("empty", ""), "got 0 bytes");
  std::string bad = kDigits;
  bad[9] = 'g';
  expect(File("not_hex", bad), "another character at byte 10");
  expect(File("bom", "\xEF\xBB\xBF" + kDigits.substr(3)), "another character at byte 1");
  if (geteuid() == 0) {  // root may give a file away: one of another user is refused
    const fs::path theirs = File("theirs", kDigits);
    ASSERT_EQ(chown(theirs.c_str(), 65534, 65534), 0);
    expect(theirs, "belongs to another user (uid 65534)");
  }
}

TEST_F(TeamSecretTest, ASecretFolderIsPrivateAndGoesAwayWithWhatItHolds) {
  fs::path kept;
  {
    const SecretFolder folder(dir_);
    kept = folder.path();
    struct stat st{};
    ASSERT_EQ(stat(kept.c_str(), &st), 0);
    EXPECT_TRUE(S_ISDIR(st.st_mode));
    EXPECT_EQ(st.st_mode & 07777, 0700u);
    WriteSecretFile(kept / "team.secret", DrawSecret());
  }
  EXPECT_FALSE(fs::exists(kept));
  EXPECT_THROW(SecretFolder(dir_ / "no" / "such"), std::runtime_error);
}

}  // namespace
}  // namespace dvpr::auth
