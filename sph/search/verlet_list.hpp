#pragma once
#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdint>
#include <cmath>
#include <limits>
#include <vector>

#include <omp.h>

#include "sph/core/isa.hpp"
#include "sph/core/stretches.hpp"
#include "sph/hydro/pairs.hpp"
#include "sph/search/grid_search.hpp"

namespace sph {

// A particle's position and support radius in one 32-byte record, {x_1 .. x_D, (unused), h}: the
// pair filter loads a candidate's with one aligned load (four or eight candidates at a time, then
// transposed) instead of four scattered ones.
struct alignas(32) Site {
  double x[3];
  double h;
};

// For i = first .. last-1: the pairs (i, j) of list's row r = row[i] (r = i where row is null)
// with |r_ij| < max(h_i, h_j), appended to js in the row's order, with offset[i + 1] = the count so
// far; returns the count. Compiled in search/verlet_list.cpp in copies like the pair loops, the one
// run is loop_path's (core/isa.hpp).
template <int D>
std::size_t select_pairs(IsaPath path, std::size_t first, std::size_t last, const NeighbourList& list, const int* row,
                         const Site* sites, const Vec<D>& L, const Vec<D>& wrap, int* js, std::size_t* offset);
extern template std::size_t select_pairs<1>(IsaPath, std::size_t, std::size_t, const NeighbourList&, const int*,
                                            const Site*, const Vec<1>&, const Vec<1>&, int*, std::size_t*);
extern template std::size_t select_pairs<2>(IsaPath, std::size_t, std::size_t, const NeighbourList&, const int*,
                                            const Site*, const Vec<2>&, const Vec<2>&, int*, std::size_t*);
extern template std::size_t select_pairs<3>(IsaPath, std::size_t, std::size_t, const NeighbourList&, const int*,
                                            const Site*, const Vec<3>&, const Vec<3>&, int*, std::size_t*);

// Neighbour lists reused across steps (a Verlet list: 9.4.3's search with a skin). A search at
// positions x0 and support radii h0 lists the pairs within the padded radii (1 + skin) h0, and
// serves until a pair that now interacts might be missing from it. With d_k = |x_k - x0_k|
// (nearest image) and g_k = max(0, h_k - h0_k), a pair with |r_ij| < max(h_i, h_j) has
// |r0_ij| <= |r_ij| + d_i + d_j < max(h0_i, h0_j) + max(g_i, g_j) + d_i + d_j, so it is listed
// while either
//   (a) d_k + g_k <= skin h0_k / 2 for every k (particles that move, each by its own h), or
//   (b) 2 max_k d_k + g_k <= skin h0_k for every k (particles at rest while h changes, as in (50)).
// Each evaluation gets the pairs of the padded list that interact, as a fresh search would list
// them; filtering costs a fraction of a grid search, which tests several times more candidates.
// The padding is dropped where it would exceed half a periodic box.
template <int D>
class VerletList {
 public:
  explicit VerletList(double skin) : skin_(skin), serial_(next_serial()) {}

  // The list for the particles at x with support radii h: the last one, or a new search.
  // Throws std::invalid_argument from the search (h not positive and finite, or beyond half a
  // periodic box).
  // The list holds exactly the pairs with |r_ij| < max(h_i, h_j) now, as a fresh search would (the
  // padded list filtered, in its order), so no pair loop of the evaluation visits the padding.
  const NeighbourList& update(const std::vector<Vec<D>>& x, const std::vector<double>& h, const Box<D>& box) {
    const auto t0 = std::chrono::steady_clock::now();
    const std::vector<double>& r = radii(h);
    if (!covers(x, r, box)) search(x, r, box);
    select(x, r, box);
    seconds_ += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    return active_;
  }
  long searches() const { return searches_; }
  // A number no other list made in this process has, and how many times renumber_in_visiting_order
  // has renumbered the particles: with both, a caller keeping an array over the particles knows
  // whether its indices still name the particles they named (a list's address may be reused).
  std::uint64_t serial() const { return serial_; }
  long renumberings() const { return renumberings_; }
  // The time spent in update so far (`sphv bench` shows it as the step's search phase).
  double seconds() const { return seconds_; }
  // The next update searches anew, whether or not the lists cover (a step timed with a fresh
  // search at every evaluation).
  void expire() { searches_at_expiry_ = searches_ + 1; }

