// `sphv convert --input FILE --out FILE --format csv|swift|h5part [--time T]`: rewrites a snapshot
// in another format (e.g. sphv's particles.csv as a SWIFT or H5Part file).
#include <CLI/CLI.hpp>
#include <cmath>
#include <cstdio>

#include "verification/snapshot/convert_command.hpp"
#include "verification/snapshot/snapshot.hpp"

namespace sphv {

namespace {
struct Options {
  std::filesystem::path input, out;
  std::string format;
  double time = NAN;
};
}  // namespace

void add_convert_command(CLI::App& app) {
  auto o = std::make_shared<Options>();
  auto* cmd = app.add_subcommand("convert", "rewrite a particle snapshot in another format (csv, swift, h5part)");
  cmd->add_option("--input", o->input, "snapshot (any format sphv reads)")->required();
  cmd->add_option("--out", o->out, "output file")->required();
  cmd->add_option("--format", o->format, "csv|swift|h5part")->required()->check(CLI::IsMember({"csv", "swift", "h5part"}));
  cmd->add_option("--time", o->time, "the snapshot's time (overrides the input's)");
  cmd->callback([o] {
    Snapshot s = read_snapshot(o->input);
    if (std::isfinite(o->time)) s.time = o->time;
    write_snapshot(s, o->out, o->format);
    std::printf("%s -> %s (%s, %zu particles): %s\n", o->input.c_str(), o->out.c_str(), o->format.c_str(), s.size(),
                s.describe().c_str());
  });
}

}  // namespace sphv
