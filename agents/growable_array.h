#pragma once
// A vector of trivially copyable values that grows without copying its rows or touching memory
// again once it is large (a robot's store: IncrementalIndex, HalfScreen).
//
// Why: a std::vector that grows allocates a new buffer, copies every value and frees the old one;
// 1000 stores of up to 5342 rows doing that kept the kernel busy zeroing fresh pages for the new
// buffers (the 10^6-frame x 1000-robot run, docs/performance.md). Here a buffer of at least
// kMapBytes is its own memory mapping and grows with mremap, which moves the page table, not the
// bytes: each page is zeroed once, when a value is first written into it. Smaller buffers (and
// systems without mremap) use malloc and realloc.
#include <cstddef>
#include <cstring>
#include <type_traits>
#include <utility>

namespace dvpr {
namespace growable_detail {

// Storage of `bytes` that keeps the first `kept` bytes of `p`, a buffer of `capacity` bytes from
// Resize (nullptr and 0: none).
void* Resize(void* p, std::size_t capacity, std::size_t kept, std::size_t bytes);
void Release(void* p, std::size_t bytes);
// Buffers from this size on are memory mappings.
inline constexpr std::size_t kMapBytes = std::size_t{256} << 10;

}  // namespace growable_detail

template <typename T>
class GrowableArray {
  static_assert(std::is_trivially_copyable_v<T>, "GrowableArray moves values as bytes");

 public:
  GrowableArray() = default;
  GrowableArray(const GrowableArray& o) { Append(o.data_, o.size_); }
  GrowableArray(GrowableArray&& o) noexcept { Swap(o); }
  GrowableArray& operator=(const GrowableArray& o) {
    if (this != &o) {
      clear();
      Append(o.data_, o.size_);
    }
    return *this;
  }
  GrowableArray& operator=(GrowableArray&& o) noexcept {
    GrowableArray moved(std::move(o));
    Swap(moved);
    return *this;
  }
  ~GrowableArray() { growable_detail::Release(data_, capacity_ * sizeof(T)); }

  T* data() { return data_; }
  const T* data() const { return data_; }
  std::size_t size() const { return size_; }
  bool empty() const { return size_ == 0; }
  T& operator[](std::size_t i) { return data_[i]; }
  const T& operator[](std::size_t i) const { return data_[i]; }
  T* begin() { return data_; }
  T* end() { return data_ + size_; }
  const T* begin() const { return data_; }
  const T* end() const { return data_ + size_; }
  const T& back() const { return data_[size_ - 1]; }

  void push_back(const T& value) { Append(&value, 1); }
  void Append(const T* values, std::size_t count) {
    Reserve(size_ + count);
    if (count > 0) std::memcpy(data_ + size_, values, count * sizeof(T));
    size_ += count;
  }
  // New values are zero bytes.
  void resize(std::size_t size) {
    Reserve(size);
    if (size > size_) std::memset(static_cast<void*>(data_ + size_), 0, (size - size_) * sizeof(T));
    size_ = size;
  }
  void clear() { size_ = 0; }  // keeps the storage

 private:
  void Reserve(std::size_t size) {
    if (size <= capacity_) return;
    std::size_t capacity = capacity_ < 8 ? 8 : capacity_ * 2;
    while (capacity < size) capacity *= 2;
    data_ = static_cast<T*>(growable_detail::Resize(data_, capacity_ * sizeof(T), size_ * sizeof(T), capacity * sizeof(T)));
    capacity_ = capacity;
  }
  void Swap(GrowableArray& o) noexcept {
    std::swap(data_, o.data_);
    std::swap(size_, o.size_);
    std::swap(capacity_, o.capacity_);
  }

  T* data_ = nullptr;
  std::size_t size_ = 0;
  std::size_t capacity_ = 0;
};

}  // namespace dvpr
