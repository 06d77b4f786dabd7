#pragma once
#include <algorithm>
#include <atomic>
#include <cstdio>
#include <cstdint>
#include <cstdlib>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <vector>

#include "sph/density/fixed_neighbours.hpp"
#include "sph/kernel/power.hpp"
#include "sph/search/verlet_list.hpp"

namespace sph {

// The density phase of a scheme whose h follows (50): the summation density (27) and h solved
// together, per particle, by Newton-Raphson on
//   f_i(h_i) = rho_i(h_i) - m_i (hfact / h_i)^D = 0,
// with rho_i the sum (27) over the pairs at h_ij = (h_i + h_j)/2 and
//   f_i'(h_i) = d rho_i / d h_i + D m_i hfact^D / h_i^(D+1),   d rho_i / d h_i = sum_j m_j dW/dh(r_ij, h_ij)
// (with the self term's dW/dh(0, h_i)), dW/dh = -(D W + r dW/dr) / h for every kernel
// W = h^-D w(r/h). The neighbours' h_j are those of the pass before (a Jacobi sweep), so the
// result does not depend on the order of the particles or on the thread count. They change in
// the same pass, mostly alike, so d rho_i / d h_i is taken with h_j changing as h_i does (h_ij's
// own derivative, not the half of it that h_i alone gives): with the half, a pass of particles
// whose rho depends strongly on h overshoots twofold together and oscillates about the root.
//
// A pass evaluates rho_i and f_i' at the particles' current h and proposes a new h_i: Newton's,
// kept inside the bracket of h_i the signs of f_i have shown (below: f_i < 0, above: f_i > 0);
// where Newton's step leaves it (or f_i' <= 0) the fixed-point value of (50), hfact (m_i/rho_i)^(1/D),
// and where that leaves it too, the bracket's midpoint (bisection). h is capped at h_max as in
// smoothing_length_iterate. A particle whose h fits (50) with its rho to tol, |hfact
// (m_i/rho_i)^(1/D) - h_i| < tol h_i (SmoothingLengthControl::tol, 1e-3: the criterion of the
// iteration over all particles, smoothing_length_iterate), has converged: its h and its rho, the
// sum (27) at that h, are kept. The others take the proposed h,
// and the next pass evaluates only them and their neighbours (whose rho changed with h_ij). Where
// those are at least half the particles, every particle of the pass takes its proposed h, however
// small the change: the next pass evaluates nearly all of them anyway, and each then starts at its
// root, so that the neighbours' changes seldom push it past tol again (otherwise the few it pushes
// have most particles evaluated a third time). The phase ends when a pass changes no h, so that
// every rho is the sum (27) of the h returned, or after max_iterations passes, the last of which
// only sums rho.
//
// The start: the h on entry (the integrator's prediction by (53)) plus the step each particle's
// last pass proposed beyond the h it kept (next_i - h_i, at most about tol h_i: a converged
// particle keeps an h within tol of the root, not the root). Without it those offsets add up over
// the steps until at least half the particles are off by tol after the first pass, and a whole
// second pass follows (every third step on a uniform gas in random motion). The offsets are kept
// while the particles keep their numbers (VerletList::serial and renumberings: the same lists,
// renumbered as often); a start is only the first pass's guess, so the h returned satisfy (50) to
// tol whatever it is.
//
// Pairs: the lists' (search/verlet_list.hpp), selected with a margin of h (VerletList::set_margin)
// so that an h that changes by less keeps them; where one changes by more, the lists are updated
// for the new h (a new search where it leaves their padding). The force loop then visits the
// same pairs.
//
// own_h: the density of a grad-h scheme (schemes/gradh_switches.hpp), rho_i = sum_j m_j W(r_ij, h_i)
// with i's own h in every pair (Springel & Hernquist 2002; Price & Monaghan 2007). Then rho_i
// depends on h_i alone, d rho_i / d h_i = sum_j m_j dW/dh(r_ij, h_i) is f_i' exactly (the Newton
// iteration converges quadratically, particle by particle), and a changed h_i leaves the
// neighbours' rho as it was: only the changed particles are evaluated again. drho_dh() returns
// that derivative at the h returned, from which the scheme forms Omega_i.
template <int D, class K = CubicSpline<D>, bool own_h = false>
class FixedNeighboursNewton {
 public:
  struct Outcome {
    int passes = 0;
    std::size_t evaluated = 0;  // particle evaluations over the passes
    std::size_t changed = 0;    // particles whose h changed
    bool converged = false;
  };

  // The margin of h the lists' pairs are selected with (VerletList::set_margin): the changes of h
  // in a phase start from (53)'s prediction and are mostly below it; 1 % costs 3 % more pairs in
  // 3D, which the pair loops evaluate to zero.
  static constexpr double margin = 0.01;

