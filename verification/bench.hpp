#pragma once
#include "verification/cli_app.hpp"

namespace sphv {

// `sphv bench`: throughput of the neighbour search, the density and hydro force loops, a full
// hydro step, the tree and the direct sum, for 3D uniform gas at several N and thread counts.
// Benchmarks, not tests: nothing fails on a time.
void add_bench_command(CLI::App& app);

}  // namespace sphv
