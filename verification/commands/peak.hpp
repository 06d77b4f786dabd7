#pragma once
// The double-precision peak of this CPU, measured: what `sphv bench` compares the force loop with.
#include <string>

namespace sphv {

struct Peak {
  std::string isa;     // the widest vectors the CPU runs: "avx512f", "avx2+fma" or "sse2"
  double flops_per_s;  // all threads together
};

// Independent chains of fused multiply-adds (2 flops each) on the widest vectors, on `threads`
// threads at once; best of five runs of about 0.1 s.
Peak measure_peak(int threads);

}  // namespace sphv
