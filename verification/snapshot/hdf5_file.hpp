#pragma once
// The few HDF5 C library calls the snapshot readers and writers share: handles closed on scope
// exit, whole datasets and attributes as doubles (HDF5 converts float32 and integers), and files
// written through a temporary name and a rename.
#include <hdf5.h>

#include <cmath>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "verification/harness/params.hpp"

namespace sphv::h5 {

// An HDF5 identifier closed by its own close function.
class Handle {
 public:
  Handle(hid_t id, herr_t (*close)(hid_t)) : id_(id), close_(close) {}
  Handle(const Handle&) = delete;
  Handle& operator=(const Handle&) = delete;
  ~Handle() {
    if (id_ >= 0) close_(id_);
  }
  operator hid_t() const { return id_; }
  bool ok() const { return id_ >= 0; }

 private:
  hid_t id_;
  herr_t (*close_)(hid_t);
};

// Opens a file for reading; HDF5's own error stack printing is switched off (errors become one
// InputError line naming the file).
inline hid_t open_read(const std::filesystem::path& path) {
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
  const hid_t f = H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  if (f < 0) throw InputError(path.string() + ": not a readable HDF5 file (truncated or damaged?)");
  return f;
}

inline bool exists(hid_t loc, const std::string& name) { return H5Lexists(loc, name.c_str(), H5P_DEFAULT) > 0; }

// Refuses an element type other than a plain integer or IEEE-like float (sizes 1-8 bytes, bit
// fields inside the element). HDF5 1.10's conversion to double trusts the type's bit fields: a
// damaged file declaring a 32-bit integer with 38176 bits of precision smashed its stack (found
// by the snapshot fuzz test).
inline void check_numeric_type(hid_t type, const std::string& what, const std::string& file) {
  const H5T_class_t cls = H5Tget_class(type);
  const std::size_t size = H5Tget_size(type), bits = 8 * size;
  const int precision = static_cast<int>(H5Tget_precision(type)), offset = H5Tget_offset(type);
  bool ok = (cls == H5T_INTEGER || cls == H5T_FLOAT) && size >= 1 && size <= 8 && precision > 0 && offset >= 0 &&
            static_cast<std::size_t>(offset + precision) <= bits;
  if (ok && cls == H5T_FLOAT) {
    size_t spos = 0, epos = 0, esize = 0, mpos = 0, msize = 0;
    ok = H5Tget_fields(type, &spos, &epos, &esize, &mpos, &msize) >= 0 && esize >= 2 && esize <= 15 && msize <= 64 &&
         spos < bits && epos + esize <= bits && mpos + msize <= bits;
  }
  if (!ok) throw InputError(file + ": " + what + " is not stored as plain integers or floating-point numbers");
}

// The relative round-off of a value stored as type (checked numeric): half a unit in the last
// place of a float's mantissa (2^-24 for float32, 2^-53 for float64); integers are exact.
inline double round_off_of(hid_t type) {
  if (H5Tget_class(type) != H5T_FLOAT) return 0.0;
  size_t spos = 0, epos = 0, esize = 0, mpos = 0, msize = 0;
  H5Tget_fields(type, &spos, &epos, &esize, &mpos, &msize);
  return std::ldexp(1.0, -static_cast<int>(msize) - 1);
}

// A whole dataset as doubles, with its dimensions (and the round-off of its stored type).
inline std::vector<double> read_dataset(hid_t loc, const std::string& name, const std::string& file,
                                        std::vector<hsize_t>& dims, double* round_off = nullptr) {
  const Handle ds(H5Dopen2(loc, name.c_str(), H5P_DEFAULT), H5Dclose);
  if (!ds.ok()) throw InputError(file + ": cannot open dataset " + name);
  const Handle type(H5Dget_type(ds), H5Tclose);
  check_numeric_type(type, "dataset " + name, file);
  if (round_off) *round_off = round_off_of(type);
  const Handle space(H5Dget_space(ds), H5Sclose);
  const int rank = H5Sget_simple_extent_ndims(space);
  if (rank < 1 || rank > 2) throw InputError(file + ": dataset " + name + " has rank " + std::to_string(rank) + " (expected 1 or 2)");
  dims.assign(rank, 0);
  H5Sget_simple_extent_dims(space, dims.data(), nullptr);
  // A damaged header can declare any size: refuse more values than a snapshot this tool reads
  // holds (1e9 doubles, 8 GB) before allocating.
  constexpr hsize_t max_values = 1'000'000'000;
  hsize_t total = 1;
  for (hsize_t d : dims) total = d == 0 ? 0 : total > max_values / d ? max_values + 1 : total * d;
  if (total > max_values) throw InputError(file + ": dataset " + name + " declares more than 1e9 values");
  // Stored contiguously (not chunked and compressed), its bytes in the file are its values.
  const Handle plist(H5Dget_create_plist(ds), H5Pclose);
  const H5D_layout_t layout = H5Pget_layout(plist);
  if ((layout == H5D_CONTIGUOUS || layout == H5D_COMPACT) && total > 0 &&
      H5Dget_storage_size(ds) != total * H5Tget_size(type))
    throw InputError(file + ": dataset " + name + " declares " + std::to_string(total) + " values but stores " +
                     std::to_string(H5Dget_storage_size(ds)) + " bytes (damaged file?)");
  std::vector<double> v(total);
  if (total > 0 && H5Dread(ds, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, v.data()) < 0)
    throw InputError(file + ": cannot read dataset " + name + " (truncated file or a non-numeric type)");
  return v;
}

// A numeric attribute's values (and the round-off of its stored type), or nothing when it is absent.
inline std::optional<std::vector<double>> read_attribute(hid_t obj, const std::string& name, const std::string& file,
                                                         double* round_off = nullptr) {
  if (H5Aexists(obj, name.c_str()) <= 0) return std::nullopt;
  const Handle a(H5Aopen(obj, name.c_str(), H5P_DEFAULT), H5Aclose);
  if (!a.ok()) throw InputError(file + ": cannot read attribute " + name);
  const Handle type(H5Aget_type(a), H5Tclose);
  check_numeric_type(type, "attribute " + name, file);
  if (round_off) *round_off = round_off_of(type);
  const Handle space(H5Aget_space(a), H5Sclose);
  const hssize_t n = H5Sget_simple_extent_npoints(space);
  std::vector<double> v(n > 0 ? n : 0);
  if (!a.ok() || n <= 0 || H5Aread(a, H5T_NATIVE_DOUBLE, v.data()) < 0)
    throw InputError(file + ": cannot read attribute " + name + " as numbers");
  return v;
}

// A fixed-length string attribute's text (SWIFT's run-time parameters are such strings), or
// nothing when it is absent or not a fixed-length string.
inline std::optional<std::string> read_text_attribute(hid_t obj, const std::string& name) {
  if (H5Aexists(obj, name.c_str()) <= 0) return std::nullopt;
  const Handle a(H5Aopen(obj, name.c_str(), H5P_DEFAULT), H5Aclose);
  if (!a.ok()) return std::nullopt;
  const Handle type(H5Aget_type(a), H5Tclose);
  const Handle space(H5Aget_space(a), H5Sclose);
  const std::size_t size = H5Tget_size(type);
  if (H5Tget_class(type) != H5T_STRING || H5Tis_variable_str(type) != 0 || size == 0 || size > 4096 ||
      H5Sget_simple_extent_npoints(space) != 1)
    return std::nullopt;
  std::string text(size, '\0');
  if (H5Aread(a, type, text.data()) < 0) return std::nullopt;
  return text.substr(0, text.find('\0'));
}

// A numeric attribute that must hold a whole number in [lo, hi], or nothing when it is absent.
inline std::optional<int> read_int_attribute(hid_t obj, const std::string& name, const std::string& file, int lo, int hi) {
  const auto v = read_attribute(obj, name, file);
  if (!v) return std::nullopt;
  const double d = v->at(0);
  if (!(d >= lo && d <= hi) || d != static_cast<double>(static_cast<int>(d)))
    throw InputError(file + ": attribute " + name + " is " + std::to_string(d) + " (expected a whole number from " +
                     std::to_string(lo) + " to " + std::to_string(hi) + ")");
  return static_cast<int>(d);
}

// Writing: a new file at a temporary name, renamed by `commit` once complete.
class Writer {
 public:
  explicit Writer(std::filesystem::path path) : path_(std::move(path)), tmp_(path_.string() + ".tmp.h5") {
    if (!path_.parent_path().empty()) std::filesystem::create_directories(path_.parent_path());
    H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
    file_ = H5Fcreate(tmp_.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT);
    if (file_ < 0) throw std::runtime_error("cannot write " + tmp_);
  }
  ~Writer() {  // an unfinished file (an error on the way) is removed
    for (hid_t g : groups_) H5Gclose(g);
    if (file_ >= 0) H5Fclose(file_), std::filesystem::remove(tmp_);
  }
  hid_t file() const { return file_; }
  hid_t group(const std::string& name) {
    groups_.push_back(H5Gcreate2(file_, name.c_str(), H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT));
    if (groups_.back() < 0) throw std::runtime_error("cannot write group " + name + " in " + tmp_);
    return groups_.back();
  }
  // The values are converted to the file's type (integers such as particle IDs are exact below 2^53).
  void dataset(hid_t loc, const std::string& name, const std::vector<double>& v, std::vector<hsize_t> dims,
               hid_t type = H5T_IEEE_F64LE) {
    const Handle space(H5Screate_simple(static_cast<int>(dims.size()), dims.data(), nullptr), H5Sclose);
    const Handle ds(H5Dcreate2(loc, name.c_str(), type, space, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), H5Dclose);
    if (!ds.ok() || H5Dwrite(ds, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, v.data()) < 0)
      throw std::runtime_error("cannot write dataset " + name + " in " + tmp_);
  }
  void attribute(hid_t loc, const std::string& name, const std::vector<double>& v, hid_t type = H5T_IEEE_F64LE) {
    const hsize_t n = v.size();
    const Handle space(H5Screate_simple(1, &n, nullptr), H5Sclose);
    const Handle a(H5Acreate2(loc, name.c_str(), type, space, H5P_DEFAULT, H5P_DEFAULT), H5Aclose);
    if (!a.ok() || H5Awrite(a, H5T_NATIVE_DOUBLE, v.data()) < 0)
      throw std::runtime_error("cannot write attribute " + name + " in " + tmp_);
  }
  void commit() {
    for (hid_t g : groups_) H5Gclose(g);
    groups_.clear();
    const herr_t e = H5Fclose(file_);
    file_ = -1;
    if (e < 0) throw std::runtime_error("cannot write " + tmp_);
    std::filesystem::rename(tmp_, path_);
  }

 private:
  std::filesystem::path path_;
  std::string tmp_;
  hid_t file_ = -1;
  std::vector<hid_t> groups_;
};

}  // namespace sphv::h5
