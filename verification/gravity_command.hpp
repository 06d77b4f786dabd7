#pragma once
#include "verification/cli_app.hpp"

namespace sphv {

// `sphv gravity --input FILE [--theta T] [--multipole mono|quad] [--softening EPS] [--no-direct] --out FILE.csv`:
// tree and direct-sum gravity (G = 1, Plummer softening) of the user's particles (any snapshot
// read_snapshot reads: positions and masses); writes both fields and prints the error percentiles.
void add_gravity_command(CLI::App& app);

}  // namespace sphv
