// Fuzzed input: generated malformed values for every parser a user reaches (each parameter of
// each case given with --set, whole settings, case names, level lists) are refused with an
// InputError, never a crash, another exception or a hang; a few hundred of them through the
// command line end in one "sphv: error:" line, exit 2 and no output. The generator is seeded
// (fuzz_inputs.hpp): a failure names the seed and index that replay it.
#include <catch2/catch.hpp>

#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <thread>

#include "verification/harness/case.hpp"
#include "verification/tests/fuzz_inputs.hpp"

extern char** environ;

namespace {

namespace fs = std::filesystem;

// What a user can type: a setting key=value of a case, a case name, or a level list.
struct Target {
  enum class Kind { setting, value, case_name, levels } kind;
  const sphv::Case* c = nullptr;
  std::string key, valid;
};

std::vector<Target> targets() {
  std::vector<Target> out;
  for (const auto& c : sphv::catalogue()) {
    out.push_back({Target::Kind::case_name, &c, "", c.name});
    for (const auto& p : c.params) {
      out.push_back({Target::Kind::setting, &c, p.name, p.name + "=" + p.default_value});
      out.push_back({Target::Kind::value, &c, p.name, p.default_value});
      for (const auto& choice : p.choices) out.push_back({Target::Kind::value, &c, p.name, choice});
    }
    out.push_back({Target::Kind::levels, &c, "", "16,32,64"});
  }
  return out;
}

// Parses one input in-process: true when refused with an InputError, false when accepted.
// Any other exception propagates and fails the test.
bool refused(const Target& t, const std::string& input) {
  try {
    switch (t.kind) {
      case Target::Kind::setting: t.c->parse({input}); break;
      case Target::Kind::value: t.c->parse({t.key + "=" + input}); break;
      case Target::Kind::case_name: sphv::find_case(input); break;
      case Target::Kind::levels: sphv::parse_levels(input); break;
    }
  } catch (const sphv::InputError&) {
    return true;
  }
  return false;
}

// Whether sphv refuses the input as typed on its command line, where --set items are split at
// commas and blanks first (sphv::split_settings): "n=256 " is refused by Case::parse but is the
// valid setting n=256 on the command line.
bool refused_on_command_line(const Target& t, const std::string& input) {
  if (t.kind != Target::Kind::setting && t.kind != Target::Kind::value) return refused(t, input);
  try {
    t.c->parse(sphv::split_settings({t.kind == Target::Kind::setting ? input : t.key + "=" + input}));
  } catch (const sphv::InputError&) {
    return true;
  }
  return false;
}

std::vector<std::string> command_line(const Target& t, const std::string& input, const fs::path& out) {
  const std::string o = "--out=" + out.string();
  switch (t.kind) {
    case Target::Kind::setting: return {"run", t.c->name, "--set=" + input, o};
    case Target::Kind::value: return {"run", t.c->name, "--set=" + t.key + "=" + input, o};
    case Target::Kind::case_name: return {"run", input, o};
    case Target::Kind::levels: break;
  }
  return {"sweep", t.c->name, "--levels=" + input, o};
}

struct Ran {
  bool exited = false, timed_out = false;
  int status = -1;
  std::string out, err;
};

// Runs sphv with args (stdout, stderr to files in dir); killed after timeout_s.
Ran run_sphv(const std::vector<std::string>& args, const fs::path& dir, double timeout_s) {
  std::vector<std::string> a = {SPHV_EXE, "--threads", "1"};
  a.insert(a.end(), args.begin(), args.end());
  std::vector<char*> argv;
  for (auto& s : a) argv.push_back(s.data());
  argv.push_back(nullptr);
  const std::string out = (dir / "stdout").string(), err = (dir / "stderr").string();
  posix_spawn_file_actions_t fa;
  posix_spawn_file_actions_init(&fa);
  posix_spawn_file_actions_addopen(&fa, 1, out.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  posix_spawn_file_actions_addopen(&fa, 2, err.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  pid_t pid = -1;
  const int spawned = posix_spawn(&pid, argv[0], &fa, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&fa);
  REQUIRE(spawned == 0);
  Ran r;
  const auto t0 = std::chrono::steady_clock::now();
  int status = 0;
  while (waitpid(pid, &status, WNOHANG) == 0) {
    if (std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count() > timeout_s) {
      kill(pid, SIGKILL);
      waitpid(pid, &status, 0);
      r.timed_out = true;
      break;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
  }
  r.exited = WIFEXITED(status);
  r.status = r.exited ? WEXITSTATUS(status) : -1;
  r.out = sphv::fuzz::slurp(out);
  r.err = sphv::fuzz::slurp(err);
  return r;
}

std::string printable(const std::string& s) {
  std::string o;
  for (unsigned char ch : s) {
    if (ch >= 0x20 && ch < 0x7f) o += static_cast<char>(ch);
    else {
      char buf[8];
      std::snprintf(buf, sizeof buf, "\\x%02x", ch);
      o += buf;
    }
  }
  return o;
}

}  // namespace

TEST_CASE("fuzz: 10,000+ malformed inputs to every parser are refused with an InputError", "[fuzz]") {
  const auto all = targets();
  sphv::fuzz::Inputs gen(sphv::fuzz::seed);
  // Per target: mutations until it has 40 refused inputs (or 400 tries: a few texts, such as a
  // free integer, accept most of their mutations).
  std::size_t n_refused = 0, n_accepted = 0, index = 0;
  for (const auto& t : all) {
    int mine = 0;
    for (int tries = 0; mine < 40 && tries < 400; ++tries, ++index) {
      const std::string input = gen.mutate(t.valid);
      INFO("seed " << sphv::fuzz::seed << ", input " << index << ": " << (t.c ? t.c->name : "") << " " << t.key << " '"
                   << printable(input) << "'");
      if (refused(t, input)) ++mine;
      else ++n_accepted;
    }
    n_refused += mine;
  }
  WARN("fuzz (seed " << sphv::fuzz::seed << "): " << n_refused << " malformed inputs refused, " << n_accepted
                     << " mutations accepted as valid");
  CHECK(n_refused >= 10000);
}

TEST_CASE("fuzz: malformed input on the command line ends in one error line, exit 2, no output", "[fuzz][cli]") {
  const auto all = targets();
  sphv::fuzz::Inputs gen(sphv::fuzz::seed + 1);
  const fs::path dir = fs::temp_directory_path() / ("sphv-fuzz-" + std::to_string(getpid()));
  fs::create_directories(dir);
  int ran = 0;
  for (std::size_t index = 0; ran < 300; ++index) {
    const Target& t = all[gen.below(all.size())];
    std::string input = gen.mutate(t.valid);
    std::erase(input, '\0');  // an argument cannot hold one
    if (!refused_on_command_line(t, input)) continue;
    const auto args = command_line(t, input, dir / "out");
    std::string shown;
    for (const auto& a : args) shown += " '" + printable(a) + "'";
    INFO("seed " << sphv::fuzz::seed + 1 << ", input " << index << ": sphv" << shown);
    const Ran r = run_sphv(args, dir, 60.0);
    INFO("exit " << r.status << ", stderr '" << printable(r.err) << "', stdout '" << printable(r.out) << "'");
    REQUIRE_FALSE(r.timed_out);
    REQUIRE(r.exited);
    REQUIRE(r.status == 2);
    REQUIRE(r.err.rfind("sphv: error: ", 0) == 0);
    REQUIRE(r.err.find('\n') == r.err.size() - 1);
    REQUIRE(r.out.empty());
    REQUIRE_FALSE(fs::exists(dir / "out"));
    ++ran;
  }
  fs::remove_all(dir);
}