  // list: the pairs `lists` selected for the particles' h on entry (VerletList::update, which
  // returns it). On return, list holds the pairs for the returned h. Throws std::invalid_argument
  // from a search (an h beyond half a periodic box).
  Outcome solve(Particles<D>& p, VerletList<D>& lists, const NeighbourList& list, const Box<D>& box,
                const SmoothingLengthControl& c) {
    Outcome out;
    const std::size_t n = p.size();
    const Vec<D> L = box.length(), wrap = box.wrap_factor();
    lists.set_margin(margin);
    copy_components<D>(p.x, xs_);
    drho_.resize(n);
    next_.resize(n);
    fit_.resize(n);
    fit_lo_ = kernel_power<D>(1.0 - c.tol), fit_hi_ = kernel_power<D>(1.0 + c.tol);
    lo_.assign(n, 0.0);
    hi_.assign(n, std::numeric_limits<double>::infinity());
    mark_.assign(n, 0);
    if (offset_.size() == n && offset_serial_ == lists.serial() && offset_renumberings_ == lists.renumberings()) {
      bool held = true;
#pragma omp parallel for reduction(&& : held) if (n >= parallel_threshold)
      for (std::size_t i = 0; i < n; ++i) {
        const double h = std::min(p.h[i] + offset_[i], c.h_max);
        p.h[i] = h, held = lists.holds(i, h) && held;
      }
      if (!held) lists.update(p.x, p.h, box);
    }
    offset_.clear();
    which_ = list.order;
    if (which_.empty())
      for (std::size_t i = 0; i < n; ++i) which_.push_back(static_cast<int>(i));
    for (out.passes = 1;; ++out.passes) {
      const bool last = out.passes >= c.max_iterations;
      out.evaluated += which_.size();
      for_each_listed<D>(which_, [&](std::size_t i) {
        sums_of(i, list.j.data() + list.offset[i], list.offset[i + 1] - list.offset[i], p, L, wrap);
        if (!last) propose(i, p, c);
      });
      if (last) break;
      // The particles that change, in the pass's order; their neighbours are marked for the next.
      auto changes = [&](bool within_tol_too) {
        changed_.clear();
        for (int i : which_)
          if ((fit_[i] == Fit::beyond || (within_tol_too && fit_[i] == Fit::within)) && next_[i] != p.h[i])
            changed_.push_back(i);
      };
      changes(false);
      if (changed_.empty()) {
        out.converged = true;
        offset_.resize(n);
#pragma omp parallel for if (n >= parallel_threshold)
        for (std::size_t i = 0; i < n; ++i) offset_[i] = next_[i] - p.h[i];
        offset_serial_ = lists.serial(), offset_renumberings_ = lists.renumberings();
        break;
      }
      if (2 * mark(list) >= n) {
        changes(true);
        mark(list);
      }
      out.changed += changed_.size();
      bool held = true;
      for (int i : changed_) p.h[i] = next_[i], held = held && lists.holds(i, p.h[i]);
      if (!held) {
        lists.update(p.x, p.h, box);  // the new pairs: their ends are marked too
        mark(list);
      }
      // The next pass's particles in the order of this one, then those newly marked in index
      // order: the same list on any thread count.
      std::vector<int> next_which;
      next_which.reserve(which_.size());
      for (int i : which_)
        if (mark_[i] == 1) next_which.push_back(i), mark_[i] = 2;
      for (std::size_t i = 0; i < n; ++i)
        if (mark_[i] == 1) next_which.push_back(static_cast<int>(i));
      for (int i : next_which) mark_[i] = 0;
      which_.swap(next_which);
    }
    return out;
  }

  // d rho_i / d h_i at the h returned (with own_h: sum_j m_j dW/dh(r_ij, h_i), the self term
  // included), each evaluated at the h and positions of i's last evaluation.
  const std::vector<double>& drho_dh() const { return drho_; }

 private:
  // rho_i (27) and d rho_i / d h_i over i's pairs js[0 .. count): every pair evaluated without a
  // branch (W and dW/dr vanish beyond h_ij), in vectorised batches, each summed in list order.
  void sums_of(std::size_t i, const int* js, std::size_t count, Particles<D>& p, const Vec<D>& L, const Vec<D>& wrap) {
    constexpr int batch = 128;
    double w[batch], dw[batch];
    const double hi = p.h[i];
    const double* h = p.h.data();
    const double* m = p.m.data();
    double rho = 0.0, drho = 0.0;
    for (std::size_t t0 = 0; t0 < count; t0 += batch) {
      const int nb = static_cast<int>(std::min<std::size_t>(count - t0, batch));
#pragma omp simd
      for (int t = 0; t < nb; ++t) {
        const int j = js[t0 + t];
        const double r = std::sqrt(distance2<D>(i, j, xs_, L, wrap)), hij = own_h ? hi : h_ij(hi, h[j]);
        const double W = K::W(r, hij);
        w[t] = m[j] * W;
        // dW/dh_ij (h_i and h_j changing alike, or h_i's own), with the kernel's own 1 / h_ij: one
        // division a pair, not two.
        dw[t] = -m[j] * (D * W + r * K::dWdr(r, hij)) * (1.0 / hij);
      }
      for (int t = 0; t < nb; ++t) rho += w[t], drho += dw[t];
    }
    const double self = p.m[i] * K::W(0.0, hi);
    p.rho[i] = self + rho;
    drho_[i] = -D * self / hi + drho;
  }

