#pragma once
// A particle snapshot written by any SPH code, reduced to named columns (sphv's names: x y z
// vx vy vz m rho u p h ax ay az phi), the time and the number of coordinates. Readers: CSV
// (csv.cpp), HDF5 in the SWIFT/GADGET layout (swift.cpp) and in SPH-EXA's H5Part layout
// (h5part.cpp). Every reader refuses a bad file with an InputError naming the file.
#include <cstdint>
#include <filesystem>
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace sphv {

// A value the file states about the set-up besides its columns, and where it says it.
struct Stated {
  std::vector<double> value;
  std::string from;       // "/HydroScheme Adiabatic index", "# gamma comment", ...
  double round_off = 0.0;  // relative round-off of the value as stored (float32: 2^-24)
};

struct Snapshot {
  std::filesystem::path path;
  std::string format;                 // csv | swift | h5part
  int dim = 0;                        // coordinates present: 1 (x), 2 (x, y) or 3
  std::optional<double> time;         // from the file's header, when it has one
  std::map<std::string, std::vector<double>> columns;  // sphv's names
  std::map<std::string, std::string> taken_from;        // sphv name -> the file's name for it
  std::string time_from;                                // where the time was read ("" = none)
  // What the file states: "gamma" (the adiabatic index), "box" (x_lo, x_hi[, y_lo, y_hi[, z_lo,
  // z_hi]], one pair per dimension), "periodic" (1 or 0).
  std::map<std::string, Stated> stated;
  // Relative round-off of each column as stored: 2^-53 for doubles, 2^-24 for float32; in a CSV
  // file half a unit in the last digit of its longest number.
  std::map<std::string, double> round_off;

  std::size_t size() const { return columns.empty() ? 0 : columns.begin()->second.size(); }
  bool has(const std::string& name) const { return columns.count(name) > 0; }
  // The column, or an InputError naming the file and the column (and what needs it).
  const std::vector<double>& at(const std::string& name, const std::string& needed_by) const;
  // "x <- Coordinates[:,0], rho <- Densities, ..." for the log and result.json.
  std::string describe() const;
};

// sphv's column names in the order files are written.
const std::vector<std::string>& snapshot_names();
// The sphv name of a column name written by some code (case and spelling insensitive:
// "Density", "densities", "internal_energy", "vel_x", ...), or "" if it is not one.
std::string canonical_column(const std::string& file_name);

// Reads a snapshot; format auto|csv|swift|h5part (auto: HDF5 files by their signature and
// layout, anything else as CSV); step: the H5Part step (default: the last). Checks that the file
// has particles, equal-length finite columns and at least the coordinate x.
// HDF5 files are parsed in a child process (read_hdf5_isolated) unless hdf5_in_child is false
// (tests that feed thousands of generated files, where a fork costs more than the read).
Snapshot read_snapshot(const std::filesystem::path& path, const std::string& format = "auto",
                       std::optional<long> step = std::nullopt, bool hdf5_in_child = true);
// Writes the snapshot's columns (and its time; CSV also what the file stated) in the format, atomically.
void write_snapshot(const Snapshot& s, const std::filesystem::path& path, const std::string& format);

// Path, size in bytes and SHA-256 of a file, for provenance.
nlohmann::json file_provenance(const std::filesystem::path& path);

// Runs read (an HDF5 reader) in a child process: a file that crashes the HDF5 library becomes an
// InputError naming it (isolated.cpp).
Snapshot read_hdf5_isolated(const std::filesystem::path& path, const std::function<Snapshot()>& read);

// The readers and writers of each format (called through the two functions above).
Snapshot read_csv_snapshot(const std::filesystem::path& path);
Snapshot read_swift_snapshot(const std::filesystem::path& path);
Snapshot read_h5part_snapshot(const std::filesystem::path& path, std::optional<long> step);
void write_csv_snapshot(const Snapshot& s, const std::filesystem::path& path);
void write_swift_snapshot(const Snapshot& s, const std::filesystem::path& path);
void write_h5part_snapshot(const Snapshot& s, const std::filesystem::path& path);

}  // namespace sphv
