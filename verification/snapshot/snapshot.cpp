#include "verification/snapshot/snapshot.hpp"

#include <openssl/evp.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <fstream>

#include "verification/harness/params.hpp"

namespace sphv {

const std::vector<std::string>& snapshot_names() {
  static const std::vector<std::string> names = {"x", "y", "z", "vx", "vy", "vz", "m", "rho",
                                                 "u", "p", "h", "ax", "ay", "az", "phi"};
  return names;
}

std::string canonical_column(const std::string& file_name) {
  std::string s;
  for (char c : file_name)
    if (!std::isspace(static_cast<unsigned char>(c))) s += c == '-' || c == '.' ? '_' : std::tolower(static_cast<unsigned char>(c));
  // Spellings of SWIFT, GADGET, Phantom, SPH-EXA, PySPH and plain English.
  static const std::map<std::string, std::vector<std::string>> aliases = {
      {"m", {"mass", "masses"}},
      {"rho", {"density", "densities", "dens"}},
      {"u", {"internal_energy", "internal_energies", "internalenergy", "internalenergies", "specific_internal_energy",
             "specific_energy", "utherm"}},
      {"p", {"pressure", "pressures", "pres"}},
      {"h", {"smoothing_length", "smoothing_lengths", "smoothinglength", "smoothinglengths", "hsml"}},
      {"phi", {"potential", "potentials", "pot", "gpot"}}};
  for (const auto& [name, spellings] : aliases)
    if (s == name || std::find(spellings.begin(), spellings.end(), s) != spellings.end()) return name;
  // Vector components: x, pos_x, position_x, coordinates_x; vx, v_x, vel_x, velocity_x; ax, acc_x, ...
  for (const char* axis : {"x", "y", "z"}) {
    const std::string a = axis;
    for (const std::string pre : {"", "pos_", "position_", "positions_", "coord_", "coordinates_"})
      if (s == pre + a) return a;
    for (const std::string pre : {"v", "v_", "vel_", "velocity_", "velocities_"})
      if (s == pre + a) return "v" + a;
    for (const std::string pre : {"a", "a_", "acc_", "acceleration_", "accelerations_"})
      if (s == pre + a) return "a" + a;
  }
  return "";
}

const std::vector<double>& Snapshot::at(const std::string& name, const std::string& needed_by) const {
  const auto it = columns.find(name);
  if (it == columns.end())
    throw InputError(path.string() + ": no column for '" + name + "' (needed by " + needed_by + "; found: " +
                     describe() + ")");
  return it->second;
}

std::string Snapshot::describe() const {
  std::string s;
  for (const auto& name : snapshot_names())
    if (has(name)) s += (s.empty() ? "" : ", ") + name + " <- " + taken_from.at(name);
  return s.empty() ? "no usable column" : s;
}

namespace {

bool is_hdf5(const std::filesystem::path& path) {
  std::ifstream f(path, std::ios::binary);
  char sig[8] = {};
  f.read(sig, 8);
  return f.gcount() == 8 && std::string(sig, 8) == "\x89HDF\r\n\x1a\n";
}

void check(Snapshot& s) {
  const std::string f = s.path.string();
  if (const auto it = s.stated.find("box"); it != s.stated.end()) {
    auto& box = it->second.value;
    if (box.size() < 2 * static_cast<std::size_t>(s.dim))
      throw InputError(f + ": its box (" + it->second.from + ") has " + std::to_string(box.size() / 2) +
                       " axis(es) for " + std::to_string(s.dim) + " dimension(s)");
    box.resize(2 * s.dim);
  }
  if (!s.has("x")) throw InputError(f + ": no x coordinate (found: " + s.describe() + ")");
  if (s.size() == 0) throw InputError(f + ": no particles");
  if (s.time && !std::isfinite(*s.time)) throw InputError(f + ": the time in its header is not finite");
  for (const auto& [name, c] : s.columns) {
    if (c.size() != s.size())
      throw InputError(f + ": column " + s.taken_from.at(name) + " has " + std::to_string(c.size()) +
                       " values, x has " + std::to_string(s.size()));
    for (std::size_t i = 0; i < c.size(); ++i)
      if (!std::isfinite(c[i]))
        throw InputError(f + ": column " + s.taken_from.at(name) + " has a non-finite value (" + std::to_string(c[i]) +
                         ") at particle " + std::to_string(i));
  }
}

}  // namespace

Snapshot read_snapshot(const std::filesystem::path& path, const std::string& format, std::optional<long> step,
                       bool hdf5_in_child) {
  auto isolated = [&](const std::function<Snapshot()>& read) { return hdf5_in_child ? read_hdf5_isolated(path, read) : read(); };
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) throw InputError("cannot read snapshot " + path.string() + ": no such file");
  std::string fmt = format;
  if (fmt == "auto") fmt = is_hdf5(path) ? "hdf5" : "csv";
  Snapshot s;
  if (fmt == "csv") s = read_csv_snapshot(path);
  else if (fmt == "swift") s = isolated([&] { return read_swift_snapshot(path); });
  else if (fmt == "h5part") s = isolated([&] { return read_h5part_snapshot(path, step); });
  else if (fmt == "hdf5") {
    s = isolated([&] {
      try {
        return read_swift_snapshot(path);
      } catch (const InputError& swift_error) {
        try {
          return read_h5part_snapshot(path, step);
        } catch (const InputError&) {
          throw InputError(std::string(swift_error.what()) + " (and no /Step#k groups of H5Part either)");
        }
      }
    });
  } else throw InputError("unknown snapshot format '" + format + "' (auto, csv, swift, h5part)");
  check(s);
  return s;
}

void write_snapshot(const Snapshot& s, const std::filesystem::path& path, const std::string& format) {
  if (format == "csv") write_csv_snapshot(s, path);
  else if (format == "swift") write_swift_snapshot(s, path);
  else if (format == "h5part") write_h5part_snapshot(s, path);
  else throw InputError("unknown snapshot format '" + format + "' (csv, swift, h5part)");
}

nlohmann::json file_provenance(const std::filesystem::path& path) {
  std::ifstream f(path, std::ios::binary);
  EVP_MD_CTX* ctx = EVP_MD_CTX_new();
  EVP_DigestInit_ex(ctx, EVP_sha256(), nullptr);
  std::vector<char> buf(1 << 20);
  std::uintmax_t size = 0;
  while (f) {
    f.read(buf.data(), buf.size());
    EVP_DigestUpdate(ctx, buf.data(), f.gcount());
    size += f.gcount();
  }
  unsigned char md[EVP_MAX_MD_SIZE];
  unsigned int len = 0;
  EVP_DigestFinal_ex(ctx, md, &len);
  EVP_MD_CTX_free(ctx);
  std::string hex;
  char h[3];
  for (unsigned int k = 0; k < len; ++k) std::snprintf(h, sizeof h, "%02x", md[k]), hex += h;
  return {{"path", std::filesystem::absolute(path).string()}, {"size_bytes", size}, {"sha256", hex}};
}

}  // namespace sphv
