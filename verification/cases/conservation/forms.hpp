#pragma once
// The Euler forms (22), (23), (25), (26) and energy forms (37), (38), (40), (41), (42) (and the
// symmetric energy form with (25)'s P_ij) of the conservation catalogue, by name; each is
// dispatched once to its scene term type by sph/hydro/forms.hpp.
#include <string>
#include <vector>

#include "sph/hydro/forms.hpp"

namespace sphv::conservation {

struct EulerChoice {
  std::string form;     // "22", "23", "25", "26"
  double lambda = 1.0;  // for (25)
  std::string label() const { return form == "25" ? "25(l=" + lambda_text() + ")" : form; }
  std::string lambda_text() const {
    std::string s = std::to_string(lambda);
    s.erase(s.find_last_not_of('0') + 1);
    if (s.back() == '.') s.pop_back();
    return s;
  }
};

// (25) with several lambda besides 1 (= (23)) and 2 (= (26)). lambda = 0 (p_j/rho_i^2 + p_i/rho_j^2)
// is left out: it drives u < 0 at the free surface of the 3D blobs (measured: step ~80 of 150).
inline std::vector<EulerChoice> euler_forms() {
  return {{"22"}, {"23"}, {"25", 0.5}, {"25", 1.5}, {"25", 2.5}, {"26"}};
}

// Energy forms for an Euler form: the five of the chapter, and for (25) the symmetric energy
// form with the same P_ij ("25").
inline std::vector<std::string> energy_forms(const EulerChoice& e) {
  std::vector<std::string> f = {"37", "38", "40", "41", "42"};
  if (e.form == "25") f.push_back("25");
  return f;
}

// Pairs for which sum_i m_i (v_i . dv_i/dt + du_i/dt) = 0 identically, by the relabelling
// i <-> j of (102)-(104) and grad_j W_ji = -grad_i W_ij:
//   (22) + (37): sum_ij m_i m_j p_i/(rho_i rho_j) v_j . grad_i W_ij relabels to the kinetic sum;
//   (23) + (41), and also (23) + (38) and (23) + (40): the sums over i of (38), (40) and (41)
//        are equal (each is sum_ij m_i m_j (p_i + p_j)/(rho_i rho_j) v_i . grad_i W_ij);
//   (26) + (42) (the chapter's (97)-(101)), and (25) + its own symmetric form for any lambda.
// Every other pairing leaves a residual of the order of the discretisation error.
inline bool conserves_energy(const EulerChoice& e, const std::string& energy) {
  if (e.form == "22") return energy == "37";
  if (e.form == "23") return energy == "38" || energy == "40" || energy == "41";
  if (e.form == "26") return energy == "42";
  return energy == "25";
}

}  // namespace sphv::conservation
