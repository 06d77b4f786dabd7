#include "verification/snapshot/swift_ic.hpp"

#include <stdexcept>

#include "verification/snapshot/hdf5_file.hpp"

namespace sphv {

double swift_kernel_gamma(int dim) {
  switch (dim) {
    case 1: return 1.732051;
    case 2: return 1.778002;
    case 3: return 1.825742;
  }
  throw std::invalid_argument("SWIFT's kernel_gamma: dimension " + std::to_string(dim));
}

void write_swift_ic(const Snapshot& s, const SwiftIcHeader& header, const std::filesystem::path& path) {
  const hsize_t n = s.size();
  const double N = static_cast<double>(n);
  h5::Writer w(path);
  // Six entries per particle type, GADGET's count: no SWIFT has fewer types, so its reader's
  // buffer (swift_type_count entries) holds them.
  const hid_t h = w.group("Header");
  w.attribute(h, "BoxSize", {header.box[0], header.box[1], header.box[2]});
  w.attribute(h, "NumPart_ThisFile", {N, 0, 0, 0, 0, 0}, H5T_STD_I64LE);
  w.attribute(h, "NumPart_Total", {N, 0, 0, 0, 0, 0}, H5T_STD_I64LE);
  w.attribute(h, "NumPart_Total_HighWord", {0, 0, 0, 0, 0, 0}, H5T_STD_I64LE);
  w.attribute(h, "MassTable", {0, 0, 0, 0, 0, 0});
  w.attribute(h, "Flag_Entropy_ICs", {0, 0, 0, 0, 0, 0}, H5T_STD_I32LE);  // InternalEnergy is u, not an entropy
  w.attribute(h, "NumFilesPerSnapshot", {1}, H5T_STD_I32LE);
  w.attribute(h, "Dimension", {double(s.dim)}, H5T_STD_I32LE);
  w.attribute(h, "Time", {s.time.value_or(0.0)});
  const hid_t units = w.group("Units");
  for (const char* u : {"Unit length in cgs (U_L)", "Unit mass in cgs (U_M)", "Unit time in cgs (U_t)",
                        "Unit current in cgs (U_I)", "Unit temperature in cgs (U_T)"})
    w.attribute(units, u, {1.0});
  const hid_t scheme = w.group("HydroScheme");
  w.attribute(scheme, "Kernel gamma", {swift_kernel_gamma(s.dim)});
  if (header.gamma) w.attribute(scheme, "Adiabatic index", {*header.gamma});
  const hid_t gas = w.group("PartType0");
  for (const auto& [prefix, name] : {std::pair<std::string, std::string>{"", "Coordinates"}, {"v", "Velocities"}}) {
    std::vector<double> v(n * 3, 0.0);  // 3 components in every dimension: SWIFT reads N x 3
    for (int d = 0; d < s.dim; ++d) {
      const auto& c = s.at(prefix + std::string(1, "xyz"[d]), "SWIFT's " + name);
      for (hsize_t i = 0; i < n; ++i) v[i * 3 + d] = c[i];
    }
    w.dataset(gas, name, v, {n, 3});
  }
  w.dataset(gas, "Masses", s.at("m", "SWIFT's Masses"), {n});
  w.dataset(gas, "InternalEnergy", s.at("u", "SWIFT's InternalEnergy"), {n});
  w.dataset(gas, "Density", s.at("rho", "the density scored"), {n});
  std::vector<double> h_swift = s.at("h", "SWIFT's SmoothingLength");
  for (double& x : h_swift) x /= swift_kernel_gamma(s.dim);
  w.dataset(gas, "SmoothingLength", h_swift, {n});
  std::vector<double> ids(n);
  for (hsize_t i = 0; i < n; ++i) ids[i] = static_cast<double>(i + 1);
  w.dataset(gas, "ParticleIDs", ids, {n}, H5T_STD_U64LE);
  w.commit();
}

}  // namespace sphv
