// HDF5 snapshots in the H5Part layout SPH-EXA writes: groups /Step#k, each with one dataset per
// field (x y z vx vy vz rho u p h m, ...) and an attribute `time`. The step read is the last one
// unless asked for; the dimension is the root attribute `dim` when present, else the number of
// coordinate datasets.
#include <charconv>
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
  if (auto t = h5::read_attribute(g, "time", f)) s.time = t->at(0);
  for (hsize_t i = 0; i < info.nlinks; ++i) {
    char name[256];
    if (H5Lget_name_by_idx(g, ".", H5_INDEX_NAME, H5_ITER_INC, i, name, sizeof name, H5P_DEFAULT) < 0) continue;
    const std::string c = canonical_column(name);
    if (c.empty() || s.has(c)) continue;
    std::vector<hsize_t> dims;
    s.columns[c] = h5::read_dataset(g, name, f, dims);
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
