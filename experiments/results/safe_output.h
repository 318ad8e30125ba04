#pragma once
// The one way dvpr puts a file in place (README "Result folders", "Security"). Every output is
// written relative to an open folder (OutputDir, opened O_DIRECTORY|O_NOFOLLOW) into a private
// temporary name that this process created exclusively (O_CREAT|O_EXCL|O_NOFOLLOW, an
// unpredictable random name), every write and the close are checked (a full disk is an error, not
// a short file), and only then is it renamed over its final name (renameat, which replaces a link
// planted there instead of following it). So no output path follows a symbolic link dvpr did not
// make, a reader never sees half a file, and an error leaves the earlier file as it was.
//
//   OutputDir dir = OutputDir::Open(folder);            // or parent.Sub("figures")
//   WriteFileAt(dir, "summary.json", text);              // a whole file at once
//   AtomicFile f(dir, "runs.csv"); f.stream() << ...; f.Commit();   // row by row
//   ScratchDir s(dir); /* gnuplot writes s.path() / "x.png" */ s.CommitFile("x.png", "x.png");
#include <fcntl.h>

#include <filesystem>
#include <memory>
#include <ostream>
#include <string>
#include <string_view>

namespace dvpr {

// An open folder that outputs are made in. Move-only; closes its descriptor.
class OutputDir {
 public:
  enum class Create { kNo, kYes };
  // Opens `path` (its last component is never followed through a symbolic link; the folders
  // above it are the user's to choose). With Create::kYes, makes it and its parents first.
  // Throws std::runtime_error naming `path`: absent, not a folder, a symbolic link, no access.
  static OutputDir Open(const std::filesystem::path& path, Create create = Create::kNo);
  // The folder `name` (one path component) inside this one, made (mode 0777 minus the umask)
  // when absent and `create` is kYes. A symbolic link there is refused, naming it.
  OutputDir Sub(const std::string& name, Create create = Create::kYes) const;

  OutputDir(OutputDir&& other) noexcept;
  OutputDir& operator=(OutputDir&& other) noexcept;
  OutputDir(const OutputDir&) = delete;
  OutputDir& operator=(const OutputDir&) = delete;
  ~OutputDir();

  int fd() const { return fd_; }
  // The path it was opened by: for messages, and for a program that takes a path.
  const std::filesystem::path& path() const { return path_; }

 private:
  OutputDir(int fd, std::filesystem::path path) : fd_(fd), path_(std::move(path)) {}
  int fd_ = -1;
  std::filesystem::path path_;
};

// A file made under a private temporary name in `dir` and renamed over `name` by Commit(); an
// uncommitted one is removed by the destructor (an error halfway leaves nothing behind, and the
// earlier file at `name` as it was). `name` is one path component. The file is mode 0666 minus
// the umask, as std::ofstream made it.
class AtomicFile {
 public:
  AtomicFile(const OutputDir& dir, std::string name);
  // Convenience for a path: opens its folder with OutputDir::Open (not created).
  explicit AtomicFile(const std::filesystem::path& path);
  ~AtomicFile();
  AtomicFile(const AtomicFile&) = delete;
  AtomicFile& operator=(const AtomicFile&) = delete;

  // Buffered; a failed write (ENOSPC, EIO) is remembered and reported by Commit().
  std::ostream& stream();
  // Appends `bytes` (throws std::runtime_error naming the file at once if a write fails).
  void Write(std::string_view bytes);
  // The open temporary, for a writer that needs a descriptor (the LCM event log writes through
  // fdopen(dup(fd()))): flush and close what you made of it before Commit(). Do not mix with
  // stream().
  int fd() const { return fd_; }
  // Flushes, closes (checked), and renames the temporary over the final name. Throws
  // std::runtime_error naming the file (the temporary is removed then).
  void Commit();

  // The final path, for messages.
  std::filesystem::path path() const;

 private:
  class Buffer;
  void Fail(const std::string& what, int error);
  std::filesystem::path dir_path_;
  int dir_fd_ = -1;  // a duplicate of the OutputDir's: an AtomicFile may outlive it
  std::string name_;
  std::string tmp_;
  int fd_ = -1;
  std::unique_ptr<Buffer> buffer_;
  std::unique_ptr<std::ostream> stream_;
  bool committed_ = false;
};

// `bytes` as the file `name` in `dir`, through an AtomicFile.
void WriteFileAt(const OutputDir& dir, const std::string& name, std::string_view bytes);
// The same for a path (its folder opened with OutputDir::Open, not created).
void WriteFileAtomic(const std::filesystem::path& path, std::string_view bytes);

// A private folder (mode 0700, a random name) inside `dir` for files that another program
// writes by path (gnuplot's `set output`): nobody else can plant a file or a link in it. The
// destructor removes it with whatever is left in it.
class ScratchDir {
 public:
  explicit ScratchDir(const OutputDir& dir);
  ~ScratchDir();
  ScratchDir(const ScratchDir&) = delete;
  ScratchDir& operator=(const ScratchDir&) = delete;

  // The folder's path, to hand to the program.
  const std::filesystem::path& path() const { return path_; }
  // Renames the file `name` the program wrote here over `final_name` in `dir`. Throws
  // std::runtime_error naming final_name if `name` is missing, not a regular file, or empty
  // (a program that could not write its output, e.g. on a full disk).
  void CommitFile(const std::string& name, const std::string& final_name);

 private:
  std::filesystem::path dir_path_;
  int dir_fd_ = -1;
  int fd_ = -1;
  std::string name_;
  std::filesystem::path path_;
};

// How a folder is opened to write in or read below it: never through a symbolic link.
inline constexpr int kDirFlags = O_RDONLY | O_DIRECTORY | O_NOFOLLOW | O_CLOEXEC;

// 16 lowercase hex digits from the kernel's random source (getrandom): an unpredictable part of
// a temporary name.
std::string RandomSuffix();

// Creates the folder `name` in `dir_fd` exclusively (mkdirat; EEXIST is reported, a link is never
// followed) and returns it open (O_DIRECTORY|O_NOFOLLOW); -1 with errno set on failure.
int MakeFolderAt(int dir_fd, const std::string& name, unsigned mode);

// Removes `name` in `dir_fd` and, when it is a folder, everything below it, never following a
// symbolic link (a link is removed, not its target). Errors are ignored.
void RemoveTreeAt(int dir_fd, const std::string& name);

}  // namespace dvpr
