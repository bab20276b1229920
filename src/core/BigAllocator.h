#pragma once
// An allocator for the large flat arrays of the mesh room (a million faces' relations, stencil
// tables) and the flame's game: blocks of 8 MB or more are mapped on 2 MB boundaries and advised
// as transparent huge pages, so that touching them costs one page fault per 2 MB instead of per
// 4 KB (on a virtual machine a page fault is dear: it was a third of a large mesh's setup).
// Smaller blocks, other systems and the sanitizer builds (which must see every block) use
// operator new on a 64-byte boundary, so that a vector register's loads and stores of whole
// registers never split across two cache lines (the flame's stacks: 1-3 % faster). Qt-free.

#include <cstddef>
#include <new>
#include <vector>

namespace awb {

namespace bigalloc {
// nullptr when the block is small or huge pages are not available here.
void *allocate(std::size_t bytes);
// true when `p` came from allocate() (and is released).
bool release(void *p, std::size_t bytes);
} // namespace bigalloc

template <class T>
struct BigAllocator {
    static constexpr std::align_val_t kLine{64};
    using value_type = T;
    BigAllocator() = default;
    template <class U>
    BigAllocator(const BigAllocator<U> &)
    {
    }
    T *allocate(std::size_t n)
    {
        if (n > std::size_t(-1) / sizeof(T))
            throw std::bad_array_new_length();
        if (void *p = bigalloc::allocate(n * sizeof(T)))
            return static_cast<T *>(p);
        return static_cast<T *>(::operator new(n * sizeof(T), kLine));
    }
    void deallocate(T *p, std::size_t n)
    {
        if (!bigalloc::release(p, n * sizeof(T)))
            ::operator delete(p, kLine);
    }
    template <class U>
    bool operator==(const BigAllocator<U> &) const
    {
        return true;
    }
};

template <class T>
using BigVector = std::vector<T, BigAllocator<T>>;

} // namespace awb
