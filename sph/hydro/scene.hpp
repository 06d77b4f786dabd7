#pragma once
#include <algorithm>
#include <cstddef>
#include <tuple>
#include <type_traits>
#include <vector>

#include "sph/core/particles.hpp"
#include "sph/hydro/pairs.hpp"
#include "sph/kernel/cubic_spline.hpp"

namespace sph {

// Time derivatives the terms of a scene accumulate, and mu_max = max_j |mu_ij| (46) of the
// artificial viscosity (0 without), which the Courant condition reads (or, in a scheme whose
// viscosity has a signal velocity, max_j v_sig,ij: hydro/signal_viscosity.hpp). h_set: the evaluation sets h
// (a density phase solving (50), schemes/chapter.hpp), and dhdt only predicts h for the next one
// (time/leapfrog.hpp).
template <int D>
struct Derivatives {
  std::vector<Vec<D>> dvdt;
  std::vector<double> dudt, drhodt, dhdt, mu_max;
  bool h_set = false;
  void reset(std::size_t n) {  // zeros written by all threads: megabytes in a large run
    for (auto* a : {&dudt, &drhodt, &dhdt, &mu_max}) a->resize(n);
    dvdt.resize(n);
#pragma omp parallel for if (n >= parallel_threshold)
    for (std::size_t i = 0; i < n; ++i) {
      dvdt[i].setZero();
      dudt[i] = drhodt[i] = dhdt[i] = mu_max[i] = 0.0;
    }
  }
};

// The same quantities of one particle i summed over its pairs by the pair loop.
template <int D>
struct PairSums {
  Vec<D> dvdt = Vec<D>::Zero();
  double dudt = 0.0, drhodt = 0.0, dhdt = 0.0, mu_max = 0.0;
};

// The PairSums a term's pair() adds to, declared by the term as `static constexpr Writes writes`:
// the pair loop sums only what some term of the scene writes (a sum the scene never adds to costs
// a load and an add a pair otherwise). A term that writes what it does not declare loses it: the
// direct-sum test of every hydro term (verification/tests/hydro.cpp) and the heat cases fail.
struct Writes {
  bool dvdt = false, dudt = false, drhodt = false, dhdt = false, mu_max = false;
  constexpr Writes operator|(const Writes& o) const {
    return {dvdt || o.dvdt, dudt || o.dudt, drhodt || o.drhodt, dhdt || o.dhdt, mu_max || o.mu_max};
  }
};

// One interacting pair as the pair loop hands it to the terms: r_ij = r_i - r_j (nearest
// image), |r_ij|, the symmetric h_ij, grad_i W_ij(h_ij) and the velocities v_i, v_j (the terms
// read them here, not from the particles: the pair loop gathers them from one array per
// dimension, which it can vectorise).
template <int D>
struct Pair {
  std::size_t i;
  int j;
  Vec<D> rij;
  double r, h;
  Vec<D> gradW, vi, vj;
};

// A pair with the kernel's gradient at each end's own support radius as well: grad_i W_ij(h_i) and
// grad_i W_ij(h_j), for the terms of a grad-h scheme (schemes/gradh_switches.hpp), which weigh each
// end's kernel by its own h instead of h_ij. A scene hands its terms such pairs when one of them
// declares `static constexpr bool own_h_kernels = true`; it then counts a pair as interacting
// within max(h_i, h_j), where either kernel reaches.
template <int D>
struct OwnHPair : Pair<D> {
  Vec<D> gradWi, gradWj;
};

template <class T>
constexpr bool own_h_kernels = requires { requires std::remove_cvref_t<T>::own_h_kernels; };

// The pair type of a scene of the terms T...: OwnHPair where a term asks for it, else Pair.
template <int D, class... T>
using PairOf = std::conditional_t<(own_h_kernels<T> || ...), OwnHPair<D>, Pair<D>>;

// What term T writes in the pair loop (nothing without pair()); P the scene's pair type.
template <int D, class T, class P = Pair<D>>
constexpr Writes writes_of() {
  if constexpr (requires(const T& t, const Particles<D>& p, PairSums<D>& s, const P& q) { t.pair(p, s, q); }) {
    static_assert(requires { T::writes; }, "a term with pair() declares what it writes: static constexpr Writes writes");
    return T::writes;
  } else {
    return {};
  }
}

template <int D>
class VerletList;

// The particles with the geometry their pair loops need. lists: the reused lists `list` was
// selected from (search/verlet_list.hpp), given by evolve: a density phase that sets h
// (schemes/chapter.hpp) selects `list` from them anew for the h it sets (null: list is fixed).
template <int D>
struct Neighbourhood {
  const NeighbourList& list;
  const Box<D>& box;
  VerletList<D>* lists = nullptr;
};

// A term that only caps the copies of its scene's pair loop the build compiles (core/isa.hpp), for
// scenes whose runs are small: a copy then costs compile time and saves no run time (the
// conservation catalogue's 48 3D scenes, whose runs are too small to gain from AVX-512).
template <IsaPath widest>
struct WidestLoopCopy {
  static constexpr IsaPath widest_loop_copy = widest;
};

// A term that only names its scene's kernel (sph/kernel/kernels.hpp), for scenes none of whose
// other terms names one (a term that evaluates W itself, e.g. SummationDensity, names its own).
template <class K>
struct WithKernel {
  using kernel = K;
};

// The kernel of a scene: the one its terms name (`using kernel`), all the same one; the cubic
// spline (6) when none does.
template <class T>
struct KernelOf {
  using type = void;
};
template <class T>
  requires requires { typename T::kernel; }
struct KernelOf<T> {
  using type = typename T::kernel;
};
template <int D, class... Terms>
struct SceneKernel {
  using type = CubicSpline<D>;
};
template <int D, class T, class... Rest>
struct SceneKernel<D, T, Rest...> {
  using own = typename KernelOf<std::remove_cvref_t<T>>::type;
  using type = std::conditional_t<std::is_void_v<own>, typename SceneKernel<D, Rest...>::type, own>;
};

// A scene lists its physical terms as types, and its kernel through them (SceneKernel). A term may
// provide any of
//   void prepare(Particles<D>&, const Neighbourhood<D>&)                   before the pair loop
//   void pair(const Particles<D>&, PairSums<D>&, const Pair<D>&)           inside it (adds the pair's share)
//   void finish(const Particles<D>&, const Neighbourhood<D>&, Derivatives<D>&)  after it
// The pair loop is a fold over the terms that have pair(): a term the scene does not list is not
// compiled into it, and no flag is tested per pair. A term with pair() declares what it writes
// (Writes above). pair() must not branch on the pair, and reads velocities from the Pair: then the
// loop vectorises across pairs (sums_of below).
template <int D, class... Terms>
struct Scene {
  static constexpr int dim = D;
  // The kernel of grad W in the pair loop (SceneKernel).
  using Kernel = typename SceneKernel<D, Terms...>::type;
  static_assert(((std::is_void_v<typename KernelOf<std::remove_cvref_t<Terms>>::type> ||
                  std::is_same_v<typename KernelOf<std::remove_cvref_t<Terms>>::type, Kernel>) && ...),
                "the terms of a scene name one kernel");
  std::tuple<Terms...> terms;
  // The positions and velocities one array per dimension, as the pair loop gathers them: buffers
  // kept from one evaluation to the next. Allocated afresh, a large run's columns would go back to
  // the system when freed and be faulted in again at every evaluation, which on a virtual machine
  // slows every loop that follows.
  Components<D> xs, vs;

