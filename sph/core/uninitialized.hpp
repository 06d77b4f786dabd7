#pragma once
// An allocator that default-initialises: resize() of a vector of ints or doubles with it leaves
// the new entries unset instead of writing zeros. For arrays every entry of which is written
// right after the resize (neighbour lists, position columns): zeros written first would be a
// memset of the whole list, on one thread, at every search and every pair selection.
#include <algorithm>
#include <cstddef>
#include <memory>
#include <new>
#include <utility>

namespace sph {

template <class T>
struct DefaultInitAllocator : std::allocator<T> {
  template <class U>
  struct rebind {
    using other = DefaultInitAllocator<U>;
  };
  DefaultInitAllocator() = default;
  template <class U>
  DefaultInitAllocator(const DefaultInitAllocator<U>&) noexcept {}

  template <class U>
  void construct(U* p) noexcept {
    ::new (static_cast<void*>(p)) U;
  }
  template <class U, class... Args>
  void construct(U* p, Args&&... args) {
    ::new (static_cast<void*>(p)) U(std::forward<Args>(args)...);
  }
};

// v resized to n entries that the caller then writes, every one. When v must grow, it moves to a
// block an eighth larger than n, without copying its entries: a neighbour list a few pairs longer
// than at the last search then stays where it is, instead of moving to fresh pages that the kernel
// faults in and zeroes.
template <class V>
void resize_for_overwrite(V& v, std::size_t n) {
  if (n > v.capacity()) {
    v.clear();
    v.reserve(n + n / 8);
  }
  v.resize(n);
}

// v (with DefaultInitAllocator) grown to n entries, its first `kept` ones kept and the rest unset:
// in place when its block holds n, else only those copied to a new one. A vector's own growth
// copies all of its entries, the unwritten ones too, and so writes (faults in) the new block up to
// its old size.
template <class V>
void grow_keeping(V& v, std::size_t kept, std::size_t n) {
  if (n <= v.capacity()) return v.resize(n);
  V w;
  resize_for_overwrite(w, n);
  std::copy_n(v.begin(), kept, w.begin());
  v.swap(w);
}

}  // namespace sph
