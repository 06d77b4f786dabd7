#pragma once
// The runtime choice of Euler form (22), (23), (25), (26) and energy form (37), (38), (40), (41),
// (42) (and "25": the symmetric energy form with (25)'s P_ij), resolved here, once, into term
// types: the caller's generic callable is instantiated per form and builds its scene from them,
// so nothing is tested per pair.
#include <stdexcept>
#include <string>

#include "sph/hydro/energy.hpp"
#include "sph/hydro/euler.hpp"

namespace sph {

// Calls f with the Euler term of the named form; lambda is (25)'s.
template <int D, class F>
auto with_euler_form(const std::string& form, double lambda, F&& f) {
  if (form == "22") return f(EulerDirect<D>{});
  if (form == "23") return f(EulerSymmetric<D, Lambda1>{});
  if (form == "25") return f(EulerSymmetric<D, LambdaGeneral>{LambdaGeneral{lambda}});
  if (form == "26") return f(EulerSymmetric<D, Lambda2>{});
  throw std::invalid_argument("unknown Euler form " + form);
}

// Calls f with the energy term of the named form; "25" is the symmetric form with (25)'s lambda.
template <int D, class F>
auto with_energy_form(const std::string& form, double lambda, F&& f) {
  using enum EnergyForm;
  if (form == "37") return f(EnergyAsymmetric<D, direct37>{});
  if (form == "38") return f(EnergyAsymmetric<D, difference38>{});
  if (form == "40") return f(EnergyAsymmetric<D, swapped40>{});
  if (form == "41") return f(EnergySymmetric<D, Lambda1>{});
  if (form == "42") return f(EnergySymmetric<D, Lambda2>{});
  if (form == "25") return f(EnergySymmetric<D, LambdaGeneral>{LambdaGeneral{lambda}});
  throw std::invalid_argument("unknown energy form " + form);
}

// The energy form the chapter pairs with each Euler form: 22-37, 23-41, 25-(25's own), 26-42.
inline std::string partner_energy(const std::string& euler) {
  if (euler == "22") return "37";
  if (euler == "23") return "41";
  if (euler == "25") return "25";
  if (euler == "26") return "42";
  throw std::invalid_argument("unknown Euler form " + euler);
}

// The energy term the chapter pairs with an Euler term, as a type: (22)-(37), (23)-(41), (25)-its
// own symmetric form with the same lambda, (26)-(42).
template <int D>
EnergyAsymmetric<D, EnergyForm::direct37> partner_energy_term(const EulerDirect<D>&) {
  return {};
}
template <int D, class Lambda>
EnergySymmetric<D, Lambda> partner_energy_term(const EulerSymmetric<D, Lambda>& e) {
  return {e.lambda};
}

// Calls f(euler, energy) with the terms of both named forms: one instantiation per pairing.
template <int D, class F>
auto with_hydro_forms(const std::string& euler, const std::string& energy, double lambda, F&& f) {
  return with_euler_form<D>(euler, lambda, [&](auto e) {
    return with_energy_form<D>(energy, lambda, [&](auto en) { return f(e, en); });
  });
}

}  // namespace sph
