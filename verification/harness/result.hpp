#pragma once
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace sphv {

// Named columns of equal length, written as CSV with a header row (particles.csv).
struct Table {
  std::vector<std::string> names;
  std::vector<std::vector<double>> columns;
  void add(std::string name, std::vector<double> column) {
    names.push_back(std::move(name));
    columns.push_back(std::move(column));
  }
  bool empty() const { return names.empty(); }
};

// A figure the report draws from a run (profiles, error against a parameter, ...):
// series of points or lines on shared axes. The report script knows nothing case-specific.
struct Series {
  std::string label;
  std::vector<double> x, y;
  std::string style = "line";  // "line", "points" or "dashed"
};
struct Figure {
  std::string name, title, xlabel, ylabel;
  std::string xscale = "linear", yscale = "linear";
  std::vector<Series> series;
};

// What one run of a case produced; serialised as result.json.
struct Result {
  std::string case_name;
  nlohmann::json params = nlohmann::json::object();
  std::size_t n_particles = 0;
  double wall_time_s = 0.0;
  std::map<std::string, double> errors;       // against the independent reference
  std::map<std::string, double> functionals;  // converging outputs (for Roache's GCI)
  std::string verdict = "ok";                 // "ok", or what went bad, where and when
  std::vector<Figure> figures;
  nlohmann::json extra = nlohmann::json::object();  // case-specific detail
  Table particles;                                  // empty when the case has none
  // Where, when and with how many threads the point ran: taken when it ends (run_case) or is
  // first written, and kept when the result is read back, so a sweep written later (by the
  // parent of the point's process, on other threads) reports the point's own.
  nlohmann::json provenance;
};

nlohmann::json provenance();
nlohmann::json to_json(const Figure& f);
// No result file holds NaN or infinity. name_non_finite (run_case calls it) removes every
// non-finite error or functional, nulls non-finite numbers in extra, drops a particle table
// holding one, and names each in the verdict ("non-finite errors.L1_rho=nan ..."), appended to
// a verdict that was not "ok". to_json of a result that still holds one throws (a figure's
// non-finite points are written as null: gaps in a line).
void name_non_finite(Result& r);
nlohmann::json to_json(const Result& r);
// Reads a result back (resumed sweeps, subprocess and MPI points); particles are not read.
Result result_from_json(const nlohmann::json& j);

// Writes text to path through a temporary file and a rename: a reader never sees half a file
// and an earlier file survives a failed write.
void write_atomically(const std::filesystem::path& path, const std::string& text);
void write_result(const Result& r, const std::filesystem::path& dir);
std::string csv(const Table& t);
// The first non-finite entry of each column that has one, as "name[row]=value" (no output file
// holds a non-finite number: what writes a table checks it first).
std::vector<std::string> non_finite_entries(const Table& t);

}  // namespace sphv
