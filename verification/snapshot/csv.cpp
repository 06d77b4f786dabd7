// CSV snapshots: a header row of column names (any spelling canonical_column knows; others are
// ignored), comma- or whitespace-separated, comment lines beginning with '#'; a comment
// "# time = T" (or "t: T") gives the time.
#include <cctype>
#include <cmath>
#include <fstream>
#include <string_view>

#include "verification/params.hpp"
#include "verification/result.hpp"
#include "verification/snapshot/snapshot.hpp"

namespace sphv {
namespace {

// Splits on commas (trimming blanks) or, without commas in the header, on runs of blanks.
void split(std::string_view line, bool comma, std::vector<std::string_view>& f) {
  f.clear();
  auto blank = [](char c) { return c == ' ' || c == '\t' || c == '\r'; };
  if (comma) {
    std::size_t from = 0;
    while (true) {
      const std::size_t to = std::min(line.find(',', from), line.size());
      std::size_t a = from, b = to;
      while (a < b && blank(line[a])) ++a;
      while (b > a && blank(line[b - 1])) --b;
      f.push_back(line.substr(a, b - a));
      if (to == line.size()) break;
      from = to + 1;
    }
    return;
  }
  std::size_t k = 0;
  while (k < line.size()) {
    while (k < line.size() && blank(line[k])) ++k;
    const std::size_t a = k;
    while (k < line.size() && !blank(line[k])) ++k;
    if (k > a) f.push_back(line.substr(a, k - a));
  }
}

bool parse_field(std::string_view t, double& v) {  // a number, '+' allowed in front
  if (!t.empty() && t.front() == '+') t.remove_prefix(1);
  return parse_number(t, v);
}

// "# time = 0.25", "# t: 0.25", "#time 0.25": the time, else nothing.
std::optional<double> comment_time(std::string_view c) {
  std::size_t k = 1;
  while (k < c.size() && std::isspace(static_cast<unsigned char>(c[k]))) ++k;
  std::size_t e = k;
  while (e < c.size() && std::isalpha(static_cast<unsigned char>(c[e]))) ++e;
  std::string key(c.substr(k, e - k));
  for (auto& ch : key) ch = std::tolower(static_cast<unsigned char>(ch));
  if (key != "time" && key != "t") return std::nullopt;
  while (e < c.size() && (std::isspace(static_cast<unsigned char>(c[e])) || c[e] == '=' || c[e] == ':')) ++e;
  std::size_t end = c.size();
  while (end > e && std::isspace(static_cast<unsigned char>(c[end - 1]))) --end;
  double v;
  if (!parse_field(c.substr(e, end - e), v)) return std::nullopt;
  return v;
}

}  // namespace

Snapshot read_csv_snapshot(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError("cannot read snapshot " + path.string());
  std::string text(std::filesystem::file_size(path), '\0');
  in.read(text.data(), text.size());
  if (in.gcount() != static_cast<std::streamsize>(text.size())) throw InputError("cannot read snapshot " + path.string());
  const std::string f = path.string();
  if (text.find('\0') != std::string::npos)
    throw InputError(f + ": binary data, not a CSV file (an HDF5 file? it lacks the HDF5 signature)");

  Snapshot s;
  s.path = path;
  s.format = "csv";
  std::vector<std::string> names;                // per header field: sphv name, or "" (ignored)
  std::vector<std::vector<double>*> cols;        // per header field: its column, or null
  bool comma = false;
  std::vector<std::string_view> fields;
  std::size_t pos = 0;
  for (long row = 1; pos < text.size(); ++row) {
    const std::size_t eol = std::min(text.find('\n', pos), text.size());
    const std::string_view line(text.data() + pos, eol - pos);
    pos = eol + 1;
    const std::size_t first = line.find_first_not_of(" \t\r");
    if (first == std::string_view::npos) continue;
    if (line[first] == '#') {
      if (auto t = comment_time(line.substr(first))) s.time = t;
      continue;
    }
    auto where = [&] { return f + ":" + std::to_string(row); };
    if (names.empty()) {
      comma = line.find(',') != std::string_view::npos;
      split(line, comma, fields);
      double v;
      if (parse_field(fields[0], v))
        throw InputError(where() + ": no header row (the first row holds numbers; expected names like x,y,z,m,rho)");
      for (const auto& name : fields) {
        std::string c = canonical_column(std::string(name));
        if (s.has(c)) c.clear();  // a second spelling of a column already taken
        if (!c.empty()) s.taken_from[c] = std::string(name), s.columns[c];
        names.push_back(c);
      }
      for (const auto& c : names) cols.push_back(c.empty() ? nullptr : &s.columns[c]);
      continue;
    }
    split(line, comma, fields);
    if (fields.size() != names.size())
      throw InputError(where() + ": " + std::to_string(fields.size()) + " fields, the header has " +
                       std::to_string(names.size()));
    for (std::size_t k = 0; k < fields.size(); ++k) {
      if (!cols[k]) continue;
      double v;
      if (!parse_field(fields[k], v) || !std::isfinite(v))
        throw InputError(where() + ": " + (fields[k].empty() ? std::string("an empty field") : "'" + std::string(fields[k]) + "'") +
                         " in column " + s.taken_from.at(names[k]) + " is not a finite number");
      cols[k]->push_back(v);
    }
  }
  if (names.empty()) throw InputError(f + ": empty (no header row)");
  if (s.has("z") && !s.has("y")) throw InputError(f + ": has a z column but no y");
  s.dim = s.has("z") ? 3 : s.has("y") ? 2 : 1;
  return s;
}

void write_csv_snapshot(const Snapshot& s, const std::filesystem::path& path) {
  std::string out;
  if (s.time) out += "# time = " + shortest(*s.time) + "\n";
  std::vector<const std::vector<double>*> cols;
  for (const auto& name : snapshot_names())
    if (s.has(name)) {
      out += (cols.empty() ? "" : ",") + name;
      cols.push_back(&s.columns.at(name));
    }
  out += '\n';
  char buf[32];
  for (std::size_t i = 0; i < s.size(); ++i) {
    for (std::size_t c = 0; c < cols.size(); ++c) {
      if (c) out += ',';
      const auto r = std::to_chars(buf, buf + sizeof buf, (*cols[c])[i]);  // shortest exact form
      out.append(buf, r.ptr);
    }
    out += '\n';
  }
  write_atomically(path, out);
}

}  // namespace sphv
