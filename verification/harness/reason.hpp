#pragma once
// A no-claim or known-failure reason quotes the numbers of its own sweep only: the case writes
// placeholders and the harness fills them in from that sweep's runs, so a reason can never carry
// a number measured on another variant, at other levels or by an older build.
//   {levels}        "n = 200, 400, 800"
//   {NAME}          the error NAME at every level, four digits, e.g. "0.0132, 0.0133, 0.0133"
//   {extra.KEY}     the run's extra KEY (a number) at every level, or once with "at every level"
//                   where the four digits agree at every level
//   {order.NAME}    the observed order of NAME with its standard error, e.g. "0.02 +- 0.01"
// A value a run lacks prints as "-"; an unknown placeholder stays as written, so a test finds it.
#include <string>

namespace sphv {

struct Sweep;

std::string fill_reason(const std::string& why, const Sweep& s);
// The same text for `sphv info`, before any run: each placeholder named in words.
std::string describe_reason(const std::string& why);
// The reason with every placeholder, equation number "(38)" and chapter section "section 9.5"
// removed: what must hold no typed-in measurement.
std::string reason_without_placeholders(const std::string& why);

}  // namespace sphv