  // From the next update on, the pairs selected are those within (1 + margin) max(h_i, h_j) (and
  // the lists are searched and kept for those radii): a caller that changes h by less than the
  // margin between updates (a density phase solving (50)) keeps the pairs it has. The pair loops
  // give such pairs no share (W and grad W vanish beyond h_ij), so their results are those of
  // the exact pairs; they visit about D x margin more pairs in D dimensions.
  void set_margin(double margin) { margin_ = margin; }
  // Whether the last update's pairs hold every pair of particle i with |r_ij| < max(h_i, h_j) for
  // an h_i now (the positions and the other radii as then): h_i within the radius selected.
  bool holds(std::size_t i, double h) const { return h <= sites_[i].h; }
  // For a caller that stores its particles in the visiting order of the last search (evolve, see
  // hydro/storage_order.hpp): returns that order and renumbers the lists so that particle order[k]
  // becomes k. They are then the lists a search of the particles so stored would give (the same
  // pairs, in the same order). Empty if there was no search since the last renumbering.
  std::vector<int> renumber_in_visiting_order() {
    std::vector<int> order;
    order.swap(list_.order);  // the visiting order is now the storage order
    const std::size_t n = order.size();
    if (n == 0) return order;
    ++renumberings_;
    std::vector<int> now(n);  // now[i]: the new number of particle i
#pragma omp parallel for if (n >= parallel_threshold)
    for (std::size_t k = 0; k < n; ++k) now[order[k]] = static_cast<int>(k);
    const std::size_t m = list_.j.size();
#pragma omp parallel for if (n >= parallel_threshold)
    for (std::size_t t = 0; t < m; ++t) list_.j[t] = now[list_.j[t]];
    row_ = order;  // the rows stay where they are: k's is order[k]'s
    std::vector<Vec<D>> x0(n);
    std::vector<double> h0(n);
#pragma omp parallel for if (n >= parallel_threshold)
    for (std::size_t k = 0; k < n; ++k) x0[k] = x0_[order[k]], h0[k] = h0_[order[k]];
    x0_.swap(x0), h0_.swap(h0);
    return order;
  }

 private:
  // The radii searched and selected: h, or h padded by the margin.
  const std::vector<double>& radii(const std::vector<double>& h) {
    if (margin_ == 0.0) return h;
    const std::size_t n = h.size();
    padded_h_.resize(n);
#pragma omp parallel for if (n >= parallel_threshold)
    for (std::size_t k = 0; k < n; ++k) padded_h_[k] = (1.0 + margin_) * h[k];
    return padded_h_;
  }

  bool covers(const std::vector<Vec<D>>& x, const std::vector<double>& h, const Box<D>& box) const {
    if (searches_ < searches_at_expiry_ || x.size() != x0_.size() || box.lo != box_.lo || box.hi != box_.hi || box.periodic != box_.periodic) return false;
    const Vec<D> L = box.length(), wrap = box.wrap_factor();
    const double s = used_skin_;
    bool each = true, finite = true;
    double d_max = 0.0, slack = std::numeric_limits<double>::infinity();
    const std::size_t n = x.size();
#pragma omp parallel for reduction(&& : each, finite) reduction(max : d_max) reduction(min : slack) if (n >= parallel_threshold)
    for (std::size_t k = 0; k < n; ++k) {
      const double d = min_image<D>(x[k] - x0_[k], L, wrap).norm(), g = std::max(0.0, h[k] - h0_[k]);
      finite = finite && std::isfinite(d + h[k]);
      each = each && d + g <= 0.5 * s * h0_[k];  // (a)
      d_max = std::max(d_max, d);
      slack = std::min(slack, s * h0_[k] - g);  // (b): 2 d_max <= min_k (skin h0_k - g_k)
    }
    return finite && (each || 2.0 * d_max <= slack);
  }

  void search(const std::vector<Vec<D>>& x, const std::vector<double>& h, const Box<D>& box) {
    const double widest = h.empty() ? 0.0 : (1.0 + skin_) * *std::max_element(h.begin(), h.end());
    const Vec<D> L = box.length();
    used_skin_ = skin_;
    for (int d = 0; d < D; ++d)
      if (box.periodic[d] && widest > 0.5 * L[d]) used_skin_ = 0.0;
    const std::size_t n = h.size();
    reach_.resize(n);
#pragma omp parallel for if (n >= parallel_threshold)
    for (std::size_t k = 0; k < n; ++k) reach_[k] = (1.0 + used_skin_) * h[k];
    grid_search<D>(x, reach_, box, list_, buffers_);
    row_.clear();
    x0_ = x, h0_ = h, box_ = box;
    ++searches_;
  }

