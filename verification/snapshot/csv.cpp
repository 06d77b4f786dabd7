// CSV snapshots: a header row of column names (any spelling canonical_column knows; others are
// ignored), comma- or whitespace-separated, comment lines beginning with '#'. Comments of the
// form "# key = value" (or "key: value") state the set-up: time (or t), gamma, box (x_lo, x_hi[,
// y_lo, y_hi[, z_lo, z_hi]]) and periodic (yes/no, 1/0).
#include <algorithm>
#include <cctype>
#include <cmath>
#include <fstream>
#include <optional>
#include <string_view>

#include "verification/harness/params.hpp"
#include "verification/harness/result.hpp"
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

// "# gamma = 1.4", "# t: 0.25", "#box 0,2": the key (lower case) and its value's text, else nothing.
std::optional<std::pair<std::string, std::string_view>> comment_setting(std::string_view c) {
  std::size_t k = 1;
  while (k < c.size() && std::isspace(static_cast<unsigned char>(c[k]))) ++k;
  std::size_t e = k;
  while (e < c.size() && std::isalpha(static_cast<unsigned char>(c[e]))) ++e;
  std::string key(c.substr(k, e - k));
  for (auto& ch : key) ch = std::tolower(static_cast<unsigned char>(ch));
  if (key != "time" && key != "t" && key != "gamma" && key != "box" && key != "periodic") return std::nullopt;
  while (e < c.size() && (std::isspace(static_cast<unsigned char>(c[e])) || c[e] == '=' || c[e] == ':')) ++e;
  std::size_t end = c.size();
  while (end > e && std::isspace(static_cast<unsigned char>(c[end - 1]))) --end;
  if (e == end) return std::nullopt;
  return std::pair{key == "t" ? std::string("time") : key, c.substr(e, end - e)};
}

// Numbers separated by commas or blanks, or nothing when any is not a finite number.
std::optional<std::vector<double>> numbers(std::string_view text) {
  std::vector<std::string_view> f;
  split(text, text.find(',') != std::string_view::npos, f);
  std::vector<double> v;
  for (auto t : f) {
    double x;
    if (!parse_field(t, x) || !std::isfinite(x)) return std::nullopt;
    v.push_back(x);
  }
  return v;
}

// The relative round-off of a number printed with this text: half a unit in its last
// significant digit (at least a double's 2^-53); 0 for a zero, which tells nothing.
double printed_round_off(std::string_view t) {
  int digits = 0;
  bool leading = true;
  for (char ch : t) {
    if (ch == 'e' || ch == 'E') break;
    if (ch < '0' || ch > '9') continue;
    if (leading && ch == '0') continue;
    leading = false;
    ++digits;
  }
  return digits == 0 ? 0.0 : std::max(0.5 * std::pow(10.0, 1 - digits), std::ldexp(1.0, -53));
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
  double round_off = 0.0;                        // of the file's longest number (0: none seen)
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
      const auto setting = comment_setting(line.substr(first));
      if (!setting) continue;
      const auto& [key, text] = *setting;
      const std::string from = "# " + key + " comment (line " + std::to_string(row) + ")";
      if (key == "periodic") {
        const bool yes = text == "yes" || text == "1", no = text == "no" || text == "0";
        if (!yes && !no) throw InputError(f + ":" + std::to_string(row) + ": periodic is '" + std::string(text) + "' (yes or no)");
        s.stated["periodic"] = {{yes ? 1.0 : 0.0}, from};
        continue;
      }
      const auto v = numbers(text);
      if (key == "time") {
        if (v && v->size() == 1) s.time = v->front(), s.time_from = from;  // other comments beginning "time" are prose
        continue;
      }
      if (!v || v->empty()) throw InputError(f + ":" + std::to_string(row) + ": " + key + " is not a number ('" + std::string(text) + "')");
      if (key == "gamma") {
        if (v->size() != 1 || !(v->front() > 1.0))
          throw InputError(f + ":" + std::to_string(row) + ": gamma must be one number > 1, got '" + std::string(text) + "'");
        s.stated["gamma"] = {*v, from, 0.0};  // the number as written
      } else {
        bool pairs = v->size() % 2 == 0 && v->size() <= 6;
        for (std::size_t d = 0; pairs && d < v->size(); d += 2) pairs = (*v)[d] < (*v)[d + 1];
        if (!pairs)
          throw InputError(f + ":" + std::to_string(row) + ": box must be x_lo, x_hi[, y_lo, y_hi[, z_lo, z_hi]] with lo < hi, got '" +
                           std::string(text) + "'");
        s.stated["box"] = {*v, from};
      }
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
      // A writer prints every column with one format (trailing zeros dropped): the file's
      // precision is that of its longest number.
      const double r = printed_round_off(fields[k]);
      if (r > 0.0 && (round_off == 0.0 || r < round_off)) round_off = r;
    }
  }
  if (names.empty()) throw InputError(f + ": empty (no header row)");
  for (const auto& [c, v] : s.columns) s.round_off[c] = round_off;
  if (s.has("z") && !s.has("y")) throw InputError(f + ": has a z column but no y");
  s.dim = s.has("z") ? 3 : s.has("y") ? 2 : 1;
  return s;
}

void write_csv_snapshot(const Snapshot& s, const std::filesystem::path& path) {
  std::string out;
  if (s.time) out += "# time = " + shortest(*s.time) + "\n";
  // What the source file stated of the set-up, as the comments the reader takes.
  for (const auto& [key, st] : s.stated) {
    std::string v;
    for (double x : st.value) v += (v.empty() ? "" : ",") + shortest(x);
    out += "# " + key + " = " + (key == "periodic" ? std::string(st.value.at(0) != 0.0 ? "yes" : "no") : v) + "\n";
  }
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
