#pragma once
#include <cstddef>

namespace sph {

// Below this many particles a loop over particles or pairs runs on one thread: forking a team
// costs more than it saves, and small runs (1D tubes, heat tests) take thousands of steps. Every
// threaded loop writes per particle (or reduces by min, max or a logical and), so results do not
// depend on the thread count. A variable so that a test can set it to 0 and run small scenes on
// several threads, to check that claim where it would otherwise hold trivially (tests/gates.cpp).
inline std::size_t parallel_threshold = 4096;

}  // namespace sph
