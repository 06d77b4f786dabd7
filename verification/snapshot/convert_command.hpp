#pragma once
#include "verification/cli_app.hpp"

namespace sphv {

// `sphv convert --input FILE --out FILE --format csv|swift|h5part [--time T]`.
void add_convert_command(CLI::App& app);

}  // namespace sphv