  void derivatives(Particles<D>& p, const Neighbourhood<D>& nb, Derivatives<D>& d) {
    d.reset(p.size());
    std::apply([&](auto&... t) { (prepare(t, p, nb), ...); }, terms);
    if constexpr ((has_pair<Terms> || ...)) {
      copy_components<D>(p.x, xs);
      copy_components<D>(p.v, vs);
      const Vec<D> L = nb.box.length(), wrap = nb.box.wrap_factor();
      const IsaPath path = loop_path<D>(isa_path(), widest);
      for_each_particle<D, widest>(p.size(), nb.list,
                                   [&](std::size_t i) { sums_of(i, path, p, xs, vs, nb.list, L, wrap, d); });
    }
    std::apply([&](auto&... t) { (finish(t, p, nb, d), ...); }, terms);
  }

  template <class T>
  T& term() { return std::get<T>(terms); }

 private:
  // The shares of a batch of pairs, one lane per pair.
  struct Shares {
    static constexpr int size = PairBatch<D>::size;
    double dvdt[D][size], dudt[size], drhodt[size], dhdt[size], mu_max[size];
  };

  // The share of pair t of batch b, (i, j), in sh's lane t: 0 beyond h_ij, where W and grad W
  // vanish. A function of its own: GCC 12 fails (internal error) on a PairSums declared inside
  // the simd loop.
  void share(int t, std::size_t i, int j, const Particles<D>& p, const Vec<D>& vi, const Components<D>& vs,
             const PairBatch<D>& b, Shares& sh) const {
    Vec<D> rij, vj;
#pragma GCC unroll 3
    for (int k = 0; k < D; ++k) {
      rij[k] = b.dx[k][t];
      vj[k] = vs[k][j];
    }
    const Pair<D> pq{i, j, rij, b.r[t], b.h[t], Vec<D>(b.g[t] * rij), vi, vj};  // grad_i W_ij (9)
    PairSums<D> s{};
    // 1 inside, 0 beyond h_ij (beyond max(h_i, h_j) with own_h kernels), multiplied rather than
    // selected: GCC 12 would otherwise load the fields under the mask, as masked gathers it does
    // not emulate (and does not vectorise).
    double in;
    if constexpr (std::is_same_v<PairType, OwnHPair<D>>) {
      const double r = b.r[t], hi = p.h[i], hj = p.h[j];
      const double gi = r > 0.0 ? Kernel::dWdr(r, hi) / r : 0.0, gj = r > 0.0 ? Kernel::dWdr(r, hj) / r : 0.0;
      const OwnHPair<D> q{pq, Vec<D>(gi * rij), Vec<D>(gj * rij)};
      std::apply([&](const auto&... term) { (pair(term, p, s, q), ...); }, terms);
      in = r < std::max(hi, hj) ? 1.0 : 0.0;
    } else {
      std::apply([&](const auto&... term) { (pair(term, p, s, pq), ...); }, terms);
      in = b.r[t] < b.h[t] ? 1.0 : 0.0;
    }
    if constexpr (written.dvdt)
#pragma GCC unroll 3
      for (int k = 0; k < D; ++k) sh.dvdt[k][t] = in * s.dvdt[k];
    if constexpr (written.dudt) sh.dudt[t] = in * s.dudt;
    if constexpr (written.drhodt) sh.drhodt[t] = in * s.drhodt;
    if constexpr (written.dhdt) sh.dhdt[t] = in * s.dhdt;
    if constexpr (written.mu_max) sh.mu_max[t] = in * s.mu_max;
  }

