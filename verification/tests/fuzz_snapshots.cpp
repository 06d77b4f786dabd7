// Fuzzed snapshots: every reader a user reaches (CSV, SWIFT/GADGET HDF5, H5Part; `sphv score`,
// `sphv gravity --input`, `sphv convert`) is fed at least 10,000 generated malformed files each.
// Every file is refused with one InputError line naming it, or read into a snapshot that keeps
// the reader's promises (particles, equal-length finite columns, x present); then the particles
// of gravity and a rotating case's scorer must also end in a result or an InputError. Never a
// crash, another exception or a hang. HDF5 files are malformed in their structure (missing or
// extra objects, wrong rank, length, type or name, non-finite and out-of-range values) and in
// their bytes (cut short, bytes overwritten); HDF5 1.10 itself crashes on some of the latter, which
// read_snapshot contains in a child process (snapshot/isolated.cpp), as it does for every user. The generator is seeded: a failure names the seed
// and index that replay it.
#include <hdf5.h>
#include <unistd.h>

#include <catch2/catch.hpp>
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>

#include "verification/io/gravity_input.hpp"
#include "verification/harness/params.hpp"
#include "verification/commands/score.hpp"
#include "verification/snapshot/snapshot.hpp"
#include "verification/tests/fuzz_inputs.hpp"

namespace fs = std::filesystem;
using namespace sphv;

