#include "verification/support/reference_cache.hpp"

#include <unistd.h>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <mutex>

namespace sphv {
namespace {

// FNV-1a: a file name for the key (the file repeats the key, which decides).
std::uint64_t fnv1a(const std::string& s) {
  std::uint64_t h = 14695981039346656037ull;
  for (unsigned char c : s) h = (h ^ c) * 1099511628211ull;
  return h;
}

template <class T>
bool read_value(std::ifstream& f, T& v) {
  return static_cast<bool>(f.read(reinterpret_cast<char*>(&v), sizeof v));
}

// The file's columns if it holds key, else nothing (a missing, partial or foreign file).
bool read_columns(const std::filesystem::path& file, const std::string& key, Columns& out) {
  std::ifstream f(file, std::ios::binary);
  std::uint64_t key_size = 0, count = 0;
  if (!f || !read_value(f, key_size) || key_size != key.size()) return false;
  std::string stored(key_size, '\0');
  if (!f.read(stored.data(), static_cast<std::streamsize>(key_size)) || stored != key || !read_value(f, count))
    return false;
  Columns c(count);
  for (auto& col : c) {
    std::uint64_t n = 0;
    if (!read_value(f, n) || n > (std::uint64_t{1} << 32)) return false;
    col.resize(n);
    if (!f.read(reinterpret_cast<char*>(col.data()), static_cast<std::streamsize>(n * sizeof(double)))) return false;
  }
  if (f.peek() != std::char_traits<char>::eof()) return false;
  out = std::move(c);
  return true;
}

void write_columns(const std::filesystem::path& file, const std::string& key, const Columns& c) {
  std::error_code ec;
  std::filesystem::create_directories(file.parent_path(), ec);
  const std::filesystem::path part = file.string() + ".part" + std::to_string(getpid());
  {
    std::ofstream f(part, std::ios::binary);
    auto put = [&f](std::uint64_t v) { f.write(reinterpret_cast<const char*>(&v), sizeof v); };
    put(key.size());
    f.write(key.data(), static_cast<std::streamsize>(key.size()));
    put(c.size());
    for (const auto& col : c) {
      put(col.size());
      f.write(reinterpret_cast<const char*>(col.data()), static_cast<std::streamsize>(col.size() * sizeof(double)));
    }
    if (!f) {
      f.close();
      std::filesystem::remove(part, ec);
      return;
    }
  }
  std::filesystem::rename(part, file, ec);
  if (ec) std::filesystem::remove(part, ec);
}

// This process's references (the lock is not held while one is solved: two threads may both
// solve a key, and keep the same numbers).
Columns kept_in_process(const std::string& key, const std::function<Columns()>& make) {
  static std::mutex mx;
  static std::map<std::string, Columns> kept;
  {
    const std::lock_guard<std::mutex> lock(mx);
    if (const auto it = kept.find(key); it != kept.end()) return it->second;
  }
  Columns c = make();
  const std::lock_guard<std::mutex> lock(mx);
  return kept.emplace(key, std::move(c)).first->second;
}

}  // namespace

Columns cached_reference(const std::string& key, const std::function<Columns()>& make) {
  const char* dir = std::getenv(reference_cache_variable);
  if (!dir || !*dir) return kept_in_process(key, make);
  char name[32];
  std::snprintf(name, sizeof name, "%016llx.bin", static_cast<unsigned long long>(fnv1a(key)));
  const std::filesystem::path file = std::filesystem::path(dir) / name;
  Columns c;
  if (read_columns(file, key, c)) return c;
  c = make();
  write_columns(file, key, c);
  return c;
}

std::string key_number(double v) {
  char b[40];
  std::snprintf(b, sizeof b, "%a", v);
  return b;
}

}  // namespace sphv
