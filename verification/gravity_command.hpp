#pragma once
#include <CLI/CLI.hpp>

namespace sphv {

// `sphv gravity --input FILE.csv [--theta T] [--multipole mono|quad] [--softening EPS] --out FILE.csv`:
// tree and direct-sum gravity (G = 1, Plummer softening) of the user's particles (columns
// x,y,z,m with a header row); writes both fields and prints the error percentiles.
void add_gravity_command(CLI::App& app);

}  // namespace sphv