namespace {

constexpr std::size_t wanted = 10000;  // malformed files refused per reader (issue 17)
#ifdef SPHV_SANITIZED
// Under AddressSanitizer each HDF5 file open costs ~10 ms (the library callocs its multi-MB
// metadata cache, which the sanitizer maps and unmaps; measured 155 s for 10,000 SWIFT files):
// the sanitizer tests feed 1,000 per HDF5 reader, the release tests 10,000.
constexpr std::size_t wanted_hdf5 = 1000;
#else
constexpr std::size_t wanted_hdf5 = wanted;
#endif

fs::path scratch_dir() {
  const fs::path shm = "/dev/shm";
  const fs::path base = fs::is_directory(shm) ? shm : fs::temp_directory_path();
  const fs::path d = base / ("sphv-fuzz-snap-" + std::to_string(getpid()));
  fs::create_directories(d);
  return d;
}

void write_bytes(const fs::path& f, const std::string& bytes) {
  std::ofstream out(f, std::ios::binary | std::ios::trunc);
  out << bytes;
}

// A valid 3D snapshot of n particles (time 0.1), with every column sphv knows.
Snapshot valid(std::size_t n) {
  Snapshot s;
  s.dim = 3;
  s.time = 0.1;
  for (const auto& name : snapshot_names()) {
    auto& c = s.columns[name];
    for (std::size_t i = 0; i < n; ++i) c.push_back(name == "m" || name == "rho" || name == "u" || name == "h" || name == "p"
                                                          ? 0.5 + 0.01 * double(i)
                                                          : 0.1 * double(i) - 0.05 * double(n));
    s.taken_from[name] = name;
  }
  return s;
}

// The scorers a read snapshot is handed to in turn (the settings each needs besides the file).
const std::vector<std::pair<std::string, std::vector<std::string>>> scorings = {
    {"sod", {}}, {"sedov", {}}, {"noh", {}}, {"heat", {}}, {"gravity", {}}, {"evrard", {"zones=20"}}};

struct Tally {
  std::size_t refused = 0, accepted = 0, scored = 0, library_failed = 0;
};

// Reads one file and, when it is accepted, hands it on. Returns true when refused; any exception
// other than an InputError propagates and fails the test.
bool try_file(const fs::path& file, const std::string& format, std::optional<long> step, bool in_child, Tally& tally) {
  Snapshot s;
  try {
    s = read_snapshot(file, format, step, in_child);
  } catch (const InputError& e) {
    const std::string msg = e.what();
    INFO("message: " << msg);
    REQUIRE(msg.find('\n') == std::string::npos);
    REQUIRE(msg.find(file.string()) != std::string::npos);
    ++tally.refused;
    tally.library_failed += msg.find("the HDF5 library failed") != std::string::npos;
    return true;
  }
  // The reader's promises.
  REQUIRE(s.size() > 0);
  REQUIRE(s.has("x"));
  REQUIRE((s.dim >= 1 && s.dim <= 3));
  for (const auto& [name, c] : s.columns) {
    REQUIRE(c.size() == s.size());
    for (double v : c) REQUIRE(std::isfinite(v));
  }
  // What it states of the set-up: a box of lo < hi per dimension, gamma > 1, periodic 0 or 1.
  if (s.stated.count("box")) {
    const auto& box = s.stated.at("box").value;
    REQUIRE(box.size() == 2 * std::size_t(s.dim));
    for (std::size_t d = 0; d < box.size(); d += 2) REQUIRE((std::isfinite(box[d]) && std::isfinite(box[d + 1]) && box[d] < box[d + 1]));
  }
  if (s.stated.count("gamma")) REQUIRE((s.stated.at("gamma").value.at(0) > 1.0 && std::isfinite(s.stated.at("gamma").value.at(0))));
  if (s.stated.count("periodic")) REQUIRE((s.stated.at("periodic").value.at(0) == 0.0 || s.stated.at("periodic").value.at(0) == 1.0));
  for (const auto& [name, r] : s.round_off) REQUIRE((r >= 0.0 && r < 1.0));
  ++tally.accepted;
  for (double eps : {0.0, 0.01}) try {
      gravity_particles(s, eps);
    } catch (const InputError&) {
    }
  // Every 16th accepted file is scored by the next case (scoring costs a reference solution).
  if (tally.accepted % 16 == 0 && s.size() <= 64) {
    const auto& [name, settings] = scorings[(tally.accepted / 16) % scorings.size()];
    try {
      const Result r = score_snapshot(find_case(name), settings, s);
      for (const auto& [k, v] : r.errors) {
        INFO(name << " error " << k);
        REQUIRE(std::isfinite(v));
      }
      ++tally.scored;
    } catch (const InputError&) {
    }
  }
  return false;
}

// Byte-level damage to a file's bytes: cut short, or 1 to 8 bytes overwritten.
std::string damaged(std::string bytes, fuzz::Inputs& gen) {
  if (gen.below(3) == 0) return bytes.substr(0, gen.below(bytes.size()));
  for (auto k = 1 + gen.below(8); k > 0; --k) bytes[gen.below(bytes.size())] = static_cast<char>(gen.below(256));
  return bytes;
}

// --- HDF5 files malformed in their structure ---------------------------------------------------

struct H5Writer {
  hid_t file;
  explicit H5Writer(const fs::path& p) {
    H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
    file = H5Fcreate(p.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT);
    REQUIRE(file >= 0);
  }
  ~H5Writer() { H5Fclose(file); }
};

// One of the awkward values a numeric field can hold.
double awkward(fuzz::Inputs& gen) {
  static const double values[] = {0.0, -1.0, 1.0, 2.0, 2.5, 3.0, 4.0, 1e300, -1e300, 1e19, -1e19, NAN, INFINITY,
                                  -INFINITY, 4.9e-324, 2147483648.0, -2147483649.0};
  return values[gen.below(std::size(values))];
}

// A dataset of `name` in loc: usually n x cols doubles (or n), sometimes another rank, length,
// element type, or non-finite values.
void dataset(hid_t loc, const std::string& name, std::size_t n, std::size_t cols, fuzz::Inputs& gen) {
  std::vector<hsize_t> dims = cols > 1 ? std::vector<hsize_t>{n, cols} : std::vector<hsize_t>{n};
  hid_t type = H5T_NATIVE_DOUBLE;
  const bool odd = gen.below(6) == 0;
  if (odd) switch (gen.below(7)) {
      case 0: dims = {}; break;                                 // a scalar
      case 1: dims.push_back(2); break;                         // one rank more
      case 2: dims[0] = gen.below(2 * n + 1); break;            // another length, 0 included
      case 3: if (dims.size() == 2) dims[1] = gen.below(6); break;  // 0 to 5 columns
      case 4: type = H5T_NATIVE_FLOAT; break;
      case 5: type = H5T_NATIVE_INT; break;
      default: type = H5T_C_S1; break;                          // one-byte strings
    }
  hsize_t total = 1;
  for (hsize_t d : dims) total *= d;
  const hid_t space = dims.empty() ? H5Screate(H5S_SCALAR) : H5Screate_simple(int(dims.size()), dims.data(), nullptr);
  const hid_t ds = H5Dcreate2(loc, name.c_str(), type, space, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
  std::vector<double> v(total);
  for (hsize_t i = 0; i < total; ++i) v[i] = 0.5 + 0.01 * double(i);
  if (gen.below(8) == 0 && total > 0) v[gen.below(total)] = awkward(gen);
  if (type == H5T_C_S1) {
    std::vector<char> text(total, '7');
    H5Dwrite(ds, type, H5S_ALL, H5S_ALL, H5P_DEFAULT, text.data());
  } else if (total > 0) {
    H5Dwrite(ds, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, v.data());
  }
  H5Dclose(ds);
  H5Sclose(space);
}

// An attribute `name` of obj: one double, sometimes awkward, several values, none, or a string.
void attribute(hid_t obj, const std::string& name, double value, fuzz::Inputs& gen) {
  hsize_t n = 1;
  hid_t type = H5T_NATIVE_DOUBLE;
  if (gen.below(4) == 0) switch (gen.below(4)) {
      case 0: value = awkward(gen); break;
      case 1: n = gen.below(4); break;  // 0 to 3 values
      case 2: type = H5T_NATIVE_INT; value = awkward(gen); break;
      default: type = H5T_C_S1; break;
    }
  const hid_t space = H5Screate_simple(1, &n, nullptr);
  const hid_t a = H5Acreate2(obj, name.c_str(), type, space, H5P_DEFAULT, H5P_DEFAULT);
  if (type == H5T_C_S1) {
    std::vector<char> text(n, 'a');
    H5Awrite(a, type, text.data());
  } else if (n > 0) {
    std::vector<double> v(n, value);
    H5Awrite(a, H5T_NATIVE_DOUBLE, v.data());  // out-of-range values for int: HDF5 clips them
  }
  H5Aclose(a);
  H5Sclose(space);
}

// A SWIFT/GADGET file with its parts present, absent, misnamed or malformed at random.
void swift_file(const fs::path& p, fuzz::Inputs& gen) {
  H5Writer w(p);
  const std::size_t n = 1 + gen.below(40);
  const std::size_t dim = 1 + gen.below(3);
  if (gen.below(6)) {
    const hid_t header = H5Gcreate2(w.file, "Header", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
    if (gen.below(6)) attribute(header, "Time", 0.1, gen);
    if (gen.below(3)) attribute(header, "Dimension", double(dim), gen);
    if (gen.below(2)) attribute(header, "BoxSize", 1.0, gen);
    H5Gclose(header);
  }
  if (gen.below(2)) {  // SWIFT's scheme: the adiabatic index and the kernel's support / h
    const hid_t scheme = H5Gcreate2(w.file, "HydroScheme", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
    if (gen.below(4)) attribute(scheme, "Adiabatic index", 5.0 / 3.0, gen);
    if (gen.below(4)) attribute(scheme, "Kernel gamma", 1.825742, gen);
    H5Gclose(scheme);
  }
  if (gen.below(3) == 0) {  // SWIFT's run-time parameters: strings
    const hid_t params = H5Gcreate2(w.file, "Parameters", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
    static const char* texts[] = {"1", "0", "", "yes", "11"};
    const std::string text = texts[gen.below(std::size(texts))];
    if (gen.below(4)) {
      const hid_t type = H5Tcopy(H5T_C_S1);
      H5Tset_size(type, std::max<std::size_t>(1, text.size()));
      const hid_t space = H5Screate(H5S_SCALAR);
      const hid_t a = H5Acreate2(params, "InitialConditions:periodic", type, space, H5P_DEFAULT, H5P_DEFAULT);
      H5Awrite(a, type, text.empty() ? "\0" : text.c_str());
      H5Aclose(a), H5Sclose(space), H5Tclose(type);
    } else {
      attribute(params, "InitialConditions:periodic", 1.0, gen);  // a number where SWIFT writes text
    }
    H5Gclose(params);
  }
  if (gen.below(12) == 0) {  // PartType0 a dataset, not a group
    dataset(w.file, "PartType0", n, 1, gen);
    return;
  }
  const hid_t gas = H5Gcreate2(w.file, gen.below(20) ? "PartType0" : "PartType1", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
  const std::size_t cols = gen.below(2) ? 3 : dim;
  auto pick = [&](std::initializer_list<const char*> names) { return std::string(names.begin()[gen.below(names.size())]); };
  if (gen.below(10)) dataset(gas, "Coordinates", n, cols, gen);
  if (gen.below(3)) dataset(gas, pick({"Velocities", "Velocity"}), n, cols, gen);
  if (gen.below(5)) dataset(gas, pick({"Masses", "Mass"}), n, 1, gen);
  if (gen.below(3)) dataset(gas, pick({"Densities", "Density"}), n, 1, gen);
  if (gen.below(3)) dataset(gas, pick({"InternalEnergies", "InternalEnergy"}), n, 1, gen);
  if (gen.below(3)) dataset(gas, pick({"SmoothingLengths", "SmoothingLength"}), n, 1, gen);
  if (gen.below(3)) dataset(gas, pick({"Pressures", "Pressure"}), n, 1, gen);
  if (gen.below(4) == 0) dataset(gas, pick({"Accelerations", "Potentials"}), n, gen.below(2) ? 3 : 1, gen);
  H5Gclose(gas);
}

// An H5Part file: steps with awkward names, fields present, absent or malformed at random.
void h5part_file(const fs::path& p, fuzz::Inputs& gen) {
  H5Writer w(p);
  const std::size_t n = 1 + gen.below(40);
  const std::size_t dim = 1 + gen.below(3);
  if (gen.below(2)) attribute(w.file, "dim", double(dim), gen);
  static const char* step_names[] = {"Step#0", "Step#1", "Step#7", "Step#-1", "Step#", "Step#1x", "Step#99999999999999999999",
                                     "Step#0001", "step#0", "Step# 2"};
  const auto steps = gen.below(4);  // 0 to 3 steps
  for (std::size_t k = 0; k < steps; ++k) {
    const char* name = step_names[gen.below(std::size(step_names))];
    if (H5Lexists(w.file, name, H5P_DEFAULT) > 0) continue;
    if (gen.below(12) == 0) {  // a dataset where a step group should be
      dataset(w.file, name, n, 1, gen);
      continue;
    }
    const hid_t g = H5Gcreate2(w.file, name, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
    if (gen.below(6)) attribute(g, "time", 0.1, gen);
    // SPH-EXA's set-up attributes: gamma (here or at the root), the box, the boundary types.
    if (gen.below(3)) attribute(gen.below(2) ? g : w.file, "gamma", 5.0 / 3.0, gen);
    if (gen.below(3)) {
      std::vector<double> box = {-0.5, 0.5, -0.5, 0.5, -0.5, 0.5};
      box.resize(gen.below(8));
      if (!box.empty() && gen.below(4) == 0) box[gen.below(box.size())] = awkward(gen);
      const hsize_t nb = box.size();
      const hid_t space = H5Screate_simple(1, &nb, nullptr);
      const hid_t a = H5Acreate2(g, "box", H5T_NATIVE_DOUBLE, space, H5P_DEFAULT, H5P_DEFAULT);
      if (nb > 0) H5Awrite(a, H5T_NATIVE_DOUBLE, box.data());
      H5Aclose(a), H5Sclose(space);
    }
    if (gen.below(3)) attribute(g, "boundaryType", double(gen.below(4)), gen);
    for (const char* field : {"x", "y", "z", "vx", "vy", "vz", "m", "rho", "u", "p", "h"}) {
      const bool coordinate = field[1] == '\0' && field[0] >= 'x';
      if (coordinate && std::size_t(field[0] - 'x') >= dim && gen.below(4)) continue;
      if (gen.below(coordinate ? 12 : 3)) dataset(g, field, n, gen.below(30) ? 1 : 2, gen);
    }
    H5Gclose(g);
  }
}

// How one generated file is read: as which format, which H5Part step, and whether in a child
// process (damaged HDF5 bytes, which can crash the HDF5 library itself).
struct Reading {
  std::string format;
  std::optional<long> step;
  bool in_child = false;
};

// Runs `wanted` refused files (or a cap of tries) of one kind through the readers.
template <class Make>
void fuzz_reader(const std::string& format, std::uint64_t offset, Make make) {
  const fs::path dir = scratch_dir();
  const fs::path file = dir / ("snapshot." + std::string(format == "csv" ? "csv" : "h5"));
  fuzz::Inputs gen(fuzz::seed + offset);
  Tally tally;
  std::size_t index = 0, in_child = 0;
  const std::size_t target = format == "csv" ? wanted : wanted_hdf5;
  for (; tally.refused < target && index < 5 * target; ++index) {
    INFO(format << " fuzz, seed " << fuzz::seed + offset << ", input " << index << " (file " << file << ")");
    const Reading r = make(file, gen);
    in_child += r.in_child;
    try_file(file, r.format, r.step, r.in_child, tally);
  }
  WARN(format << " fuzz: " << tally.refused << " malformed files refused, " << tally.accepted << " accepted (" << tally.scored
              << " of them scored) in " << index << " files; " << in_child << " with damaged bytes read in a child process, "
              << "where the HDF5 library itself failed on " << tally.library_failed);
  CHECK(tally.refused >= target);
  fs::remove_all(dir);
}

// One HDF5 file in 256 has damaged bytes and is read in a child process like every snapshot a user
// gives (a fork costs 1-10 ms on a loaded machine, about a second for a sanitized process: the
// sanitizer tests read structural faults only); the others are malformed in structure.
template <class Structure>
Reading hdf5_input(const fs::path& f, fuzz::Inputs& gen, const std::string& good, const std::string& format, Structure structure) {
  Reading r;
#ifndef SPHV_SANITIZED
  r.in_child = gen.below(256) == 0;
#endif
  if (r.in_child) write_bytes(f, damaged(good, gen));
  else structure(f, gen);
  r.format = gen.below(2) ? format : "auto";
  return r;
}

}  // namespace

TEST_CASE("fuzz: 10,000+ malformed CSV snapshots are refused or read soundly", "[fuzz][snapshot]") {
  write_csv_snapshot(valid(12), scratch_dir() / "valid.csv");
  // With the comments that state the set-up, for the mutations to reach their parsing too.
  const std::string text = "# gamma = 1.4\n# box = -1,1,-1,1,-1,1\n# periodic = yes\n" + fuzz::slurp(scratch_dir() / "valid.csv");
  fuzz_reader("csv", 10, [&](const fs::path& f, fuzz::Inputs& gen) {
    write_bytes(f, gen.mutate(text));
    return Reading{gen.below(2) ? "csv" : "auto", std::nullopt};
  });
}

TEST_CASE("fuzz: 10,000+ malformed SWIFT/GADGET HDF5 snapshots are refused or read soundly", "[fuzz][snapshot]") {
  write_swift_snapshot(valid(12), scratch_dir() / "valid.h5");
  const std::string good = fuzz::slurp(scratch_dir() / "valid.h5");
  fuzz_reader("swift", 11, [&](const fs::path& f, fuzz::Inputs& gen) { return hdf5_input(f, gen, good, "swift", swift_file); });
}

TEST_CASE("fuzz: 10,000+ malformed H5Part snapshots are refused or read soundly", "[fuzz][snapshot]") {
  write_h5part_snapshot(valid(12), scratch_dir() / "valid.h5part");
  const std::string good = fuzz::slurp(scratch_dir() / "valid.h5part");
  fuzz_reader("h5part", 12, [&](const fs::path& f, fuzz::Inputs& gen) {
    Reading r = hdf5_input(f, gen, good, "h5part", h5part_file);
    if (gen.below(3) == 0) r.step = long(gen.below(4)) - 1;
    return r;
  });
}
