#include "core/BigAllocator.h"

#if defined(__linux__)
#include <sys/mman.h>
#endif
#include <cstdint>

namespace awb::bigalloc {

namespace {

#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
constexpr bool kMapped = false;  // the sanitizers must see every block
#elif defined(__linux__) && defined(MADV_HUGEPAGE)
constexpr bool kMapped = true;
#else
constexpr bool kMapped = false;
#endif

constexpr std::size_t kHuge = std::size_t(2) << 20;
constexpr std::size_t kThreshold = std::size_t(4) << 20;

// The same test in allocate() and release(): a block's size says where it came from.
bool mapped(std::size_t bytes) { return kMapped && bytes >= kThreshold; }

std::size_t roundUp(std::size_t bytes) { return (bytes + kHuge - 1) & ~(kHuge - 1); }

} // namespace

void *allocate(std::size_t bytes)
{
    if (!mapped(bytes))
        return nullptr;
#if defined(__linux__) && defined(MADV_HUGEPAGE)
    const std::size_t length = roundUp(bytes);
    void *raw = mmap(nullptr, length + kHuge, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS,
                     -1, 0);
    if (raw == MAP_FAILED)
        throw std::bad_alloc();
    // Keep the 2 MB-aligned part, give back the rest.
    const auto begin = reinterpret_cast<std::uintptr_t>(raw);
    const std::uintptr_t aligned = (begin + kHuge - 1) & ~std::uintptr_t(kHuge - 1);
    const std::uintptr_t end = begin + length + kHuge;
    if (aligned > begin)
        munmap(raw, aligned - begin);
    if (end > aligned + length)
        munmap(reinterpret_cast<void *>(aligned + length), end - (aligned + length));
    madvise(reinterpret_cast<void *>(aligned), length, MADV_HUGEPAGE);
    return reinterpret_cast<void *>(aligned);
#else
    return nullptr;
#endif
}

bool release(void *p, std::size_t bytes)
{
    if (!mapped(bytes))
        return false;
#if defined(__linux__) && defined(MADV_HUGEPAGE)
    munmap(p, roundUp(bytes));
#endif
    return true;
}

} // namespace awb::bigalloc
