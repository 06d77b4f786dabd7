#pragma once
// The centre of a radially symmetric set-up (sedov, noh) in a scored snapshot: codes put it at
// the origin or at the box centre. `sphv run` builds its set-ups around the origin.
#include <string>

#include "sph/core/vec.hpp"
#include "verification/harness/params.hpp"

namespace sphv::radial {

inline ParamSpec centre_param() {
  return {"centre", ParamSpec::Kind::Text, "0,0,0",
          "centre x,y,z of the set-up in a scored snapshot (sphv score; sphv run uses the origin)"};
}

// The first D coordinates of the parameter "centre" ("x,y,z"; missing ones are 0).
template <int D>
sph::Vec<D> centre(const Params& p) {
  const std::string& s = p.text("centre");
  sph::Vec<D> c = sph::Vec<D>::Zero();
  std::size_t from = 0;
  for (int d = 0; d < 3 && from <= s.size(); ++d) {
    const std::size_t to = std::min(s.find(',', from), s.size());
    double v = 0.0;
    if (!parse_finite(std::string_view(s).substr(from, to - from), v))
      throw InputError("parameter centre: '" + s + "' is not x,y,z (three finite numbers)");
    if (d < D) c[d] = v;
    from = to + 1;
  }
  return c;
}

}  // namespace sphv::radial
