// The tree walks of sph/gravity/tree_gravity.hpp, compiled once per method and instruction-set
// path (core/isa.hpp): the group walk in a portable copy, an AVX2 + FMA copy and an AVX-512 copy.
#include "sph/gravity/tree_gravity.hpp"

#include "sph/core/isa.hpp"

namespace sph {

namespace {
template <Multipole M, Opening O>
[[gnu::flatten]] void group_portable(const detail::Walk& w, detail::Lanes in, detail::Group& g) {
  detail::group_field<M, O>(w, in, g);
}

#ifdef SPH_AVX2_COPY
template <Multipole M, Opening O>
[[gnu::flatten, gnu::target("avx2,fma")]] void group_avx2(const detail::Walk& w, detail::Lanes in, detail::Group& g) {
  detail::group_field<M, O>(w, in, g);
}

// The sum's lanes are 8 targets, not the AVX2 copy's 4: a group takes half the vector operations.
template <Multipole M, Opening O>
[[gnu::flatten, gnu::target(SPH_AVX512_TARGET)]] void group_avx512(
    const detail::Walk& w, detail::Lanes in, detail::Group& g) {
  detail::group_field<M, O>(w, in, g);
}
#endif

template <Multipole M, Opening O>
GravityField field(const Tree<3>& t, const std::vector<Vec<3>>& x, const std::vector<double>& m,
                   const GravityOptions& o, const std::vector<Vec<3>>& targets, bool at_particles) {
  detail::GroupField group = group_portable<M, O>;
#ifdef SPH_AVX2_COPY
  if (isa_path() == IsaPath::avx2) group = group_avx2<M, O>;
  if (isa_path() == IsaPath::avx512) group = group_avx512<M, O>;
#endif
  return detail::field(detail::walk_of<O>(t, x, m, o), targets, at_particles, group);
}
}  // namespace

GravityField tree_gravity_at(const Tree<3>& t, const std::vector<Vec<3>>& x, const std::vector<double>& m,
                             const GravityOptions& o, const std::vector<Vec<3>>& targets, bool at_particles) {
  if (!(o.theta > 0.0)) throw std::invalid_argument("tree gravity: opening angle theta must be > 0");
  if (!(o.eps >= 0.0)) throw std::invalid_argument("tree gravity: softening eps must be >= 0");
  using enum Multipole;
  using enum Opening;
  if (o.multipole == monopole)
    return o.opening == plain ? field<monopole, plain>(t, x, m, o, targets, at_particles)
                              : field<monopole, robust>(t, x, m, o, targets, at_particles);
  return o.opening == plain ? field<quadrupole, plain>(t, x, m, o, targets, at_particles)
                            : field<quadrupole, robust>(t, x, m, o, targets, at_particles);
}

}  // namespace sph
