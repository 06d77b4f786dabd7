#pragma once
// Tests whose list follows what registers itself at start-up (the catalogue's cases, each from
// its own translation unit in an unspecified order): they register from main(), once every static
// object exists, through a function queued here (verification/tests/catch_main.cpp runs them).
#include <vector>

namespace sphv::tests {

using Registrar = void (*)();
std::vector<Registrar>& deferred_registrars();

struct Deferred {
  explicit Deferred(Registrar r) { deferred_registrars().push_back(r); }
};

}  // namespace sphv::tests
