#include "experiments/domain/data/npy.h"

#include <unistd.h>

#include <atomic>
#include <bit>
#include <cctype>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <limits>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "experiments/domain/data/printable.h"
#include "experiments/domain/data/text_file.h"

namespace dvpr {
namespace {

static_assert(std::endian::native == std::endian::little,
              "npy I/O copies little-endian data as is; a big-endian host needs byte swaps");

constexpr char kMagic[] = "\x93NUMPY";
constexpr std::size_t kMagicLen = 6;
constexpr std::size_t kAlign = 64;
// numpy >= 1.24 leaves room in the header so the first axis can grow in place.
constexpr std::size_t kGrowthAxisMaxDigits = 21;

[[noreturn]] void Fail(const std::filesystem::path& path, const std::string& what) {
  throw std::runtime_error("npy file " + path.string() + ": " + what);
}

struct NpyHeader {
  std::string descr;
  bool fortran_order = false;
  std::vector<std::uint64_t> shape;
};

// Scanner for the Python dict literal in the header, e.g.
// {'descr': '<f4', 'fortran_order': False, 'shape': (3, 4), }
class HeaderParser {
 public:
  HeaderParser(const std::filesystem::path& path, std::string text)
      : path_(path), text_(std::move(text)) {}

  NpyHeader Parse() {
    NpyHeader h;
    bool have_descr = false, have_order = false, have_shape = false;
    Expect('{');
    while (!Accept('}')) {
      const std::string key = QuotedString();
      Expect(':');
      if (key == "descr") {
        h.descr = QuotedString();
        have_descr = true;
      } else if (key == "fortran_order") {
        h.fortran_order = Boolean();
        have_order = true;
      } else if (key == "shape") {
        h.shape = Tuple();
        have_shape = true;
      } else {
        Bad("unknown key '" + Printable(key) + "'");
      }
      if (!Accept(',')) {
        Expect('}');
        break;
      }
    }
    if (!have_descr || !have_order || !have_shape) {
      Bad("expected keys 'descr', 'fortran_order' and 'shape'");
    }
    return h;
  }

 private:
  [[noreturn]] void Bad(const std::string& what) const {
    // The header is the file's bytes: quoted, so the message stays one line whatever they hold.
    Fail(path_, "bad header (" + what + "): '" + Printable(text_) + "'");
  }
  void SkipSpace() {
    while (pos_ < text_.size() && std::isspace(static_cast<unsigned char>(text_[pos_]))) ++pos_;
  }
  bool Accept(char c) {
    SkipSpace();
    if (pos_ < text_.size() && text_[pos_] == c) {
      ++pos_;
      return true;
    }
    return false;
  }
  void Expect(char c) {
    if (!Accept(c)) Bad(std::string("expected '") + c + "'");
  }
  std::string QuotedString() {
    SkipSpace();
    if (pos_ >= text_.size() || (text_[pos_] != '\'' && text_[pos_] != '"')) {
      Bad("expected a quoted string");
    }
    const char quote = text_[pos_++];
    const std::size_t end = text_.find(quote, pos_);
    if (end == std::string::npos) Bad("unterminated string");
    std::string s = text_.substr(pos_, end - pos_);
    pos_ = end + 1;
    return s;
  }
  bool Boolean() {
    SkipSpace();
    for (const auto& [word, value] : {std::pair{"True", true}, std::pair{"False", false}}) {
      const std::size_t n = std::strlen(word);
      if (text_.compare(pos_, n, word) == 0) {
        pos_ += n;
        return value;
      }
    }
    Bad("expected True or False");
  }
  std::vector<std::uint64_t> Tuple() {
    std::vector<std::uint64_t> dims;
    Expect('(');
    while (!Accept(')')) {
      SkipSpace();
      std::uint64_t v = 0;
      const std::size_t start = pos_;
      while (pos_ < text_.size() && std::isdigit(static_cast<unsigned char>(text_[pos_]))) {
        if (v > (std::numeric_limits<std::uint64_t>::max() - 9) / 10) Bad("dimension too large");
        v = v * 10 + static_cast<std::uint64_t>(text_[pos_++] - '0');
      }
      if (pos_ == start) Bad("expected a non-negative integer in shape");
      dims.push_back(v);
      if (!Accept(',')) {
        Expect(')');
        break;
      }
    }
    return dims;
  }

