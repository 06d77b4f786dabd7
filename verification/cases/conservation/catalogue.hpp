#pragma once
// The conservation catalogue of case `conservation`: every Euler/energy pairing on the colliding
// blobs, instantiated per dimension in conservation/scenes_2d.cpp and conservation/scenes_3d.cpp.
#include <string>
#include <vector>

#include "sph/density/terms.hpp"
#include "sph/hydro/eos.hpp"
#include "sph/hydro/viscosity.hpp"
#include "verification/cases/conservation/forms.hpp"
#include "verification/cases/conservation/scene.hpp"

namespace sphv::conservation {

struct CatalogueSetup {
  long n = 16;           // particles per blob diameter
  double hfact = 2.4;    // support radius / particle spacing (50)
  bool viscosity = true; // artificial viscosity (44)-(48) with alpha = 1, beta = 2
  long steps = 150;
  double t_end = 0.3;
  sph::IntegratorKind integrator = sph::IntegratorKind::kdk;
};

struct CatalogueRow {
  EulerChoice euler;
  std::string energy;
  bool conserves_energy = false;
  Drifts drifts;
};

struct Catalogue {
  std::size_t particles = 0;
  std::vector<CatalogueRow> rows;
};

// One Euler/energy pairing on a copy of `initial`: summation density (27), ideal gas with
// gamma = 5/3, fixed support radii (h_ij symmetric), optionally artificial viscosity. The blobs
// are small: the pair loops' copies stop at AVX2 (WidestLoopCopy, sph/hydro/scene.hpp).
template <int D>
Drifts run_pairing(const sph::Particles<D>& initial, const EulerChoice& e, const std::string& energy_form,
                   bool viscosity, sph::IntegratorKind integrator, double dt, long steps) {
  Drifts out;
  auto go = [&](auto... terms) {
    sph::Particles<D> p = initial;
    using Copies = sph::WidestLoopCopy<sph::IsaPath::avx2>;
    sph::Scene<D, Copies, sph::SummationDensity<D>, sph::EquationOfState<D, sph::IdealGas>, decltype(terms)...> scene{
        {Copies{}, sph::SummationDensity<D>{}, sph::EquationOfState<D, sph::IdealGas>{{5.0 / 3.0}}, terms...}};
    out = run_fixed_steps(scene, p, integrator, dt, steps);
  };
  sph::with_hydro_forms<D>(e.form, energy_form, e.lambda, [&](auto euler, auto energy) {
    if (viscosity) go(euler, energy, sph::ArtificialViscosity<D>{});
    else go(euler, energy);
  });
  return out;
}

template <int D>
Catalogue catalogue(const CatalogueSetup& s) {
  const sph::Particles<D> initial = colliding_blobs<D>(s.n, s.hfact);
  Catalogue out;
  out.particles = initial.size();
  for (const EulerChoice& e : euler_forms())
    for (const std::string& en : energy_forms(e))
      out.rows.push_back({e, en, conserves_energy(e, en),
                          run_pairing(initial, e, en, s.viscosity, s.integrator, s.t_end / s.steps, s.steps)});
  return out;
}

extern template Catalogue catalogue<2>(const CatalogueSetup&);
extern template Drifts run_pairing<2>(const sph::Particles<2>&, const EulerChoice&, const std::string&, bool,
                                     sph::IntegratorKind, double, long);
extern template Catalogue catalogue<3>(const CatalogueSetup&);

}  // namespace sphv::conservation