  // Marks the changed particles and every particle their rows of `list` hold (with own_h, whose
  // neighbours' rho do not depend on h_i, the changed particles alone); returns how many particles
  // are marked.
  std::size_t mark(const NeighbourList& list) {
    const std::size_t m = changed_.size();
    if constexpr (own_h) {
      for (int i : changed_) mark_[i] = 1;
      return m;
    } else {
#pragma omp parallel for schedule(dynamic, 256) if (m >= parallel_threshold)
      for (std::size_t k = 0; k < m; ++k) {
        const int i = changed_[k];
        std::atomic_ref<unsigned char>(mark_[i]).store(1, std::memory_order_relaxed);
        for (int j : list.of(i)) std::atomic_ref<unsigned char>(mark_[j]).store(1, std::memory_order_relaxed);
      }
      std::size_t marked = 0;
      for (unsigned char k : mark_) marked += k;
      return marked;
    }
  }

  // next_[i]: the h that i's pass proposes (above); fit_[i]: whether h_i is within tol of (50)'s
  // h with rho_i, |hfact (m_i/rho_i)^(1/D) - h_i| < tol h_i, tested as the D-th power of that ratio,
  // (m_i (hfact/h_i)^D / rho_i) against (1 -+ tol)^D: no root is taken for a particle that keeps
  // Newton's step (the root of (50)'s fixed point is the pass's costliest operation a particle).
  void propose(std::size_t i, const Particles<D>& p, const SmoothingLengthControl& c) {
    const double h = p.h[i], rho = p.rho[i];
    const double target = p.m[i] * kernel_power<D>(c.hfact / h);  // (50)'s density at h
    const double f = rho - target, fp = drho_[i] + D * target / h;
    double& lo = lo_[i];
    double& hi = hi_[i];
    // The bracket as f's sign shows it now; a side the neighbours' changes have overtaken, or
    // brought within tol h of h (the root moved past it), is dropped.
    if (f < 0.0) {
      lo = h;
      if (hi <= h * (1.0 + c.tol)) hi = std::numeric_limits<double>::infinity();
    } else if (f > 0.0) {
      hi = h;
      if (lo >= h * (1.0 - c.tol)) lo = 0.0;
    }
    // (50)'s fixed point lies on the side f points to (above h for f < 0), so with an open bracket
    // (hi infinite) one of the first two is inside and the midpoint is taken only between two bounds;
    // unless f is round-off, and Newton's step and the fixed point both round to h itself: h is then
    // the root as closely as it can be represented, and stays (the midpoint of an open bracket would
    // be infinite).
    auto inside = [&](double x) { return x > lo && x < hi; };
    const double ratio = target / rho;  // (fixed / h)^D with (50)'s fixed point below
    fit_[i] = ratio >= fit_hi_ || ratio <= fit_lo_ ? Fit::beyond : ratio == ratio ? Fit::within : Fit::undefined;
    double h_new = h;
    if (f != 0.0) {
      const double newton = h - f / fp;
      if (fp > 0.0 && inside(newton)) {
        h_new = newton;
      } else {
        const double fixed = c.hfact * std::pow(p.m[i] / rho, 1.0 / D);  // (50)
        h_new = inside(fixed) ? fixed : newton == h ? h : 0.5 * (lo + hi);
      }
    }
    next_[i] = h_new < c.h_max ? h_new : c.h_max;
  }

  Components<D> xs_;  // the positions' columns (kept from one phase to the next, Scene::xs)
  std::vector<double> drho_, next_, lo_, hi_;
  // How h_i fits (50) with rho_i: within tol, beyond it, or not comparable (rho_i not a number:
  // the particle is left as it is, and the step's check names it).
  enum class Fit : unsigned char { within, beyond, undefined };
  std::vector<Fit> fit_;
  double fit_lo_ = 0.0, fit_hi_ = 0.0;  // (1 -+ tol)^D, the bounds of the ratio (propose), once a phase
  // The offsets of the next start (above), and the lists and renumbering they were taken under.
  std::vector<double> offset_;
  std::uint64_t offset_serial_ = 0;
  long offset_renumberings_ = 0;
  std::vector<unsigned char> mark_;
  std::vector<int> which_, changed_;
};

}  // namespace sph
