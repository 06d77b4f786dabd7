#pragma once
#include <string>
#include <vector>

#include "verification/harness/sweep.hpp"

namespace sphv {

// JUnit XML of a catalogue run for CI dashboards: a test suite per sweep, a test case per gate
// check (classname "case.variant", name the check's name; the measured value, the bounds and the
// outcome in the message; a failing check is a <failure>), and one per error row whose outcome
// is "fail" without a failing check (e.g. no order claim).
std::string junit_xml(const std::vector<Sweep>& sweeps);

}  // namespace sphv
