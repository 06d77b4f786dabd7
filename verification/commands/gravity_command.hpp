#pragma once
#include <string>

namespace sphv {

// `sphv gravity --input FILE [--theta T] [--multipole mono|quad] [--softening EPS] [--no-direct] --out FILE.csv`:
// tree and direct-sum gravity (G = 1, Plummer softening) of the user's particles (any snapshot
// read_snapshot reads: positions and masses); writes both fields and prints the error percentiles.
struct GravityCommandOptions {
  std::string input, out, multipole = "quad", opening = "robust";
  double theta = 0.5, eps = 0.0;
  bool no_direct = false;
};
void gravity_command(const GravityCommandOptions& o);

}  // namespace sphv
