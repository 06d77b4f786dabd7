#pragma once
#include <catch2/catch.hpp>

#include "sph/core/isa.hpp"

// A test runs on one instruction-set path of the pair loops and tree walks (sph/core/isa.hpp):
// the path is set for the object's scope and the previous one restored after. supported() is
// false, with a warning, where this CPU lacks the path.
struct OnIsaPath {
  sph::IsaPath before = sph::isa_path();
  bool ok;
  explicit OnIsaPath(sph::IsaPath p) : ok(sph::isa_supported(p)) {
    if (ok)
      sph::set_isa_path(p);
    else
      WARN("instruction-set path " << sph::isa_name(p) << " not supported by this CPU: not tested");
  }
  ~OnIsaPath() { sph::set_isa_path(before); }
  OnIsaPath(const OnIsaPath&) = delete;
  OnIsaPath& operator=(const OnIsaPath&) = delete;
  bool supported() const { return ok; }
};