  const std::filesystem::path& path_;
  std::string text_;
  std::size_t pos_ = 0;
};

std::vector<char> ReadAll(const std::filesystem::path& path) {
  if (const std::string why = text_file::ThereButNotARegularFile(path); !why.empty()) Fail(path, why);
  std::ifstream in(path, std::ios::binary);
  if (!in) Fail(path, "cannot open for reading");
  std::vector<char> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (in.bad()) Fail(path, "read error");
  return bytes;
}

std::uint32_t LittleEndian(const char* p, int n) {
  std::uint32_t v = 0;
  for (int i = n - 1; i >= 0; --i) v = (v << 8) | static_cast<unsigned char>(p[i]);
  return v;
}

// Returns the header and the offset where the data starts.
std::pair<NpyHeader, std::size_t> ParsePreamble(const std::filesystem::path& path,
                                                const std::vector<char>& bytes) {
  if (bytes.size() < kMagicLen + 2 || std::memcmp(bytes.data(), kMagic, kMagicLen) != 0) {
    Fail(path, "bad magic: not a .npy file (expected \\x93NUMPY)");
  }
  const int major = static_cast<unsigned char>(bytes[6]);
  if (major < 1 || major > 3) {
    Fail(path, "unsupported format version " + std::to_string(major) + " (expected 1, 2 or 3)");
  }
  const int len_bytes = major == 1 ? 2 : 4;
  const std::size_t prefix = kMagicLen + 2 + static_cast<std::size_t>(len_bytes);
  if (bytes.size() < prefix) Fail(path, "truncated header");
  const std::size_t header_len = LittleEndian(bytes.data() + kMagicLen + 2, len_bytes);
  if (bytes.size() - prefix < header_len) Fail(path, "truncated header");
  std::string text(bytes.data() + prefix, header_len);
  return {HeaderParser(path, std::move(text)).Parse(), prefix + header_len};
}

template <typename T>
DescriptorMatrix Convert(const char* data, Eigen::Index rows, Eigen::Index cols, bool fortran) {
  DescriptorMatrix m(rows, cols);
  // No values: return at once, not after 2^31 empty rows (a 128-byte file of shape
  // (2147483647, 0) took seconds; found by fuzz_npy).
  if (m.size() == 0) return m;
  for (Eigen::Index i = 0; i < rows; ++i) {
    for (Eigen::Index j = 0; j < cols; ++j) {
      const Eigen::Index k = fortran ? j * rows + i : i * cols + j;
      T v;
      std::memcpy(&v, data + k * static_cast<Eigen::Index>(sizeof(T)), sizeof(T));
      m(i, j) = static_cast<float>(v);
    }
  }
  return m;
}

}  // namespace

DescriptorMatrix ReadNpyMatrix(const std::filesystem::path& path) {
  const std::vector<char> bytes = ReadAll(path);
  const auto [header, offset] = ParsePreamble(path, bytes);
  if (header.shape.size() != 2) {
    Fail(path, "expected a 2-D array (frames x dims), got " + std::to_string(header.shape.size()) +
                   "-D");
  }
  std::size_t item = 0;
  if (header.descr == "<f4") {
    item = 4;
  } else if (header.descr == "<f8") {
    item = 8;
  } else {
    Fail(path, "unsupported dtype '" + Printable(header.descr) +
                   "' (expected little-endian float32 '<f4' or float64 '<f8')");
  }
  const std::uint64_t rows = header.shape[0], cols = header.shape[1];
  const std::uint64_t limit = std::numeric_limits<std::int32_t>::max();
  if (rows > limit || cols > limit || (cols != 0 && rows > limit * 64 / cols)) {
    Fail(path, "shape too large");
  }
  const std::size_t need = rows * cols * item;
  const std::size_t have = bytes.size() - offset;
  if (have < need) {
    Fail(path, "truncated: shape (" + std::to_string(rows) + ", " + std::to_string(cols) +
                   ") needs " + std::to_string(need) + " data bytes, file has " +
                   std::to_string(have));
  }
  if (have > need) {
    Fail(path, "has " + std::to_string(have - need) + " bytes after the data of shape (" +
                   std::to_string(rows) + ", " + std::to_string(cols) + ")");
  }
  const auto r = static_cast<Eigen::Index>(rows), c = static_cast<Eigen::Index>(cols);
  const char* data = bytes.data() + offset;
  return item == 4 ? Convert<float>(data, r, c, header.fortran_order)
                   : Convert<double>(data, r, c, header.fortran_order);
}

namespace {

std::string NpyHeaderBytes(Eigen::Index rows, Eigen::Index cols) {
  const std::string first = std::to_string(rows);
  std::string dict = "{'descr': '<f4', 'fortran_order': False, 'shape': (" + first + ", " +
                     std::to_string(cols) + "), }";
  if (first.size() < kGrowthAxisMaxDigits) dict.append(kGrowthAxisMaxDigits - first.size(), ' ');
  const std::size_t prefix = kMagicLen + 2 + 2;
  // numpy always pads by 1..64 spaces (never 0), then the newline.
  const std::size_t pad = kAlign - ((prefix + dict.size() + 1) % kAlign);
  dict.append(pad, ' ');
  dict.push_back('\n');
  std::string out(kMagic, kMagicLen);
  out.push_back('\x01');
  out.push_back('\x00');
  out.push_back(static_cast<char>(dict.size() & 0xff));
  out.push_back(static_cast<char>((dict.size() >> 8) & 0xff));
  return out + dict;
}

std::filesystem::path TempPathNextTo(const std::filesystem::path& path) {
  static std::atomic<unsigned> counter{0};
  std::filesystem::path tmp = path;
  tmp += ".tmp." + std::to_string(::getpid()) + "." + std::to_string(counter++);
  return tmp;
}

}  // namespace

std::string NpyBytes(const DescriptorMatrix& m) {
  std::string bytes = NpyHeaderBytes(m.rows(), m.cols());
  const char* data = reinterpret_cast<const char*>(m.data());
  bytes.append(data, static_cast<std::size_t>(m.size()) * sizeof(float));
  return bytes;
}

void WriteNpy(const std::filesystem::path& path, const DescriptorMatrix& m) {
  const std::filesystem::path tmp = TempPathNextTo(path);
  try {
    std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
    if (!out) Fail(path, "cannot open temporary file " + tmp.string() + " for writing");
    const std::string bytes = NpyBytes(m);
    out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
    out.close();
    if (!out) Fail(path, "write error on temporary file " + tmp.string());
    std::filesystem::rename(tmp, path);
  } catch (...) {
    std::error_code ignored;
    std::filesystem::remove(tmp, ignored);
    throw;
  }
}

}  // namespace dvpr
