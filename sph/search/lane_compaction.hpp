#pragma once
#include <array>

namespace sph {

// compaction[m]: the byte shuffle (pshufb) that moves the 32-bit lanes set in the 4-bit mask m to
// the front of a 16-byte vector, zeroing the rest: four candidates' indices, the kept ones
// written to a list in their order. Used by the vectorised grid search (search/grid_search.cpp)
// and pair filter (search/verlet_list.cpp).
inline constexpr std::array<std::array<unsigned char, 16>, 16> compaction = [] {
  std::array<std::array<unsigned char, 16>, 16> c{};
  for (int m = 0; m < 16; ++m) {
    int k = 0;
    for (int e = 0; e < 4; ++e)
      if (m >> e & 1) {
        for (int b = 0; b < 4; ++b) c[m][4 * k + b] = static_cast<unsigned char>(4 * e + b);
        ++k;
      }
    for (; k < 4; ++k)
      for (int b = 0; b < 4; ++b) c[m][4 * k + b] = 0x80;  // zero
  }
  return c;
}();

}  // namespace sph