  // active_ = the pairs of list_ within max(h_i, h_j). The threads filter chunks of the rows
  // (core/stretches.hpp: their own stretch, then the back of a slower thread's), each into its own
  // buffer, and the chunks are joined in the rows' order: independent of the thread count and of
  // which thread filtered which chunk. Thread 0's own chunks open the joined list: it filters
  // them straight into it. The buffers (large: room for every candidate) are kept from one
  // evaluation to the next, so that an evaluation does not fault fresh pages in: allocated afresh,
  // they would make a step with reused lists slower than one with a fresh search. Each has room for
  // every candidate: a thread may filter any share of them, and its pages are touched only where
  // it writes. Grown by doubling as needed instead, a buffer would grow again, into a fresh block,
  // whenever its thread took a larger share than before.
  void select(const std::vector<Vec<D>>& x, const std::vector<double>& h, const Box<D>& box) {
    const std::size_t n = x.size();
    const Vec<D> L = box.length(), wrap = box.wrap_factor();
    const IsaPath path = loop_path<D>(isa_path());
    active_.offset.resize(n + 1);  // every entry is written below
    active_.offset[0] = 0;
    active_.order = list_.order;
    sites_.resize(n);  // every entry is written below
    if (active_.j.size() < list_.j.size()) resize_for_overwrite(active_.j, list_.j.size());
    Stretches stretches;
    std::vector<Chunk> chunk;  // what became of each chunk of the rows
#pragma omp parallel if (n >= parallel_threshold)
    {
      const int nt = omp_get_num_threads(), t = omp_get_thread_num();
#pragma omp for schedule(static)
      for (std::size_t k = 0; k < n; ++k) {
        for (int d = 0; d < D; ++d) sites_[k].x[d] = x[k][d];
        sites_[k].h = h[k];
      }
#pragma omp single
      {
        if (parts_.size() < static_cast<std::size_t>(nt)) parts_.resize(nt);
        stretches.reset(n, nt);
        chunk.resize(stretches.chunks());
      }
      auto& buffer = parts_[t];
      if (buffer.size() < list_.j.size()) resize_for_overwrite(buffer, list_.j.size());
      std::size_t direct = 0, used = 0;  // pairs so far in active_.j (thread 0's own) and in the buffer
      stretches.work(t, [&](std::size_t c, std::size_t first, std::size_t last) {
        const bool straight = t == 0 && stretches.owns(0, c);
        std::size_t& at = straight ? direct : used;
        const std::size_t count = select_pairs<D>(path, first, last, list_, row_.empty() ? nullptr : row_.data(),
                                                  sites_.data(), L, wrap, (straight ? active_.j : buffer).data() + at,
                                                  active_.offset.data());
        chunk[c] = {at, count, 0, straight ? -1 : t};
        at += count;
      });
#pragma omp barrier
#pragma omp single
      {
        std::size_t total = 0;
        for (Chunk& k : chunk) k.base = total, total += k.count;
        active_.j.resize(total);  // keeps thread 0's own pairs, at its start
      }
      // Each chunk's offsets (counted from its start) moved to its place, its pairs copied there;
      // the chunks dealt out in turn, so that each thread copies about as much.
#pragma omp for schedule(static, 1)
      for (std::size_t c = 0; c < chunk.size(); ++c) {
        const Chunk& k = chunk[c];
        const auto [first, last] = stretches.range(c);
        for (std::size_t i = first; i < last; ++i) active_.offset[i + 1] += k.base;
        if (k.thread >= 0) std::copy_n(parts_[k.thread].begin() + k.at, k.count, active_.j.begin() + k.base);
      }
    }
  }

  // A chunk of rows filtered into the buffer of `thread` (-1: straight into active_.j) from `at`:
  // count pairs, which go to base in the joined list.
  struct Chunk {
    std::size_t at, count, base;
    int thread;
  };

  double skin_, used_skin_ = 0.0;
  NeighbourList list_, active_;
  std::vector<int> row_;  // particle k's row of list_ (empty: row k), set by renumber_in_visiting_order
  std::vector<std::vector<int, DefaultInitAllocator<int>>> parts_;  // select's buffers, a thread's each
  std::vector<Site, DefaultInitAllocator<Site>> sites_;  // the positions and radii select reads
  GridSearchBuffers<D> buffers_;          // the search's, kept likewise
  std::vector<double> reach_;             // the padded radii searched
  std::vector<Vec<D>> x0_;
  std::vector<double> h0_;
  Box<D> box_;
  long searches_ = 0;
  long renumberings_ = 0;
  std::uint64_t serial_;
  static std::uint64_t next_serial() {
    static std::atomic<std::uint64_t> made{0};
    return ++made;
  }
  long searches_at_expiry_ = 1;  // the lists serve once searches_ reaches it (expire)
  double seconds_ = 0.0;
  double margin_ = 0.0;
  std::vector<double> padded_h_;  // the radii with the margin
};

}  // namespace sph