  // Particle i's sums over its listed pairs, in batches (hydro/pairs.hpp): the batch's geometry
  // (pair_geometry), then every pair's share through the terms, all pairs of the batch in one
  // branch-free loop the compiler vectorises (a pair beyond h_ij, where W and grad W vanish, has
  // its share set to 0), then the shares summed in list order, so the sums do not depend on the
  // vector width. A term adds to a PairSums that starts at 0 for each pair.
  void sums_of(std::size_t i, IsaPath path, const Particles<D>& p, const Components<D>& xs, const Components<D>& vs,
               const NeighbourList& nl,
               const Vec<D>& L, const Vec<D>& wrap, Derivatives<D>& d) const {
    PairBatch<D> b;
    Shares sh;
    const int* js = nl.j.data() + nl.offset[i];
    const int count = static_cast<int>(nl.offset[i + 1] - nl.offset[i]);
    PairSums<D> acc{};
    Vec<D> vi;
    for (int k = 0; k < D; ++k) vi[k] = vs[k][i];
    for (int t0 = 0; t0 < count; t0 += b.size) {
      const int nb = std::min(count - t0, b.size);
      pair_geometry<D, Kernel>(path, i, js + t0, nb, xs, p.h, L, wrap, b);
#pragma omp simd
      for (int t = 0; t < nb; ++t) share(t, i, js[t0 + t], p, vi, vs, b, sh);
      // Adding a share of +0 or -0 (0 times the pair's value) leaves a sum that starts at +0
      // unchanged, so the pairs beyond h_ij need no branch here either.
      for (int t = 0; t < nb; ++t) {
        if constexpr (written.dvdt)
#pragma GCC unroll 3
          for (int k = 0; k < D; ++k) acc.dvdt[k] += sh.dvdt[k][t];
        if constexpr (written.dudt) acc.dudt += sh.dudt[t];
        if constexpr (written.drhodt) acc.drhodt += sh.drhodt[t];
        if constexpr (written.dhdt) acc.dhdt += sh.dhdt[t];
        if constexpr (written.mu_max) acc.mu_max = std::max(acc.mu_max, sh.mu_max[t]);
      }
    }
    d.dvdt[i] = acc.dvdt;
    d.dudt[i] = acc.dudt;
    d.drhodt[i] = acc.drhodt;
    d.dhdt[i] = acc.dhdt;
    d.mu_max[i] = acc.mu_max;
  }

  // The widest copy of the pair loop compiled: AVX-512 unless a term caps it (WidestLoopCopy).
  template <class T>
  static constexpr IsaPath widest_of() {
    if constexpr (requires { T::widest_loop_copy; }) return T::widest_loop_copy;
    else return IsaPath::avx512;
  }
  static constexpr IsaPath widest = std::min({IsaPath::avx512, widest_of<Terms>()...});
  using PairType = PairOf<D, Terms...>;
  template <class T>
  static constexpr bool has_pair = requires(T& t, const Particles<D>& p, PairSums<D>& s, const PairType& pr) {
    t.pair(p, s, pr);
  };
  // What the scene's terms write, together.
  static constexpr Writes written = (Writes{} | ... | writes_of<D, Terms, PairType>());
  template <class T>
  static void prepare(T& t, Particles<D>& p, const Neighbourhood<D>& nb) {
    if constexpr (requires { t.prepare(p, nb); }) t.prepare(p, nb);
  }
  template <class T>
  static void pair(const T& t, const Particles<D>& p, PairSums<D>& s, const PairType& pr) {
    if constexpr (has_pair<T>) t.pair(p, s, pr);
  }
  template <class T>
  static void finish(T& t, const Particles<D>& p, const Neighbourhood<D>& nb, Derivatives<D>& d) {
    if constexpr (requires { t.finish(p, nb, d); }) t.finish(p, nb, d);
  }
};

}  // namespace sph
