#pragma once
// An allocator that default-initialises: resize() of a vector of ints or doubles with it leaves
// the new entries unset instead of writing zeros. For arrays every entry of which is written
// right after the resize (neighbour lists, position columns): at N = 125,000 the zeros of the
// lists were a 31 MB memset, on one thread, per search and per pair selection.
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
// faults in and zeroes. Measured at N = 1e6 (`sphv bench`, interleaved with the code before, two
// rounds): a 33-step run's page faults 0.42 M -> 0.01 M on one thread, evolve's step 1.08 -> 0.86 s
// and 1.31 -> 1.24 s on one thread, 0.67 -> 0.58 s and 0.85 -> 0.70 s on two.
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
