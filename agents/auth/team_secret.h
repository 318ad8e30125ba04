#pragma once
// The secret a launched team shares (docs/security.md): 32 random bytes drawn afresh by each
// `dvpr launch` and handed to its agents in a file only the launching user can read. Whoever
// holds it can speak for any robot of the team; whoever does not cannot (message_auth.h).
//
// The file holds the secret as 64 hexadecimal digits, optionally followed by one newline. It is
// refused, with a message naming the file and what is wrong, when it is not a regular file (a
// FIFO, a device, a directory), a symbolic link (a link loop included), readable or writable by
// its group or by others, owned by another user, or of any other content.
#include <array>
#include <cstdint>
#include <filesystem>
#include <string>

namespace dvpr::auth {

inline constexpr std::size_t kSecretBytes = 32;
using Secret = std::array<std::uint8_t, kSecretBytes>;

// 32 bytes from the kernel's random source (getrandom). Throws std::runtime_error if it fails.
Secret DrawSecret();

// Reads a secret file (above). Throws std::invalid_argument "<what>: <file>: <problem>".
Secret ReadSecretFile(const std::filesystem::path& path, const std::string& what = "--team-secret");

// Writes `secret` to a new file (never through a link, never over an existing file), readable by
// its owner only. Throws std::runtime_error naming the file.
void WriteSecretFile(const std::filesystem::path& path, const Secret& secret);

// A private folder for a secret file: made with mkdtemp under `parent`, mode 0700; removed with
// what is in it when the object goes away.
class SecretFolder {
 public:
  explicit SecretFolder(const std::filesystem::path& parent);
  ~SecretFolder();
  SecretFolder(const SecretFolder&) = delete;
  SecretFolder& operator=(const SecretFolder&) = delete;
  const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path path_;
};

}  // namespace dvpr::auth
