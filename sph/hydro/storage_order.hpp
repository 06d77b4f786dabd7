#pragma once
#include <cstddef>
#include <type_traits>
#include <vector>

#include "sph/core/particles.hpp"
#include "sph/core/threads.hpp"
#include "sph/hydro/scene.hpp"

namespace sph {

// The particles' storage along the neighbour search's cell order, during a run (evolve). The pair
// loops visit the particles in that order whatever their storage; stored in it as well, a
// particle's neighbours lie near it in memory. Particles stored in no spatial order (a snapshot
// of another code, a shuffled lattice) make every pair loop gather from all over memory, several
// times slower; a lattice stored row by row gains nothing. StorageOrder keeps the caller's index of
// each particle stored, so that the caller gets its particles back in its own order.
template <int D>
class StorageOrder {
 public:
  // Stores particle order[k] of p (and of its rates d) at k. Nothing happens for an empty order.
  void apply(const std::vector<int>& order, Particles<D>& p, Derivatives<D>& d) {
    if (order.empty()) return;
    const std::size_t n = order.size();
    std::vector<int> id(n);
#pragma omp parallel for if (n >= parallel_threshold)
    for (std::size_t k = 0; k < n; ++k) id[k] = id_.empty() ? order[k] : id_[order[k]];
    id_.swap(id);
    for (auto* a : {&p.x, &p.v, &d.dvdt}) gather(*a, order, vecs_);
    for (auto* a : {&p.m, &p.rho, &p.p, &p.c, &p.u, &p.h, &d.dudt, &d.drhodt, &d.dhdt, &d.mu_max})
      gather(*a, order, scalars_);
  }

  // p back in the caller's order.
  void restore(Particles<D>& p) {
    if (id_.empty()) return;
    for (auto* a : {&p.x, &p.v}) scatter(*a, vecs_);
    for (auto* a : {&p.m, &p.rho, &p.p, &p.c, &p.u, &p.h}) scatter(*a, scalars_);
    id_.clear();
  }

  // The caller's index of the particle stored at k.
  std::size_t caller_index(std::size_t k) const { return id_.empty() ? k : static_cast<std::size_t>(id_[k]); }

 private:
  // a[k] = a[order[k]] through the scratch array s, which keeps a's old storage for the next array.
  template <class T>
  static void gather(std::vector<T>& a, const std::vector<int>& order, std::vector<T>& s) {
    const std::size_t n = order.size();
    if (a.size() != n) return;  // an array the run does not use (left empty)
    s.resize(n);
#pragma omp parallel for if (n >= parallel_threshold)
    for (std::size_t k = 0; k < n; ++k) s[k] = a[order[k]];
    a.swap(s);
  }
  template <class T>
  void scatter(std::vector<T>& a, std::vector<T>& s) const {
    const std::size_t n = id_.size();
    if (a.size() != n) return;
    s.resize(n);
#pragma omp parallel for if (n >= parallel_threshold)
    for (std::size_t k = 0; k < n; ++k) s[id_[k]] = a[k];
    a.swap(s);
  }

  std::vector<int> id_;  // id_[k]: the caller's index of the particle stored at k (empty: k)
  std::vector<Vec<D>> vecs_;
  std::vector<double> scalars_;
};

// A scene term that keeps arrays over the particles for its caller to read after a run (the
// potential of SelfGravity) declares `static constexpr bool keeps_particle_arrays = true`: evolve
// then leaves the particles in the caller's order, in which those arrays are read.
template <class T>
constexpr bool keeps_particle_arrays = requires { requires std::remove_cvref_t<T>::keeps_particle_arrays; };

}  // namespace sph
