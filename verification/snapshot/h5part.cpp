// HDF5 snapshots in the H5Part layout SPH-EXA writes: groups /Step#k, each with one dataset per
// field (x y z vx vy vz rho u p h m, ...) and an attribute `time`. The step read is the last one
// unless asked for; the dimension is the root attribute `dim` when present, else the number of
// coordinate datasets. What the file states of the set-up, as SPH-EXA writes it: the adiabatic
// index (the step's attribute `gamma`, else the root's), the box (the step's `box`: x_lo, x_hi,
// y_lo, y_hi, z_lo, z_hi) and periodicity along x (the step's `boundaryType`, cstone's
// BoundaryType: 0 open, 1 periodic, 2 fixed).
#include <charconv>
#include <cmath>
#include <iterator>
#include <map>
#include <string_view>

#include "verification/snapshot/hdf5_file.hpp"
#include "verification/snapshot/snapshot.hpp"

namespace sphv {

namespace {
// The k of every /Step#k group, with the group's name as written (Step#0001 is step 1).
std::map<long, std::string> steps(hid_t file) {
  std::map<long, std::string> ks;
  H5G_info_t info;
  if (H5Gget_info(file, &info) < 0) return ks;
  for (hsize_t i = 0; i < info.nlinks; ++i) {
    char name[256];
    if (H5Lget_name_by_idx(file, ".", H5_INDEX_NAME, H5_ITER_INC, i, name, sizeof name, H5P_DEFAULT) < 0) continue;
    // "Step#" and digits only, in the range of a long.
    const std::string_view text(name), prefix = "Step#";
    if (!text.starts_with(prefix) || text.size() == prefix.size() || text[prefix.size()] == '-') continue;
    long k = -1;
    const auto [end, ec] = std::from_chars(text.data() + prefix.size(), text.data() + text.size(), k);
    if (ec == std::errc() && end == text.data() + text.size()) ks.emplace(k, std::string(text));
  }
  return ks;
}
}  // namespace

Snapshot read_h5part_snapshot(const std::filesystem::path& path, std::optional<long> step) {
  const std::string f = path.string();
  const h5::Handle file(h5::open_read(path), H5Fclose);
  const auto ks = steps(file);
  if (ks.empty()) throw InputError(f + ": no /Step#k group (not an H5Part file)");
  auto chosen = std::prev(ks.end());
  if (step) {
    chosen = ks.find(*step);
    if (chosen == ks.end())
      throw InputError(f + ": no /Step#" + std::to_string(*step) + " (steps " + std::to_string(ks.begin()->first) + ".." +
                       std::to_string(ks.rbegin()->first) + ")");
  }
  const std::string& group = chosen->second;
  const h5::Handle g(H5Gopen2(file, group.c_str(), H5P_DEFAULT), H5Gclose);
  H5G_info_t info;
  if (!g.ok() || H5Gget_info(g, &info) < 0) throw InputError(f + ": /" + group + " is not a group");
  Snapshot s;
  s.path = path;
  s.format = "h5part";
  if (auto t = h5::read_attribute(g, "time", f)) s.time = t->at(0), s.time_from = "/" + group + " time";
  for (hsize_t i = 0; i < info.nlinks; ++i) {
    char name[256];
    if (H5Lget_name_by_idx(g, ".", H5_INDEX_NAME, H5_ITER_INC, i, name, sizeof name, H5P_DEFAULT) < 0) continue;
    const std::string c = canonical_column(name);
    if (c.empty() || s.has(c)) continue;
    std::vector<hsize_t> dims;
    s.columns[c] = h5::read_dataset(g, name, f, dims, &s.round_off[c]);
    if (dims.size() != 1) throw InputError(f + ": /" + group + "/" + name + " is not one value per particle");
    s.taken_from[c] = "/" + group + "/" + name;
  }
  if (s.has("z") && !s.has("y")) throw InputError(f + ": /" + group + " has z but no y");
  s.dim = s.has("z") ? 3 : s.has("y") ? 2 : 1;
  if (const auto d = h5::read_int_attribute(file, "dim", f, 1, 3)) {
    const int dim = *d;
    if (dim > s.dim)
      throw InputError(f + ": root attribute dim = " + std::to_string(dim) + " but /" + group + " has " +
                       std::to_string(s.dim) + " coordinate(s)");
    for (int a = dim; a < 3; ++a) s.columns.erase(std::string(1, "xyz"[a])), s.columns.erase("v" + std::string(1, "xyz"[a]));
    s.dim = dim;
  }
  for (const auto& [obj, where] : {std::pair<hid_t, std::string>{g, "/" + group}, {file, "the root"}}) {
    double round_off = 0.0;
    if (auto gamma = h5::read_attribute(obj, "gamma", f, &round_off)) {
      if (!(gamma->at(0) > 1.0 && std::isfinite(gamma->at(0))))
        throw InputError(f + ": attribute gamma of " + where + " is " + std::to_string(gamma->at(0)) + " (must be > 1)");
      s.stated["gamma"] = {{gamma->at(0)}, where + " gamma", round_off};
      break;
    }
  }
  if (auto box = h5::read_attribute(g, "box", f)) {
    if (box->size() < 2 * static_cast<std::size_t>(s.dim))
      throw InputError(f + ": attribute box of /" + group + " has " + std::to_string(box->size()) + " values for " +
                       std::to_string(s.dim) + " dimension(s) (x_lo, x_hi, y_lo, ...)");
    box->resize(2 * s.dim);
    for (int d = 0; d < s.dim; ++d)
      if (!(std::isfinite((*box)[2 * d]) && std::isfinite((*box)[2 * d + 1]) && (*box)[2 * d] < (*box)[2 * d + 1]))
        throw InputError(f + ": attribute box of /" + group + " is not lo < hi along axis " + std::string(1, "xyz"[d]));
    s.stated["box"] = {*box, "/" + group + " box"};
  }
  if (auto b = h5::read_attribute(g, "boundaryType", f)) {
    const double x = b->at(0);
    if (x != 0.0 && x != 1.0 && x != 2.0)
      throw InputError(f + ": attribute boundaryType of /" + group + " is " + std::to_string(x) + " along x (0, 1 or 2)");
    s.stated["periodic"] = {{x == 1.0 ? 1.0 : 0.0}, "/" + group + " boundaryType[0]"};
  }
  return s;
}

void write_h5part_snapshot(const Snapshot& s, const std::filesystem::path& path) {
  h5::Writer w(path);
  w.attribute(w.file(), "dim", {double(s.dim)}, H5T_STD_I32LE);
  const hid_t g = w.group("Step#0");
  if (s.time) w.attribute(g, "time", {*s.time});
  for (const auto& name : snapshot_names())
    if (s.has(name)) w.dataset(g, name, s.columns.at(name), {s.size()});
  w.commit();
}

}  // namespace sphv
