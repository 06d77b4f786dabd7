#pragma once
#include <algorithm>
#include <atomic>
#include <cstddef>
#include <cstdint>
#include <memory>

namespace sph {

// A loop's index range cut into one stretch per thread, shared by the team. A thread takes chunks
// from the front of its own stretch, then from the back of the others': a thread slowed down (on
// this project's virtual machines a core can lose a third of its speed for seconds while the other
// runs on) leaves the rest of its stretch to the others, and the chunks taken stay contiguous, so
// consecutive particles still share their neighbours in one cache. Which thread takes a chunk
// varies from run to run; the loops that use it write per index, so no result depends on it.
class Stretches {
 public:
  // Stretch t: from[t] .. from[t + 1] - 1, for t < threads; indices below 2^32.
  void reset(const std::size_t* from, int threads) {
    stretch_.reset(new Stretch[threads]);
    threads_ = threads;
    for (int t = 0; t < threads; ++t) stretch_[t].bounds.store(pack(from[t], from[t + 1]), std::memory_order_relaxed);
  }

  // Calls run(k0, k1) on chunks of thread t's stretch, then of the others', until none is left.
  template <class Run>
  void work(int t, Run&& run) {
    std::size_t k0, k1;
    while (take(t, true, k0, k1)) run(k0, k1);
    for (int o = 1; o < threads_; ++o)
      while (take((t + o) % threads_, false, k0, k1)) run(k0, k1);
  }

 private:
  // A chunk: 512 particles, about 0.15 ms of the force loop at 60 neighbours, so the threads end
  // within that of each other, and a thread claims a chunk ~7,000 times a second.
  static constexpr std::uint64_t chunk = 512;
  struct alignas(64) Stretch {
    std::atomic<std::uint64_t> bounds;  // front << 32 | back: what is left is front .. back - 1
  };
  static std::uint64_t pack(std::uint64_t front, std::uint64_t back) { return front << 32 | back; }

  // The next chunk of stretch s, from its front (its owner) or its back (another thread).
  bool take(int s, bool front, std::size_t& k0, std::size_t& k1) {
    std::atomic<std::uint64_t>& b = stretch_[s].bounds;
    std::uint64_t v = b.load(std::memory_order_relaxed);
    for (;;) {
      const std::uint64_t f = v >> 32, e = v & 0xffffffffu;
      if (f >= e) return false;
      const std::uint64_t c = std::min(e - f, chunk);
      if (b.compare_exchange_weak(v, front ? pack(f + c, e) : pack(f, e - c), std::memory_order_relaxed)) {
        k0 = front ? f : e - c, k1 = front ? f + c : e;
        return true;
      }
    }
  }

  std::unique_ptr<Stretch[]> stretch_;
  int threads_ = 0;
};

}  // namespace sph
