// HDF5 snapshots in the SWIFT/GADGET layout: /Header attributes Time, Dimension (SWIFT; GADGET
// files are 3D), BoxSize; /PartType0 datasets Coordinates and Velocities (N x 3, or N x D),
// Masses, Density(ies), InternalEnergy(ies), SmoothingLength(s), Pressure(s), optionally
// Acceleration(s) and Potential(s). Only the gas (PartType0) is read.
#include "verification/snapshot/hdf5_file.hpp"
#include "verification/snapshot/snapshot.hpp"

namespace sphv {

namespace {
// sphv name -> the dataset names codes use for it (SWIFT's plural first, then GADGET's).
const std::vector<std::pair<std::string, std::vector<std::string>>> scalars = {
    {"m", {"Masses", "Mass"}},
    {"rho", {"Densities", "Density"}},
    {"u", {"InternalEnergies", "InternalEnergy"}},
    {"h", {"SmoothingLengths", "SmoothingLength"}},
    {"p", {"Pressures", "Pressure"}},
    {"phi", {"Potentials", "Potential"}}};
const std::vector<std::pair<std::string, std::vector<std::string>>> vectors = {
    {"", {"Coordinates"}}, {"v", {"Velocities", "Velocity"}}, {"a", {"Accelerations", "Acceleration"}}};
}  // namespace

Snapshot read_swift_snapshot(const std::filesystem::path& path) {
  const std::string f = path.string();
  const h5::Handle file(h5::open_read(path), H5Fclose);
  if (!h5::exists(file, "PartType0")) throw InputError(f + ": no /PartType0 group (not a SWIFT/GADGET snapshot)");
  Snapshot s;
  s.path = path;
  s.format = "swift";
  std::optional<int> header_dim;
  if (h5::exists(file, "Header")) {
    const h5::Handle header(H5Gopen2(file, "Header", H5P_DEFAULT), H5Gclose);
    if (auto t = h5::read_attribute(header, "Time", f)) s.time = t->at(0);
    header_dim = h5::read_int_attribute(header, "Dimension", f, 1, 3);
  }
  const h5::Handle gas(H5Gopen2(file, "PartType0", H5P_DEFAULT), H5Gclose);
  for (const auto& [prefix, names] : vectors)
    for (const auto& name : names) {
      if (!h5::exists(gas, name)) continue;
      std::vector<hsize_t> dims;
      const auto v = h5::read_dataset(gas, name, f, dims);
      const std::size_t n = dims.at(0), cols = dims.size() == 2 ? dims[1] : 1;
      if (cols > 3) throw InputError(f + ": /PartType0/" + name + " has " + std::to_string(cols) + " columns (at most 3)");
      if (prefix.empty()) s.dim = header_dim ? *header_dim : static_cast<int>(cols);
      if (header_dim && static_cast<int>(cols) < *header_dim)
        throw InputError(f + ": /PartType0/" + name + " has " + std::to_string(cols) + " columns but /Header Dimension is " +
                         std::to_string(*header_dim));
      const std::size_t use = header_dim ? *header_dim : cols;
      for (std::size_t d = 0; d < use; ++d) {
        const std::string c = prefix + std::string(1, "xyz"[d]);
        auto& col = s.columns[c];
        col.resize(n);
        for (std::size_t i = 0; i < n; ++i) col[i] = v[i * cols + d];
        s.taken_from[c] = "/PartType0/" + name + "[:," + std::to_string(d) + "]";
      }
      break;
    }
  for (const auto& [c, names] : scalars)
    for (const auto& name : names) {
      if (!h5::exists(gas, name)) continue;
      std::vector<hsize_t> dims;
      s.columns[c] = h5::read_dataset(gas, name, f, dims);
      if (dims.size() != 1) throw InputError(f + ": /PartType0/" + name + " is not one value per particle");
      s.taken_from[c] = "/PartType0/" + name;
      break;
    }
  if (!s.has("x")) throw InputError(f + ": no /PartType0/Coordinates");
  return s;
}

void write_swift_snapshot(const Snapshot& s, const std::filesystem::path& path) {
  h5::Writer w(path);
  const hsize_t n = s.size();
  const hid_t header = w.group("Header");
  if (s.time) w.attribute(header, "Time", {*s.time});
  w.attribute(header, "Dimension", {double(s.dim)}, H5T_STD_I32LE);
  w.attribute(header, "NumPart_ThisFile", {double(n), 0, 0, 0, 0, 0}, H5T_STD_U64LE);
  const hid_t gas = w.group("PartType0");
  for (const auto& [prefix, names] : vectors) {
    if (!s.has(prefix + "x")) continue;
    std::vector<double> v(n * 3, 0.0);  // SWIFT writes 3 components in every dimension
    for (int d = 0; d < 3; ++d)
      if (const std::string c = prefix + std::string(1, "xyz"[d]); s.has(c))
        for (hsize_t i = 0; i < n; ++i) v[i * 3 + d] = s.columns.at(c)[i];
    w.dataset(gas, names.front(), v, {n, 3});
  }
  for (const auto& [c, names] : scalars)
    if (s.has(c)) w.dataset(gas, names.front(), s.columns.at(c), {n});
  w.commit();
}

}  // namespace sphv
