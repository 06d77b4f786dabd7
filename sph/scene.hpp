#pragma once
#include <cstddef>
#include <tuple>
#include <vector>

#include "sph/kernel.hpp"
#include "sph/pairs.hpp"
#include "sph/particles.hpp"

namespace sph {

// Time derivatives the terms of a scene accumulate.
template <int D>
struct Derivatives {
  std::vector<Vec<D>> dvdt;
  std::vector<double> dudt, drhodt, dhdt;
  void reset(std::size_t n) {
    dvdt.assign(n, Vec<D>::Zero());
    dudt.assign(n, 0.0);
    drhodt.assign(n, 0.0);
    dhdt.assign(n, 0.0);
  }
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
//   void pair(const Particles<D>&, Derivatives<D>&, const Pair<D>&)        inside it (writes only i)
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
      for_each_pair<D>(p.x, p.h, nb.list, nb.box,
                       [&](std::size_t i, int j, const Vec<D>& rij, double r, double h) {
                         const Pair<D> pr{i, j, rij, r, h, CubicSpline<D>::gradW(rij, r, h)};
                         std::apply([&](auto&... t) { (pair(t, p, d, pr), ...); }, terms);
                       });
    }
    std::apply([&](auto&... t) { (finish(t, p, nb, d), ...); }, terms);
  }

  template <class T>
  T& term() { return std::get<T>(terms); }

 private:
  template <class T>
  static constexpr bool has_pair = requires(T& t, const Particles<D>& p, Derivatives<D>& d, const Pair<D>& pr) {
    t.pair(p, d, pr);
  };
  template <class T>
  static void prepare(T& t, Particles<D>& p, const Neighbourhood<D>& nb) {
    if constexpr (requires { t.prepare(p, nb); }) t.prepare(p, nb);
  }
  template <class T>
  static void pair(T& t, const Particles<D>& p, Derivatives<D>& d, const Pair<D>& pr) {
    if constexpr (has_pair<T>) t.pair(p, d, pr);
  }
  template <class T>
  static void finish(T& t, const Particles<D>& p, const Neighbourhood<D>& nb, Derivatives<D>& d) {
    if constexpr (requires { t.finish(p, nb, d); }) t.finish(p, nb, d);
  }
};

}  // namespace sph
