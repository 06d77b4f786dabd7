#include "verification/io/junit.hpp"

#include <cstdio>

namespace sphv {

namespace {
std::string escaped(const std::string& s) {
  std::string o;
  for (char ch : s) switch (ch) {
      case '&': o += "&amp;"; break;
      case '<': o += "&lt;"; break;
      case '>': o += "&gt;"; break;
      case '"': o += "&quot;"; break;
      case '\'': o += "&apos;"; break;
      default: o += ch;
    }
  return o;
}

std::string check_message(const Check& c) {
  char buf[160];
  std::snprintf(buf, sizeof buf, "%s = %.9g, bound [%.9g, %.9g] (%s): %s", c.name.c_str(), c.value, c.lo, c.hi,
                to_string(c.kind), c.pass() ? "pass" : "FAIL");
  return std::string(buf) + "; " + c.why;
}

std::string testcase(const std::string& cls, const std::string& name, double time, const std::string& message, bool pass) {
  std::string t = "  <testcase classname=\"" + escaped(cls) + "\" name=\"" + escaped(name) + "\" time=\"" +
                  std::to_string(time) + "\">\n";
  if (pass) t += "   <system-out>" + escaped(message) + "</system-out>\n";
  else t += "   <failure message=\"" + escaped(message) + "\"/>\n";
  return t + "  </testcase>\n";
}
}  // namespace

std::string junit_xml(const std::vector<Sweep>& sweeps) {
  std::string body;
  std::size_t tests = 0, failures = 0;
  double time = 0.0;
  for (const Sweep& s : sweeps) {
    const std::string cls = s.case_name + "." + s.variant();
    std::string cases;
    std::size_t n = 0, failed = 0;
    for (const Check& c : s.checks) {
      cases += testcase(cls, c.name, 0.0, check_message(c), c.pass());
      ++n, failed += !c.pass();
    }
    for (const Row& r : s.rows) {
      bool named = false;  // a failing check already reports this row
      for (const Check& c : s.checks) named |= c.error == r.error && !c.pass();
      if (r.outcome != "fail" || named) continue;
      cases += testcase(cls, "outcome_" + r.error, 0.0, r.error + ": fail: " + r.why, false);
      ++n, ++failed;
    }
    body += " <testsuite name=\"" + escaped(cls) + "\" tests=\"" + std::to_string(n) + "\" failures=\"" +
            std::to_string(failed) + "\" errors=\"0\" time=\"" + std::to_string(s.wall_time_s) + "\">\n" + cases +
            " </testsuite>\n";
    tests += n, failures += failed, time += s.wall_time_s;
  }
  return "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<testsuites name=\"sphv verify\" tests=\"" +
         std::to_string(tests) + "\" failures=\"" + std::to_string(failures) + "\" errors=\"0\" time=\"" +
         std::to_string(time) + "\">\n" + body + "</testsuites>\n";
}

}  // namespace sphv
