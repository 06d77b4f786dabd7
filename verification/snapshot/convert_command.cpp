// `sphv convert --input FILE --out FILE --format csv|swift|h5part [--time T]`: rewrites a snapshot
// in another format (e.g. sphv's particles.csv as a SWIFT or H5Part file).
#include <cmath>
#include <cstdio>

#include "verification/snapshot/convert_command.hpp"
#include "verification/snapshot/snapshot.hpp"

namespace sphv {

void convert_command(const ConvertOptions& o) {
  Snapshot s = read_snapshot(o.input);
  if (std::isfinite(o.time)) s.time = o.time;
  write_snapshot(s, o.out, o.format);
  std::printf("%s -> %s (%s, %zu particles): %s\n", o.input.c_str(), o.out.c_str(), o.format.c_str(), s.size(),
              s.describe().c_str());
}

}  // namespace sphv
