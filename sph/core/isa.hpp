#pragma once
#include <algorithm>
#include <cstdlib>
#include <stdexcept>
#include <string>

namespace sph {

// Instruction-set path of the pair loops (hydro/pairs.hpp) and the tree gravity walk
// (gravity/tree_gravity.cpp); the neighbour search's candidate test and the reused lists' filter
// (search/grid_search.cpp, search/verlet_list.cpp) have copies of their own, which list the same
// pairs on every path. The loops of 2D and 3D scenes and the walk are compiled twice, for
// the portable default and for x86-64 with AVX2 and FMA; the loops of 3D scenes and the walk also
// a third time, for AVX-512 in 512-bit vectors (path avx512: 2D loops as avx2). The path is chosen
// once at run time: the fastest the CPU supports, or the one the environment variable SPHV_ISA
// names ("portable", "avx2" or "avx512"). FMA contraction rounds differently, so the pair loops'
// results are reproducible for a given path (and thread count independent on each), and a run's
// provenance records the path. The walk is compiled without contraction (CMakeLists.txt), so its
// field is the same on every path bit for bit (verification/tests/gravity.cpp). The pair loops
// sum in list order on every path; their copies agree to round-off (verification/tests/hydro.cpp).
enum class IsaPath { portable, avx2, avx512 };

// Defined where the compiler can build the second and third copies (x86-64, GCC's target
// attribute); the third copy's target.
#if defined(__x86_64__) && defined(__GNUC__)
#define SPH_AVX2_COPY 1
#define SPH_AVX512_TARGET "avx512f,avx512vl,avx512dq,avx512bw,fma,prefer-vector-width=512"
#endif

inline const char* isa_name(IsaPath p) {
  return p == IsaPath::avx512 ? "avx512" : p == IsaPath::avx2 ? "avx2" : "portable";
}

// The copy of a D-dimensional scene's pair loops that path p runs: in 1D the portable one (1D runs
// are small; another copy would cost compile time, not run time), in 2D at most AVX2, in 3D p's
// own (AVX-512's eight lanes speed up the 3D force and density loops); never wider than the
// widest copy a scene has compiled (hydro/scene.hpp: WidestLoopCopy).
template <int D>
IsaPath loop_path(IsaPath p, IsaPath widest = IsaPath::avx512) {
  if (D == 1) return IsaPath::portable;
  return std::min({p, widest, D == 2 ? IsaPath::avx2 : IsaPath::avx512});
}

inline bool isa_supported(IsaPath p) {
#ifdef SPH_AVX2_COPY
  const bool avx2 = __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma");
  if (p == IsaPath::avx2) return avx2;
  if (p == IsaPath::avx512)
    return avx2 && __builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512vl") &&
           __builtin_cpu_supports("avx512dq") && __builtin_cpu_supports("avx512bw");
#endif
  return p == IsaPath::portable;
}

// The path named by SPHV_ISA, else the fastest supported. Throws std::invalid_argument for a name
// that is not a path, or a path this CPU lacks.
inline IsaPath isa_from_environment() {
  const char* v = std::getenv("SPHV_ISA");
  if (!v || !*v)
    return isa_supported(IsaPath::avx512) ? IsaPath::avx512
           : isa_supported(IsaPath::avx2) ? IsaPath::avx2
                                          : IsaPath::portable;
  const std::string s = v;
  for (IsaPath p : {IsaPath::portable, IsaPath::avx2, IsaPath::avx512})
    if (s == isa_name(p)) {
      if (!isa_supported(p)) throw std::invalid_argument("SPHV_ISA=" + s + ": this CPU does not support it");
      return p;
    }
  throw std::invalid_argument("SPHV_ISA=" + s + ": not an instruction-set path (portable, avx2 or avx512)");
}

// The path every pair loop of this process takes: chosen at the first call, changed only by
// set_isa_path (tests comparing the paths; not while a loop runs).
inline IsaPath& isa_path_slot() {
  static IsaPath p = isa_from_environment();
  return p;
}
inline IsaPath isa_path() { return isa_path_slot(); }
inline void set_isa_path(IsaPath p) {
  if (!isa_supported(p)) throw std::invalid_argument(std::string("ISA path ") + isa_name(p) + " not supported here");
  isa_path_slot() = p;
}

}  // namespace sph
