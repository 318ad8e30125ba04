#include "agents/auth/message_auth.h"

#include <openssl/core_names.h>
#include <openssl/crypto.h>
#include <openssl/evp.h>
#include <openssl/params.h>

#include <algorithm>
#include <stdexcept>
#include <string>

namespace dvpr::auth {

namespace {

constexpr char kDomain[] = "dvpr-tag-1";  // with its NUL
constexpr std::size_t kFieldBytes = 2 + 8 + 8;
constexpr std::uint64_t kSpan = 1024;

void Put(std::uint8_t* at, std::uint64_t v, int bytes) {
  for (int i = bytes - 1; i >= 0; --i, v >>= 8) at[i] = static_cast<std::uint8_t>(v & 0xff);
}

std::uint64_t Get(const std::uint8_t* at, int bytes) {
  std::uint64_t v = 0;
  for (int i = 0; i < bytes; ++i) v = v << 8 | at[i];
  return v;
}

[[noreturn]] void OpenSslFailed(const char* what) { throw std::runtime_error(std::string("HMAC-SHA-256: ") + what + " failed"); }

}  // namespace

std::uint64_t Origin::SenderKey() const {
  return (static_cast<std::uint64_t>(robot + 1) << 48) | (instance & 0xFFFFFFFFFFFFull);
}

int RobotOfSender(std::uint64_t sender) {
  const auto top = static_cast<int>(sender >> 48);
  return top >= 1 && top <= kMaxRobot + 1 ? top - 1 : -1;
}

struct MessageAuth::Mac {
  EVP_MAC* mac = nullptr;
  EVP_MAC_CTX* keyed = nullptr;  // initialised with the key; each tag works on a copy
  ~Mac() {
    EVP_MAC_CTX_free(keyed);
    EVP_MAC_free(mac);
  }
};

MessageAuth::MessageAuth(const Secret& secret, int robot, std::uint64_t instance)
    : mac_(std::make_unique<Mac>()), robot_(robot), instance_(instance & 0xFFFFFFFFFFFFull) {
  if (robot < -1 || robot > kMaxRobot) throw std::invalid_argument("MessageAuth: robot out of [0, 32767]");
  mac_->mac = EVP_MAC_fetch(nullptr, "HMAC", nullptr);
  if (mac_->mac == nullptr) OpenSslFailed("EVP_MAC_fetch");
  mac_->keyed = EVP_MAC_CTX_new(mac_->mac);
  if (mac_->keyed == nullptr) OpenSslFailed("EVP_MAC_CTX_new");
  char digest[] = "SHA256";
  const OSSL_PARAM params[] = {OSSL_PARAM_construct_utf8_string(OSSL_MAC_PARAM_DIGEST, digest, 0), OSSL_PARAM_construct_end()};
  if (EVP_MAC_init(mac_->keyed, secret.data(), secret.size(), params) != 1) OpenSslFailed("EVP_MAC_init");
  while (instance_ == 0) {
    const Secret r = DrawSecret();
    instance_ = Get(r.data(), 8) & 0xFFFFFFFFFFFFull;  // the sender key keeps 48 bits of it
  }
}

MessageAuth::~MessageAuth() = default;
MessageAuth::MessageAuth(MessageAuth&&) noexcept = default;
MessageAuth& MessageAuth::operator=(MessageAuth&&) noexcept = default;

void MessageAuth::Tag(std::string_view channel, std::span<const std::uint8_t> message,
                      std::span<const std::uint8_t, 18> fields, std::uint8_t* tag) const {
  EVP_MAC_CTX* ctx = EVP_MAC_CTX_dup(mac_->keyed);
  if (ctx == nullptr) OpenSslFailed("EVP_MAC_CTX_dup");
  static constexpr std::uint8_t kNul = 0;
  unsigned char full[32];
  std::size_t length = 0;
  const bool ok = EVP_MAC_update(ctx, reinterpret_cast<const unsigned char*>(kDomain), sizeof kDomain) == 1 &&
                  EVP_MAC_update(ctx, reinterpret_cast<const unsigned char*>(channel.data()), channel.size()) == 1 &&
                  EVP_MAC_update(ctx, &kNul, 1) == 1 && EVP_MAC_update(ctx, message.data(), message.size()) == 1 &&
                  EVP_MAC_update(ctx, fields.data(), fields.size()) == 1 &&
                  EVP_MAC_final(ctx, full, &length, sizeof full) == 1 && length == sizeof full;
  EVP_MAC_CTX_free(ctx);
  if (!ok) OpenSslFailed("computing a tag");
  std::copy(full, full + kTagBytes, tag);
  OPENSSL_cleanse(full, sizeof full);
}

void MessageAuth::Seal(std::string_view channel, std::vector<std::uint8_t>& message) {
  if (robot_ < 0) throw std::logic_error("MessageAuth::Seal: this process speaks for no robot");
  const std::size_t n = message.size();
  message.resize(n + kTrailerBytes);
  std::uint8_t* fields = message.data() + n;
  Put(fields, static_cast<std::uint64_t>(robot_), 2);
  Put(fields + 2, instance_, 8);
  Put(fields + 10, ++counter_, 8);
  Tag(channel, std::span<const std::uint8_t>(message.data(), n), std::span<const std::uint8_t, 18>(fields, 18),
      fields + kFieldBytes);
}

std::optional<Opened> MessageAuth::Open(std::string_view channel, std::span<const std::uint8_t> bytes) const {
  if (bytes.size() < kTrailerBytes) return std::nullopt;
  const std::size_t n = bytes.size() - kTrailerBytes;
  const std::uint8_t* fields = bytes.data() + n;
  std::uint8_t tag[kTagBytes];
  Tag(channel, bytes.first(n), std::span<const std::uint8_t, 18>(fields, 18), tag);
  if (CRYPTO_memcmp(tag, fields + kFieldBytes, kTagBytes) != 0) return std::nullopt;
  Opened o;
  o.message = bytes.first(n);
  o.origin.robot = static_cast<int>(Get(fields, 2));
  o.origin.instance = Get(fields + 2, 8);
  o.origin.counter = Get(fields + 10, 8);
  if (o.origin.robot > kMaxRobot) return std::nullopt;  // a holder of the secret that is not dvpr
  return o;
}

bool ReplayGuard::Take(const Origin& origin) {
  const auto key = std::make_pair(origin.robot, origin.instance);
  auto it = windows_.find(key);
  if (it == windows_.end()) {
    if (windows_.size() >= max_senders_) {
      windows_.erase(std::min_element(windows_.begin(), windows_.end(),
                                      [](const auto& a, const auto& b) { return a.second.last_use < b.second.last_use; }));
    }
    Window w;
    w.newest = origin.counter;
    w.bits[0] = 1;
    w.last_use = ++uses_;
    windows_.emplace(key, std::move(w));
    return true;
  }
  Window& w = it->second;
  w.last_use = ++uses_;
  if (origin.counter <= w.newest) {
    const std::uint64_t age = w.newest - origin.counter;
    if (age >= kSpan) return false;  // too old to tell: refused
    std::uint64_t& word = w.bits[age / 64];
    const std::uint64_t bit = std::uint64_t{1} << (age % 64);
    if (word & bit) return false;
    word |= bit;
    return true;
  }
  // Newer: every remembered counter gets `ahead` older.
  const std::uint64_t ahead = origin.counter - w.newest;
  std::vector<std::uint64_t> moved(w.bits.size(), 0);
  if (ahead < kSpan) {
    const std::size_t words = ahead / 64, shift = ahead % 64;
    for (std::size_t i = words; i < moved.size(); ++i) {
      moved[i] = w.bits[i - words] << shift;
      if (shift != 0 && i > words) moved[i] |= w.bits[i - words - 1] >> (64 - shift);
    }
  }
  w.bits = std::move(moved);
  w.bits[0] |= 1;
  w.newest = origin.counter;
  return true;
}

}  // namespace dvpr::auth
