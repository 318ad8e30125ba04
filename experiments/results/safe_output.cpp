#include "experiments/results/safe_output.h"

#include <dirent.h>
#include <fcntl.h>
#include <sys/random.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <stdexcept>
#include <streambuf>
#include <system_error>
#include <vector>

namespace dvpr {

namespace fs = std::filesystem;

namespace {

constexpr int kAttempts = 100;  // EEXIST on a fresh random name: someone is guessing; give up

std::string Why(int error) { return std::strerror(error); }

[[noreturn]] void Throw(const fs::path& what, const std::string& why) {
  throw std::runtime_error(what.string() + ": " + why);
}

// Why `name` in `dir_fd` could not be opened as a folder, in words: a link is named as one.
std::string OpenFolderError(int dir_fd, const char* name, int error) {
  struct stat st {};
  if (::fstatat(dir_fd, name, &st, AT_SYMLINK_NOFOLLOW) == 0) {
    if (S_ISLNK(st.st_mode)) return "is a symbolic link (dvpr does not write through links it did not make)";
    if (!S_ISDIR(st.st_mode)) return "exists and is not a folder";
  }
  return Why(error);
}

void CheckComponent(const fs::path& dir, const std::string& name) {
  if (name.empty() || name == "." || name == ".." || name.find('/') != std::string::npos) {
    throw std::logic_error((dir / name).string() + ": not a single file name");
  }
}

int Dup(int fd, const fs::path& what) {
  const int d = ::fcntl(fd, F_DUPFD_CLOEXEC, 0);
  if (d < 0) Throw(what, Why(errno));
  return d;
}

}  // namespace

std::string RandomSuffix() {
  unsigned char bytes[8];
  std::size_t got = 0;
  while (got < sizeof bytes) {
    const ssize_t n = ::getrandom(bytes + got, sizeof bytes - got, 0);
    if (n < 0) {
      if (errno == EINTR) continue;
      throw std::system_error(errno, std::generic_category(), "getrandom");
    }
    got += static_cast<std::size_t>(n);
  }
  static const char kHex[] = "0123456789abcdef";
  std::string s;
  for (unsigned char b : bytes) {
    s.push_back(kHex[b >> 4]);
    s.push_back(kHex[b & 15]);
  }
  return s;
}

int MakeFolderAt(int dir_fd, const std::string& name, unsigned mode) {
  if (::mkdirat(dir_fd, name.c_str(), static_cast<mode_t>(mode)) != 0) return -1;
  return ::openat(dir_fd, name.c_str(), kDirFlags);
}

void RemoveTreeAt(int dir_fd, const std::string& name) {
  if (::unlinkat(dir_fd, name.c_str(), 0) == 0 || errno == ENOENT) return;
  const int fd = ::openat(dir_fd, name.c_str(), kDirFlags);
  if (fd < 0) return;
  DIR* d = ::fdopendir(fd);
  if (d == nullptr) {
    ::close(fd);
    return;
  }
  std::vector<std::string> names;
  while (const dirent* e = ::readdir(d)) {
    const std::string n = e->d_name;
    if (n != "." && n != "..") names.push_back(n);
  }
  for (const std::string& n : names) RemoveTreeAt(::dirfd(d), n);
  ::closedir(d);
  ::unlinkat(dir_fd, name.c_str(), AT_REMOVEDIR);
}

// ---------------------------------------------------------------------------------- OutputDir

OutputDir OutputDir::Open(const fs::path& path, Create create) {
  fs::path p = path.empty() ? fs::path(".") : path;
  if (p.filename().empty() && p.has_parent_path() && p != p.root_path()) p = p.parent_path();
  if (create == Create::kYes) {
    std::error_code ec;
    fs::create_directories(p, ec);  // the user's own path: its folders may be links they made
  }
  const int fd = ::open(p.c_str(), kDirFlags);
  if (fd < 0) Throw(path, OpenFolderError(AT_FDCWD, p.c_str(), errno));
  return OutputDir(fd, path);
}

OutputDir OutputDir::Sub(const std::string& name, Create create) const {
  CheckComponent(path_, name);
  const fs::path shown = path_ / name;
  if (create == Create::kYes && ::mkdirat(fd_, name.c_str(), 0777) != 0 && errno != EEXIST) {
    Throw(shown, "cannot create the folder (" + Why(errno) + ")");
  }
  const int fd = ::openat(fd_, name.c_str(), kDirFlags);
  if (fd < 0) Throw(shown, OpenFolderError(fd_, name.c_str(), errno));
  return OutputDir(fd, shown);
}

OutputDir::OutputDir(OutputDir&& other) noexcept : fd_(other.fd_), path_(std::move(other.path_)) {
  other.fd_ = -1;
}

OutputDir& OutputDir::operator=(OutputDir&& other) noexcept {
  if (this != &other) {
    if (fd_ >= 0) ::close(fd_);
    fd_ = other.fd_;
    path_ = std::move(other.path_);
    other.fd_ = -1;
  }
  return *this;
}

OutputDir::~OutputDir() {
  if (fd_ >= 0) ::close(fd_);
}

// --------------------------------------------------------------------------------- AtomicFile

// A write buffer over the AtomicFile's descriptor; a failed write is kept for Commit().
class AtomicFile::Buffer : public std::streambuf {
 public:
  explicit Buffer(AtomicFile& file) : file_(file), data_(1 << 16) {
    setp(data_.data(), data_.data() + data_.size());
  }
  int error() const { return error_; }

 protected:
  int_type overflow(int_type ch) override {
    if (!Drain()) return traits_type::eof();
    if (!traits_type::eq_int_type(ch, traits_type::eof())) {
      *pptr() = traits_type::to_char_type(ch);
      pbump(1);
    }
    return traits_type::not_eof(ch);
  }
  int sync() override { return Drain() ? 0 : -1; }

