#pragma once
#include <algorithm>
#include <atomic>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <utility>
#include <vector>

namespace sph {

// A loop's index range cut into one stretch per thread, shared by the team. A thread takes chunks
// from the front of its own stretch, then from the back of the others': a thread slowed down (on
// this project's virtual machines a core can lose a third of its speed for seconds while the other
// runs on) leaves the rest of its stretch to the others, and the chunks taken stay contiguous, so
// consecutive particles still share their neighbours in one cache. The chunks are fixed in advance
// and numbered in index order; which thread takes one varies from run to run. A loop that writes
// per index, or per chunk into a record of its own that a join then reads in chunk order, has
// results independent of it.
class Stretches {
 public:
  // Stretch t: from[t] .. from[t + 1] - 1, for t + 1 < from.size(); from[0] = 0.
  void reset(std::vector<std::size_t> from) {
    from_ = std::move(from);
    const std::size_t threads = from_.size() - 1;
    first_.assign(threads + 1, 0);
    for (std::size_t t = 0; t < threads; ++t) first_[t + 1] = first_[t] + (from_[t + 1] - from_[t] + chunk - 1) / chunk;
    stretch_.reset(new Stretch[threads]);
    for (std::size_t t = 0; t < threads; ++t)
      stretch_[t].bounds.store(pack(first_[t], first_[t + 1]), std::memory_order_relaxed);
  }
  // Stretches of equal length over 0 .. n - 1.
  void reset(std::size_t n, int threads) {
    std::vector<std::size_t> from(threads + 1);
    for (int t = 0; t <= threads; ++t) from[t] = n * t / threads;
    reset(std::move(from));
  }

  std::size_t chunks() const { return first_.back(); }
  bool owns(int t, std::size_t c) const { return first_[t] <= c && c < first_[t + 1]; }
  // Chunk c's indices: first .. last - 1.
  std::pair<std::size_t, std::size_t> range(std::size_t c) const {
    return range(std::upper_bound(first_.begin(), first_.end(), c) - first_.begin() - 1, c);
  }

  // Calls run(c, first, last) on the chunks c of thread t's stretch, then of the others', until
  // none is left.
  template <class Run>
  void work(int t, Run&& run) {
    const int threads = static_cast<int>(first_.size()) - 1;
    std::size_t c;
    for (int o = 0; o < threads; ++o) {
      const int s = (t + o) % threads;
      while (take(s, o == 0, c)) {
        const auto [first, last] = range(s, c);
        run(c, first, last);
      }
    }
  }

 private:
  // A chunk: 512 particles, a fraction of a millisecond of the force loop, so the threads end
  // within that of each other, and claiming a chunk costs little against the chunk's work.
  static constexpr std::size_t chunk = 512;
  struct alignas(64) Stretch {
    std::atomic<std::uint64_t> bounds;  // front << 32 | back: its chunks left are front .. back - 1
  };
  static std::uint64_t pack(std::uint64_t front, std::uint64_t back) { return front << 32 | back; }

  std::pair<std::size_t, std::size_t> range(std::size_t s, std::size_t c) const {
    const std::size_t first = from_[s] + (c - first_[s]) * chunk;
    return {first, std::min(first + chunk, from_[s + 1])};
  }

  // The next chunk of stretch s, from its front (its owner) or its back (another thread).
  bool take(int s, bool front, std::size_t& c) {
    std::atomic<std::uint64_t>& b = stretch_[s].bounds;
    std::uint64_t v = b.load(std::memory_order_relaxed);
    for (;;) {
      const std::uint64_t f = v >> 32, e = v & 0xffffffffu;
      if (f >= e) return false;
      if (b.compare_exchange_weak(v, front ? pack(f + 1, e) : pack(f, e - 1), std::memory_order_relaxed)) {
        c = front ? f : e - 1;
        return true;
      }
    }
  }

  std::vector<std::size_t> from_, first_;  // stretch t: indices from from_[t], chunks from first_[t]
  std::unique_ptr<Stretch[]> stretch_;
};

}  // namespace sph
