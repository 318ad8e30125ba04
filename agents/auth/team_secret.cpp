#include "agents/auth/team_secret.h"

#include <fcntl.h>
#include <sys/random.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <stdexcept>
#include <system_error>
#include <vector>

namespace dvpr::auth {

namespace {

constexpr std::size_t kHexDigits = 2 * kSecretBytes;

int HexValue(char c) {
  if (c >= '0' && c <= '9') return c - '0';
  if (c >= 'a' && c <= 'f') return c - 'a' + 10;
  if (c >= 'A' && c <= 'F') return c - 'A' + 10;
  return -1;
}

struct Fd {
  int fd = -1;
  ~Fd() {
    if (fd >= 0) close(fd);
  }
};

}  // namespace

Secret DrawSecret() {
  Secret s{};
  std::size_t got = 0;
  while (got < s.size()) {
    const ssize_t n = getrandom(s.data() + got, s.size() - got, 0);
    if (n < 0) {
      if (errno == EINTR) continue;
      throw std::runtime_error(std::string("team secret: getrandom failed: ") + std::strerror(errno));
    }
    got += static_cast<std::size_t>(n);
  }
  return s;
}

Secret ReadSecretFile(const std::filesystem::path& path, const std::string& what) {
  const std::string where = what + ": " + path.string() + ": ";
  auto fail = [&](const std::string& problem) -> Secret { throw std::invalid_argument(where + problem); };
  // O_NOFOLLOW: a link is refused, not followed (a loop of links gives ELOOP, said as such);
  // O_NONBLOCK: opening a FIFO without a writer must not hang; fstat then refuses it.
  Fd f{open(path.c_str(), O_RDONLY | O_NOFOLLOW | O_NONBLOCK | O_CLOEXEC | O_NOCTTY)};
  if (f.fd < 0) {
    const int e = errno;
    if (e == ELOOP) return fail("is a symbolic link (or a loop of them); give the file itself");
    if (e == ENOENT) return fail("no such file");
    if (e == EACCES) return fail("permission denied");
    return fail(std::string("cannot be opened: ") + std::strerror(e));
  }
  struct stat st{};
  if (fstat(f.fd, &st) != 0) return fail(std::string("cannot be examined: ") + std::strerror(errno));
  if (S_ISFIFO(st.st_mode)) return fail("is a FIFO, not a regular file");
  if (S_ISCHR(st.st_mode) || S_ISBLK(st.st_mode)) return fail("is a device, not a regular file");
  if (S_ISDIR(st.st_mode)) return fail("is a folder, not a regular file");
  if (!S_ISREG(st.st_mode)) return fail("is not a regular file");
  if (st.st_uid != geteuid()) return fail("belongs to another user (uid " + std::to_string(st.st_uid) + ")");
  if ((st.st_mode & 077) != 0) {
    char mode[8];
    std::snprintf(mode, sizeof mode, "%04o", static_cast<unsigned>(st.st_mode & 07777));
    return fail(std::string("may be read or written by others (mode ") + mode + "); it must be 0600 or 0400");
  }
  // 64 digits and a newline at most; one byte more is enough to see a longer file.
  char text[kHexDigits + 3];
  std::size_t size = 0;
  for (;;) {
    const ssize_t n = read(f.fd, text + size, sizeof text - size);
    if (n < 0) {
      if (errno == EINTR) continue;
      return fail(std::string("cannot be read: ") + std::strerror(errno));
    }
    if (n == 0) break;
    size += static_cast<std::size_t>(n);
    if (size == sizeof text) break;
  }
  std::size_t digits = size;
  if (digits == kHexDigits + 1 && text[kHexDigits] == '\n') digits = kHexDigits;
  if (digits != kHexDigits) {
    return fail("expected " + std::to_string(kHexDigits) + " hexadecimal digits (and at most one newline), got " +
                (size == sizeof text ? "more than " + std::to_string(kHexDigits + 1) : std::to_string(size)) +
                " bytes");
  }
  Secret s{};
  for (std::size_t i = 0; i < kSecretBytes; ++i) {
    const int hi = HexValue(text[2 * i]), lo = HexValue(text[2 * i + 1]);
    if (hi < 0 || lo < 0) {
      return fail("expected hexadecimal digits, found another character at byte " + std::to_string(hi < 0 ? 2 * i + 1 : 2 * i + 2));
    }
    s[i] = static_cast<std::uint8_t>(hi << 4 | lo);
  }
  return s;
}

void WriteSecretFile(const std::filesystem::path& path, const Secret& secret) {
  Fd f{open(path.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0600)};
  if (f.fd < 0) throw std::runtime_error("team secret: cannot create " + path.string() + ": " + std::strerror(errno));
  static constexpr char kDigits[] = "0123456789abcdef";
  std::string text;
  for (std::uint8_t b : secret) {
    text.push_back(kDigits[b >> 4]);
    text.push_back(kDigits[b & 15]);
  }
  text.push_back('\n');
  std::size_t done = 0;
  while (done < text.size()) {
    const ssize_t n = write(f.fd, text.data() + done, text.size() - done);
    if (n < 0) {
      if (errno == EINTR) continue;
      throw std::runtime_error("team secret: cannot write " + path.string() + ": " + std::strerror(errno));
    }
    done += static_cast<std::size_t>(n);
  }
  std::fill(text.begin(), text.end(), '\0');
}

SecretFolder::SecretFolder(const std::filesystem::path& parent) {
  std::string pattern = (parent / "dvpr-team-XXXXXX").string();
  std::vector<char> buffer(pattern.begin(), pattern.end());
  buffer.push_back('\0');
  if (mkdtemp(buffer.data()) == nullptr) {  // mode 0700
    throw std::runtime_error("team secret: cannot make a private folder under " + parent.string() + ": " +
                             std::strerror(errno));
  }
  path_ = buffer.data();
}

SecretFolder::~SecretFolder() {
  std::error_code ignored;
  std::filesystem::remove_all(path_, ignored);
}

}  // namespace dvpr::auth
