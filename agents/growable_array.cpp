#include "agents/growable_array.h"

#include <cstdlib>
#include <new>

#if defined(__linux__)
#include <sys/mman.h>
#define DVPR_GROWABLE_MREMAP 1
#else
#define DVPR_GROWABLE_MREMAP 0
#endif

namespace dvpr::growable_detail {
namespace {

#if DVPR_GROWABLE_MREMAP
constexpr std::size_t kHugePage = std::size_t{2} << 20;

// Regions of a huge page or more ask for huge pages (the stores are scanned end to end: fewer
// TLB misses); the system may decline, which changes nothing but speed.
void AdviseHuge(void* p, std::size_t bytes) {
  if (bytes >= kHugePage) madvise(p, bytes, MADV_HUGEPAGE);
}
#endif

}  // namespace

void* Resize(void* p, std::size_t capacity, std::size_t kept, std::size_t bytes) {
#if DVPR_GROWABLE_MREMAP
  if (bytes >= kMapBytes) {
    void* q = MAP_FAILED;
    if (p != nullptr && capacity >= kMapBytes) {
      q = mremap(p, capacity, bytes, MREMAP_MAYMOVE);
    } else {
      q = mmap(nullptr, bytes, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
      if (q != MAP_FAILED && p != nullptr) {
        std::memcpy(q, p, kept);
        std::free(p);
      }
    }
    if (q == MAP_FAILED) throw std::bad_alloc();
    AdviseHuge(q, bytes);
    return q;
  }
#else
  (void)capacity;
#endif
  (void)kept;  // realloc keeps the whole buffer
  void* q = std::realloc(p, bytes);
  if (q == nullptr) throw std::bad_alloc();
  return q;
}

void Release(void* p, std::size_t bytes) {
  if (p == nullptr) return;
#if DVPR_GROWABLE_MREMAP
  if (bytes >= kMapBytes) {
    munmap(p, bytes);
    return;
  }
#else
  (void)bytes;
#endif
  std::free(p);
}

}  // namespace dvpr::growable_detail
