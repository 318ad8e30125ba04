#include "net_models/core/payload_buffers.h"

#include <algorithm>
#include <bit>
#include <utility>

namespace dvpr {

int PayloadBuffers::ClassOf(std::size_t capacity) { return std::bit_width(capacity) - 1; }

std::size_t PayloadBuffers::LimitOf(int size_class) { return std::max(kPerClass, kClassBytes >> size_class); }

std::vector<std::uint8_t> PayloadBuffers::Take(std::size_t size) {
  if (size == 0 || size > kMaxKept) return {};
  // The class of `size` itself may hold buffers below it: only its largest candidate, the last
  // one given, is looked at; the classes above hold only buffers large enough.
  const int own = ClassOf(size);
  auto& same = kept_[static_cast<std::size_t>(own)];
  if (!same.empty() && same.back().capacity() >= size) {
    std::vector<std::uint8_t> bytes = std::move(same.back());
    same.pop_back();
    kept_bytes_ -= bytes.capacity();
    return bytes;
  }
  for (int c = own + 1; c < kClasses && c <= own + 4; ++c) {
    auto& bin = kept_[static_cast<std::size_t>(c)];
    if (bin.empty()) continue;
    std::vector<std::uint8_t> bytes = std::move(bin.back());
    bin.pop_back();
    kept_bytes_ -= bytes.capacity();
    return bytes;
  }
  return {};
}

void PayloadBuffers::Give(std::vector<std::uint8_t>&& bytes) {
  const std::size_t capacity = bytes.capacity();
  if (capacity == 0 || capacity > kMaxKept) return;
  const int size_class = ClassOf(capacity);
  auto& bin = kept_[static_cast<std::size_t>(size_class)];
  if (bin.size() >= LimitOf(size_class) || kept_bytes_ + capacity > kMaxKeptBytes) return;
  kept_bytes_ += capacity;
  bin.push_back(std::move(bytes));
}

std::size_t PayloadBuffers::Kept() const {
  std::size_t n = 0;
  for (const auto& bin : kept_) n += bin.size();
  return n;
}

}  // namespace dvpr
