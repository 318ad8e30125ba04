#pragma once
// A type-erased `void()` callable stored in place when it is small (most
// events capture a pointer and an index or two), so scheduling an event does
// not allocate. Larger callables fall back to one heap allocation. It is
// neither copyable nor movable: the Simulator keeps it in storage whose
// addresses never change and invokes it where it lies.
#include <cstddef>
#include <new>
#include <type_traits>
#include <utility>

namespace dvpr {

class EventCallback {
 public:
  // Room for a std::function (32 bytes on libstdc++) or a lambda capturing up
  // to five pointers; with the two function pointers and the Simulator's key,
  // a slot is one 64-byte cache line.
  static constexpr std::size_t kInlineSize = 40;
  static constexpr std::size_t kInlineAlign = alignof(void*);

  EventCallback() = default;
  EventCallback(const EventCallback&) = delete;
  EventCallback& operator=(const EventCallback&) = delete;
  ~EventCallback() { Reset(); }

  template <typename F>
  void Emplace(F&& f) {
    using D = std::decay_t<F>;
    static_assert(std::is_invocable_v<D&>, "an event callback must be callable with no arguments");
    Reset();
    if constexpr (sizeof(D) <= kInlineSize && alignof(D) <= kInlineAlign) {
      ::new (static_cast<void*>(buf_)) D(std::forward<F>(f));
      invoke_ = [](void* p) { (*static_cast<D*>(p))(); };
      destroy_ = std::is_trivially_destructible_v<D> ? nullptr : +[](void* p) { static_cast<D*>(p)->~D(); };
    } else {
      ::new (static_cast<void*>(buf_)) D*(new D(std::forward<F>(f)));
      invoke_ = [](void* p) { (**static_cast<D**>(p))(); };
      destroy_ = [](void* p) { delete *static_cast<D**>(p); };
    }
  }

  explicit operator bool() const { return invoke_ != nullptr; }
  void operator()() { invoke_(buf_); }

  void Reset() {
    if (destroy_ != nullptr) destroy_(buf_);
    invoke_ = nullptr;
    destroy_ = nullptr;
  }

 private:
  using Fn = void (*)(void*);
  alignas(kInlineAlign) unsigned char buf_[kInlineSize];
  Fn invoke_ = nullptr;
  Fn destroy_ = nullptr;  // null when there is nothing to destroy
};

}  // namespace dvpr
