// HDF5 snapshots in the SWIFT/GADGET layout: /Header attributes Time, Dimension (SWIFT; GADGET
// files are 3D), BoxSize; /PartType0 datasets Coordinates and Velocities (N x 3, or N x D),
// Masses, Density(ies), InternalEnergy(ies), SmoothingLength(s), Pressure(s), optionally
// Acceleration(s) and Potential(s). Only the gas (PartType0) is read. What the file states of the
// set-up is kept with where it says it: the box [0, BoxSize] per axis (/Header BoxSize: three
// values, or GADGET's one), the adiabatic index (/HydroScheme `Adiabatic index`), periodicity
// (/Parameters `InitialConditions:periodic`, SWIFT's run-time parameter). SWIFT's
// SmoothingLengths are its h, whose kernel reaches `Kernel gamma` h (/HydroScheme): sphv's h is
// the support radius, so h is read as Kernel gamma times SmoothingLengths where it is stated.
#include <cmath>

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
  std::optional<std::vector<double>> box_size;
  if (h5::exists(file, "Header")) {
    const h5::Handle header(H5Gopen2(file, "Header", H5P_DEFAULT), H5Gclose);
    if (auto t = h5::read_attribute(header, "Time", f)) s.time = t->at(0), s.time_from = "/Header Time";
    header_dim = h5::read_int_attribute(header, "Dimension", f, 1, 3);
    box_size = h5::read_attribute(header, "BoxSize", f);
  }
  std::optional<double> kernel_gamma;
  if (h5::exists(file, "HydroScheme")) {
    const h5::Handle scheme(H5Gopen2(file, "HydroScheme", H5P_DEFAULT), H5Gclose);
    double round_off = 0.0;
    if (auto g = h5::read_attribute(scheme, "Adiabatic index", f, &round_off)) {
      if (!(g->at(0) > 1.0 && std::isfinite(g->at(0))))
        throw InputError(f + ": /HydroScheme Adiabatic index is " + std::to_string(g->at(0)) + " (must be > 1)");
      s.stated["gamma"] = {{g->at(0)}, "/HydroScheme Adiabatic index", round_off};
    }
    if (auto k = h5::read_attribute(scheme, "Kernel gamma", f)) {
      if (!(k->at(0) > 0.0 && std::isfinite(k->at(0))))
        throw InputError(f + ": /HydroScheme Kernel gamma is " + std::to_string(k->at(0)) + " (must be > 0)");
      kernel_gamma = k->at(0);
    }
  }
  if (h5::exists(file, "Parameters")) {
    const h5::Handle params(H5Gopen2(file, "Parameters", H5P_DEFAULT), H5Gclose);
    if (auto periodic = h5::read_text_attribute(params, "InitialConditions:periodic")) {
      if (*periodic != "0" && *periodic != "1")
        throw InputError(f + ": /Parameters InitialConditions:periodic is '" + *periodic + "' (expected 0 or 1)");
      s.stated["periodic"] = {{*periodic == "1" ? 1.0 : 0.0}, "/Parameters InitialConditions:periodic"};
    }
  }
  const h5::Handle gas(H5Gopen2(file, "PartType0", H5P_DEFAULT), H5Gclose);
  for (const auto& [prefix, names] : vectors)
    for (const auto& name : names) {
      if (!h5::exists(gas, name)) continue;
      std::vector<hsize_t> dims;
      double round_off = 0.0;
      const auto v = h5::read_dataset(gas, name, f, dims, &round_off);
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
        s.round_off[c] = round_off;
      }
      break;
    }
  for (const auto& [c, names] : scalars)
    for (const auto& name : names) {
      if (!h5::exists(gas, name)) continue;
      std::vector<hsize_t> dims;
      s.columns[c] = h5::read_dataset(gas, name, f, dims, &s.round_off[c]);
      if (dims.size() != 1) throw InputError(f + ": /PartType0/" + name + " is not one value per particle");
      s.taken_from[c] = "/PartType0/" + name;
      break;
    }
  if (!s.has("x")) throw InputError(f + ": no /PartType0/Coordinates");
  if (kernel_gamma && s.has("h")) {
    for (double& h : s.columns["h"]) h *= *kernel_gamma;
    s.taken_from["h"] = shortest(*kernel_gamma) + " (/HydroScheme Kernel gamma) x " + s.taken_from["h"];
  }
  if (box_size) {
    // SWIFT writes three sides in every dimension, GADGET one for a cube.
    if (box_size->size() != 1 && box_size->size() < static_cast<std::size_t>(s.dim))
      throw InputError(f + ": /Header BoxSize has " + std::to_string(box_size->size()) + " values for " +
                       std::to_string(s.dim) + " dimension(s)");
    std::vector<double> box;
    for (int d = 0; d < s.dim; ++d) {
      const double side = box_size->at(box_size->size() == 1 ? 0 : d);
      if (!(side > 0.0 && std::isfinite(side)))
        throw InputError(f + ": /Header BoxSize is " + std::to_string(side) + " (must be > 0)");
      box.push_back(0.0), box.push_back(side);
    }
    s.stated["box"] = {box, "/Header BoxSize"};
  }
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
