#pragma once
#include <cmath>
#include <filesystem>
#include <string>

namespace sphv {

// `sphv convert --input FILE --out FILE --format csv|swift|h5part [--time T]`.
struct ConvertOptions {
  std::filesystem::path input, out;
  std::string format;
  double time = NAN;  // NaN: the input's
};
void convert_command(const ConvertOptions& o);

}  // namespace sphv
