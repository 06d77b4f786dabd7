// HDF5 files are parsed in a child process. The HDF5 C library (Debian's 1.10) trusts a file's
// own sizes and offsets: the snapshot fuzz test found damaged files that smash its stack in a
// type conversion and make it read freed heap memory (H5Aexists, H5O__msg_iterate_real), under
// AddressSanitizer and in release builds alike. A child that dies on such a file becomes one
// InputError naming the file; the columns of a good file come back through a pipe.
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <csignal>
#include <cstring>
#include <string>

#include "verification/harness/params.hpp"
#include "verification/snapshot/snapshot.hpp"

namespace sphv {

namespace {

bool write_all(int fd, const void* data, std::size_t n) {
  const char* p = static_cast<const char*>(data);
  while (n > 0) {
    const ssize_t w = ::write(fd, p, n);
    if (w <= 0) return false;
    p += w;
    n -= static_cast<std::size_t>(w);
  }
  return true;
}

// The child's message: 'E' and the error text, or 'S' and the snapshot (JSON header with the
// column names and lengths and what the file states, which the readers check finite, then the
// time and each column's doubles as raw bytes).
std::string encode(const Snapshot& s) {
  nlohmann::json head = {{"format", s.format}, {"dim", s.dim}, {"taken_from", s.taken_from}, {"time_from", s.time_from},
                         {"round_off", s.round_off}};
  nlohmann::json stated = nlohmann::json::object();
  for (const auto& [k, v] : s.stated) stated[k] = {{"value", v.value}, {"from", v.from}, {"round_off", v.round_off}};
  head["stated"] = stated;
  head["has_time"] = s.time.has_value();  // the time itself goes raw: it may be NaN (refused later)
  nlohmann::json cols = nlohmann::json::array();
  for (const auto& [name, c] : s.columns) cols.push_back({name, c.size()});
  head["columns"] = cols;
  const std::string h = head.dump();
  std::string out = "S" + std::to_string(h.size()) + "\n" + h;
  if (s.time) out.append(reinterpret_cast<const char*>(&*s.time), sizeof(double));
  for (const auto& [name, c] : s.columns) out.append(reinterpret_cast<const char*>(c.data()), c.size() * sizeof(double));
  return out;
}

Snapshot decode(const std::string& msg, const std::filesystem::path& path) {
  const std::size_t nl = msg.find('\n');
  const std::size_t hlen = std::stoul(msg.substr(1, nl - 1));
  const nlohmann::json head = nlohmann::json::parse(msg.substr(nl + 1, hlen));
  Snapshot s;
  s.path = path;
  s.format = head["format"].get<std::string>();
  s.dim = head["dim"].get<int>();
  s.taken_from = head["taken_from"].get<std::map<std::string, std::string>>();
  s.time_from = head["time_from"].get<std::string>();
  s.round_off = head["round_off"].get<std::map<std::string, double>>();
  for (const auto& [k, v] : head["stated"].items())
    s.stated[k] = {v["value"].get<std::vector<double>>(), v["from"].get<std::string>(), v["round_off"].get<double>()};
  std::size_t at = nl + 1 + hlen;
  if (head["has_time"].get<bool>()) {
    double t;
    if (at + sizeof t > msg.size()) throw std::runtime_error("reading " + path.string() + ": short message");
    std::memcpy(&t, msg.data() + at, sizeof t);
    s.time = t;
    at += sizeof t;
  }
  for (const auto& col : head["columns"]) {
    auto& c = s.columns[col[0].get<std::string>()];
    c.resize(col[1].get<std::size_t>());
    if (c.empty()) continue;
    if (at + c.size() * sizeof(double) > msg.size()) throw std::runtime_error("reading " + path.string() + ": short message");
    std::memcpy(c.data(), msg.data() + at, c.size() * sizeof(double));
    at += c.size() * sizeof(double);
  }
  return s;
}

}  // namespace

Snapshot read_hdf5_isolated(const std::filesystem::path& path, const std::function<Snapshot()>& read) {
  int fds[2];
  if (::pipe(fds) != 0) return read();
  const pid_t pid = ::fork();
  if (pid < 0) {
    ::close(fds[0]), ::close(fds[1]);
    return read();
  }
  if (pid == 0) {  // the child: read, send, and leave without running any destructor
    ::close(fds[0]);
    std::string msg;
    try {
      msg = encode(read());
    } catch (const InputError& e) {
      msg = std::string("E") + e.what();
    } catch (const std::exception& e) {  // a defect of the reader, not of the file
      msg = std::string("X") + e.what();
    }
    ::_exit(write_all(fds[1], msg.data(), msg.size()) ? 0 : 3);
  }
  ::close(fds[1]);
  std::string msg;
  char buf[1 << 16];
  for (ssize_t r; (r = ::read(fds[0], buf, sizeof buf)) != 0;) {
    if (r < 0) {
      if (errno == EINTR) continue;
      break;
    }
    msg.append(buf, static_cast<std::size_t>(r));
  }
  ::close(fds[0]);
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
  const std::string f = path.string();
  if (WIFSIGNALED(status))
    throw InputError(f + ": the HDF5 library failed on this file (signal " + std::to_string(WTERMSIG(status)) +
                     " " + strsignal(WTERMSIG(status)) + "): damaged or not written completely?");
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0 || msg.empty())
    throw InputError(f + ": the HDF5 library failed on this file (exit " +
                     std::to_string(WIFEXITED(status) ? WEXITSTATUS(status) : -1) + "): damaged or not written completely?");
  if (msg[0] == 'E') throw InputError(msg.substr(1));
  if (msg[0] == 'X') throw std::runtime_error("reading " + f + ": " + msg.substr(1));
  return decode(msg, path);
}

}  // namespace sphv
