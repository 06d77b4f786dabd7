#pragma once
#include <filesystem>
#include <string>
#include <vector>

namespace sphv {

// `sphv bench`: throughput of the neighbour search, the density and hydro force loops, a full
// hydro step of a scheme, the tree and the direct sum, for 3D uniform gas at several N and thread
// counts. Benchmarks, not tests: nothing fails on a time; an unknown scheme is bad input.
struct BenchOptions {
  std::vector<long> sizes = {10000, 30000, 100000, 300000, 1000000};
  std::vector<int> threads;  // empty: 1 and all cores
  long tree_max = 400000, direct_max = 30000;  // the default sizes 3e5 (300763) included for the tree
  long shuffled_max = 100000;  // the step from shuffled storage, not reordered, is 3-4x slower
  std::string scheme = "chapter";  // the hydro stages' scheme (sph/schemes/schemes.hpp)
  std::filesystem::path out = "runs/bench";
};
void bench_command(BenchOptions o);

}  // namespace sphv
