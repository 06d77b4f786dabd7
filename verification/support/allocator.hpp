#pragma once
// Process-wide allocator setting of sphv and its tests: freed memory stays in the process. The
// pair loops build and drop neighbour lists of megabytes at every step; glibc would hand large
// blocks back to the kernel (mmap'ed blocks, heap trimming) and each step would pay page faults
// and zeroing to get them back: measured a third of a 3D Noh run and half of a full hydro step at
// N = 2e5 (`sphv bench`). The resident size stays at its peak instead.
#if defined(__GLIBC__)
#include <malloc.h>

#include <climits>
#endif

namespace sphv {

inline void keep_freed_memory() {
#if defined(__GLIBC__)
  mallopt(M_MMAP_MAX, 0);              // every block from the heap, none mmap'ed
  mallopt(M_TRIM_THRESHOLD, INT_MAX);  // and the heap's top never given back
#endif
}

}  // namespace sphv