 private:
  bool Drain() {
    if (error_ != 0) return false;
    const char* p = pbase();
    std::size_t left = static_cast<std::size_t>(pptr() - pbase());
    while (left > 0) {
      const ssize_t n = ::write(file_.fd_, p, left);
      if (n < 0 && errno == EINTR) continue;
      if (n <= 0) {
        error_ = n < 0 ? errno : EIO;
        return false;
      }
      p += n;
      left -= static_cast<std::size_t>(n);
    }
    setp(data_.data(), data_.data() + data_.size());
    return true;
  }
  AtomicFile& file_;
  std::vector<char> data_;
  int error_ = 0;
};

AtomicFile::AtomicFile(const OutputDir& dir, std::string name)
    : dir_path_(dir.path()), name_(std::move(name)) {
  CheckComponent(dir_path_, name_);
  dir_fd_ = Dup(dir.fd(), path());
  for (int attempt = 0; attempt < kAttempts && fd_ < 0; ++attempt) {
    // Short and not derived from the name: a valid 255-byte name still has a valid temporary.
    tmp_ = ".dvpr-" + RandomSuffix() + ".tmp";
    // O_RDWR: a caller may read back what another program wrote (a PNG is checked whole).
    fd_ = ::openat(dir_fd_, tmp_.c_str(), O_RDWR | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0666);
    if (fd_ < 0 && errno != EEXIST) {
      const int error = errno;
      ::close(dir_fd_);
      Throw(path(), "cannot open for writing (" + Why(error) + ")");
    }
  }
  if (fd_ < 0) {
    ::close(dir_fd_);
    Throw(path(), "cannot open for writing (no free temporary name)");
  }
  buffer_ = std::make_unique<Buffer>(*this);
  stream_ = std::make_unique<std::ostream>(buffer_.get());
}

AtomicFile::AtomicFile(const fs::path& path) : AtomicFile(OutputDir::Open(path.parent_path()), path.filename().string()) {}

AtomicFile::~AtomicFile() {
  if (fd_ >= 0) ::close(fd_);
  if (!committed_) ::unlinkat(dir_fd_, tmp_.c_str(), 0);
  ::close(dir_fd_);
}

fs::path AtomicFile::path() const { return dir_path_ / name_; }

std::ostream& AtomicFile::stream() { return *stream_; }

void AtomicFile::Fail(const std::string& what, int error) {
  if (fd_ >= 0) ::close(fd_);
  fd_ = -1;
  ::unlinkat(dir_fd_, tmp_.c_str(), 0);
  Throw(path(), what + " (" + Why(error) + ")");
}

void AtomicFile::Write(std::string_view bytes) {
  stream_->write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  if (!stream_->flush()) Fail("write failed", buffer_->error() != 0 ? buffer_->error() : EIO);
}

void AtomicFile::Commit() {
  if (committed_ || fd_ < 0) throw std::logic_error(path().string() + ": committed twice");
  if (!stream_->flush()) Fail("write failed", buffer_->error() != 0 ? buffer_->error() : EIO);
  const int fd = fd_;
  fd_ = -1;
  if (::close(fd) != 0 && errno != EINTR) Fail("write failed", errno);
  if (::renameat(dir_fd_, tmp_.c_str(), dir_fd_, name_.c_str()) != 0) {
    Fail("cannot rename into place", errno);
  }
  committed_ = true;
}

void WriteFileAt(const OutputDir& dir, const std::string& name, std::string_view bytes) {
  AtomicFile f(dir, name);
  f.Write(bytes);
  f.Commit();
}

void WriteFileAtomic(const fs::path& path, std::string_view bytes) {
  WriteFileAt(OutputDir::Open(path.parent_path()), path.filename().string(), bytes);
}

// --------------------------------------------------------------------------------- ScratchDir

ScratchDir::ScratchDir(const OutputDir& dir) : dir_path_(dir.path()) {
  dir_fd_ = Dup(dir.fd(), dir_path_);
  for (int attempt = 0; attempt < kAttempts && fd_ < 0; ++attempt) {
    name_ = ".dvpr-" + RandomSuffix() + ".scratch";
    fd_ = MakeFolderAt(dir_fd_, name_, 0700);
    if (fd_ < 0 && errno != EEXIST) {
      const int error = errno;
      ::close(dir_fd_);
      Throw(dir_path_, "cannot create a temporary folder (" + Why(error) + ")");
    }
  }
  if (fd_ < 0) {
    ::close(dir_fd_);
    Throw(dir_path_, "cannot create a temporary folder (no free name)");
  }
  path_ = dir_path_ / name_;
}

ScratchDir::~ScratchDir() {
  ::close(fd_);
  RemoveTreeAt(dir_fd_, name_);
  ::close(dir_fd_);
}

void ScratchDir::CommitFile(const std::string& name, const std::string& final_name) {
  CheckComponent(path_, name);
  CheckComponent(dir_path_, final_name);
  const fs::path shown = dir_path_ / final_name;
  struct stat st {};
  if (::fstatat(fd_, name.c_str(), &st, AT_SYMLINK_NOFOLLOW) != 0) {
    Throw(shown, "was not written (" + Why(errno) + ")");
  }
  if (!S_ISREG(st.st_mode)) Throw(shown, "was not written as a regular file");
  if (st.st_size == 0) Throw(shown, "was written empty (a full disk?)");
  if (::renameat(fd_, name.c_str(), dir_fd_, final_name.c_str()) != 0) {
    Throw(shown, "cannot rename into place (" + Why(errno) + ")");
  }
}

}  // namespace dvpr
