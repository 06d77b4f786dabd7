#pragma once
#include <cstddef>
#include <tuple>
#include <vector>

#include "sph/core/particles.hpp"
#include "sph/hydro/pairs.hpp"
#include "sph/kernel/cubic_spline.hpp"

namespace sph {

// Time derivatives the terms of a scene accumulate, and mu_max = max_j |mu_ij| (46) of the
// artificial viscosity (0 without), which the Courant condition reads.
template <int D>
struct Derivatives {
  std::vector<Vec<D>> dvdt;
  std::vector<double> dudt, drhodt, dhdt, mu_max;
  void reset(std::size_t n) {
    dvdt.assign(n, Vec<D>::Zero());
    dudt.assign(n, 0.0);
    drhodt.assign(n, 0.0);
    dhdt.assign(n, 0.0);
    mu_max.assign(n, 0.0);
  }
};

// The same quantities of one particle i summed over its pairs by the pair loop.
template <int D>
struct PairSums {
  Vec<D> dvdt = Vec<D>::Zero();
  double dudt = 0.0, drhodt = 0.0, dhdt = 0.0, mu_max = 0.0;
};

// One interacting pair as the pair loop hands it to the terms: r_ij = r_i - r_j (nearest
// image), |r_ij|, the symmetric h_ij and grad_i W_ij(h_ij).
template <int D>
struct Pair {
  std::size_t i;
  int j;
  Vec<D> rij;
  double r, h;
  Vec<D> gradW;
};

// The particles with the geometry their pair loops need.
template <int D>
struct Neighbourhood {
  const NeighbourList& list;
  const Box<D>& box;
};

// A scene lists its physical terms as types. A term may provide any of
//   void prepare(Particles<D>&, const Neighbourhood<D>&)                   before the pair loop
//   void pair(const Particles<D>&, PairSums<D>&, const Pair<D>&)           inside it (adds i's share)
//   void finish(const Particles<D>&, const Neighbourhood<D>&, Derivatives<D>&)  after it
// The pair loop is a fold over the terms that have pair(): a term the scene does not list is not
// compiled into it, and no flag is tested per pair.
template <int D, class... Terms>
struct Scene {
  static constexpr int dim = D;
  std::tuple<Terms...> terms;

  void derivatives(Particles<D>& p, const Neighbourhood<D>& nb, Derivatives<D>& d) {
    d.reset(p.size());
    std::apply([&](auto&... t) { (prepare(t, p, nb), ...); }, terms);
    if constexpr ((has_pair<Terms> || ...)) {
      sum_over_pairs<D, PairSums<D>>(
          p.x, p.h, nb.list, nb.box,
          [&](PairSums<D>& s, std::size_t i, int j, const Vec<D>& rij, double r, double h, double g) {
            const Pair<D> pr{i, j, rij, r, h, Vec<D>(g * rij)};  // grad_i W_ij (9)
            std::apply([&](auto&... t) { (pair(t, p, s, pr), ...); }, terms);
          },
          [&](std::size_t i, const PairSums<D>& s) {
            d.dvdt[i] = s.dvdt;
            d.dudt[i] = s.dudt;
            d.drhodt[i] = s.drhodt;
            d.dhdt[i] = s.dhdt;
            d.mu_max[i] = s.mu_max;
          });
    }
    std::apply([&](auto&... t) { (finish(t, p, nb, d), ...); }, terms);
  }

  template <class T>
  T& term() { return std::get<T>(terms); }

 private:
  template <class T>
  static constexpr bool has_pair = requires(T& t, const Particles<D>& p, PairSums<D>& s, const Pair<D>& pr) {
    t.pair(p, s, pr);
  };
  template <class T>
  static void prepare(T& t, Particles<D>& p, const Neighbourhood<D>& nb) {
    if constexpr (requires { t.prepare(p, nb); }) t.prepare(p, nb);
  }
  template <class T>
  static void pair(T& t, const Particles<D>& p, PairSums<D>& s, const Pair<D>& pr) {
    if constexpr (has_pair<T>) t.pair(p, s, pr);
  }
  template <class T>
  static void finish(T& t, const Particles<D>& p, const Neighbourhood<D>& nb, Derivatives<D>& d) {
    if constexpr (requires { t.finish(p, nb, d); }) t.finish(p, nb, d);
  }
};

}  // namespace sph
