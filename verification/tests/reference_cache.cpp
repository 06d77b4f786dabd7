// support/reference_cache.hpp: a reference stored by one point is read by the next exactly as
// computed, only under its own key; a damaged file is solved again. Without the harness's folder
// a process keeps its own.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <limits>
#include <string>
#include <vector>

#include <unistd.h>

#include "reference/blast_lagrangian.hpp"
#include "reference/evrard_lagrangian.hpp"
#include "sph/kernel/cubic_spline.hpp"
#include "verification/cases/evrard/errors.hpp"
#include "verification/cases/sedov/deposit.hpp"
#include "verification/support/reference_cache.hpp"

namespace {

// The folder SPHV_REFERENCE_CACHE names for the test's scope, fresh and empty; unset after it.
struct CacheFolder {
  std::filesystem::path dir = std::filesystem::temp_directory_path() / ("sphv_reference_cache_" + std::to_string(getpid()));
  CacheFolder() {
    std::filesystem::remove_all(dir);
    setenv(sphv::reference_cache_variable, dir.c_str(), 1);
  }
  ~CacheFolder() {
    unsetenv(sphv::reference_cache_variable);
    std::filesystem::remove_all(dir);
  }
};

// Columns whose bits a text round trip would lose: a third, a subnormal, -0, infinity, NaN.
sphv::Columns awkward() {
  return {{1.0 / 3.0, std::numeric_limits<double>::denorm_min(), -0.0},
          {},
          {std::numeric_limits<double>::infinity(), std::nan("")}};
}

bool same_bits(const sphv::Columns& a, const sphv::Columns& b) {
  if (a.size() != b.size()) return false;
  for (std::size_t k = 0; k < a.size(); ++k)
    if (a[k].size() != b[k].size() ||
        (!a[k].empty() && std::memcmp(a[k].data(), b[k].data(), a[k].size() * sizeof(double)) != 0))
      return false;
  return true;
}

}  // namespace

TEST_CASE("reference cache: one solve per key in the harness's folder, the numbers to the bit") {
  CacheFolder folder;
  int solves = 0;
  auto make = [&] { return ++solves, awkward(); };
  const sphv::Columns first = sphv::cached_reference("problem a " + sphv::key_number(0.1), make);
  const sphv::Columns again = sphv::cached_reference("problem a " + sphv::key_number(0.1), make);
  CHECK(solves == 1);
  CHECK(same_bits(first, awkward()));
  CHECK(same_bits(again, awkward()));
  // Inputs one bit apart are another key, and another solve.
  sphv::cached_reference("problem a " + sphv::key_number(std::nextafter(0.1, 1.0)), make);
  CHECK(solves == 2);
  CHECK(sphv::key_number(0.1) != sphv::key_number(std::nextafter(0.1, 1.0)));
}

TEST_CASE("reference cache: a damaged file is solved again and replaced") {
  CacheFolder folder;
  int solves = 0;
  auto make = [&] { return ++solves, awkward(); };
  sphv::cached_reference("problem b", make);
  REQUIRE(solves == 1);
  for (const auto& f : std::filesystem::directory_iterator(folder.dir))  // cut the one file short
    std::filesystem::resize_file(f.path(), std::filesystem::file_size(f.path()) - 3);
  CHECK(same_bits(sphv::cached_reference("problem b", make), awkward()));
  CHECK(solves == 2);
  sphv::cached_reference("problem b", make);
  CHECK(solves == 2);
}

TEST_CASE("reference cache: without the harness's folder, one solve per process") {
  unsetenv(sphv::reference_cache_variable);
  int solves = 0;
  auto make = [&] { return ++solves, awkward(); };
  const std::string key = "problem c " + std::to_string(getpid());
  CHECK(same_bits(sphv::cached_reference(key, make), awkward()));
  CHECK(same_bits(sphv::cached_reference(key, make), awkward()));
  CHECK(solves == 1);
}

// The keys of the references a sweep shares name every input: in one process (as a gate runs its
// variants), a reference asked for after another that differs in one input only is that input's
// own solve, bit for bit. Few zones: the keys, not the solutions, are under test.
TEST_CASE("reference cache: sedov's deposit blast and the Evrard collapse are keyed by every input") {
  unsetenv(sphv::reference_cache_variable);
  auto direct_blast = [](int dim, double gamma, double E, double rho0, double u_ambient, double r_b, double t,
                         double R, int zones) {
    reference::BlastOptions o;
    o.dim = dim, o.gamma = gamma, o.E = E, o.rho0 = rho0, o.u_ambient = u_ambient, o.t_end = t;
    o.r_out = 4.0 / 3.0 * R, o.zones = zones;
    o.deposit = [r_b, dim](double r) {
      return dim == 2 ? sph::CubicSpline<2>::W(r, r_b) : sph::CubicSpline<3>::W(r, r_b);
    };
    return reference::blast_lagrangian(o);
  };
  // gamma, E, rho0, u_ambient, r_b, t, R, zones: the base, then each changed in turn.
  const std::vector<double> base = {5.0 / 3.0, 1.0, 1.0, 1e-6, 0.075, 0.0285, 0.3, 40};
  const std::vector<double> other = {1.4, 2.0, 1.5, 1e-4, 0.15, 0.02, 0.25, 60};
  for (int dim : {2, 3})
    for (std::size_t k = 0; k <= base.size(); ++k) {
      auto v = base;
      if (k < base.size()) v[k] = other[k];
      INFO("dim " << dim << ", input " << k << " changed");
      const int zones = static_cast<int>(v[7]);
      const reference::RadialProfile cached =
          dim == 2 ? sphv::sedov::deposit_blast<2>(v[0], v[1], v[2], v[3], v[4], v[5], v[6], zones)
                   : sphv::sedov::deposit_blast<3>(v[0], v[1], v[2], v[3], v[4], v[5], v[6], zones);
      const reference::RadialProfile solved = direct_blast(dim, v[0], v[1], v[2], v[3], v[4], v[5], v[6], zones);
      CHECK(same_bits({cached.r_node, cached.v, cached.r_zone, cached.rho, cached.e},
                      {solved.r_node, solved.v, solved.r_zone, solved.rho, solved.e}));
    }
  // zones, gamma, u0, t_end.
  const std::vector<double> e_base = {40, 5.0 / 3.0, 0.05, 0.3}, e_other = {50, 1.4, 0.08, 0.25};
  for (std::size_t k = 0; k <= e_base.size(); ++k) {
    auto v = e_base;
    if (k < e_base.size()) v[k] = e_other[k];
    INFO("Evrard input " << k << " changed");
    const reference::EvrardSolution cached = sphv::evrard::reference_solution(static_cast<int>(v[0]), v[1], v[2], v[3]);
    reference::EvrardOptions o;
    o.zones = static_cast<int>(v[0]), o.gamma = v[1], o.u0 = v[2], o.t_end = v[3];
    const reference::EvrardSolution solved = reference::evrard_lagrangian(o);
    CHECK(same_bits({cached.t, cached.kinetic, cached.thermal, cached.potential, cached.r_profile, cached.rho_profile,
                     cached.at_end.rho, cached.at_end.e},
                    {solved.t, solved.kinetic, solved.thermal, solved.potential, solved.r_profile, solved.rho_profile,
                     solved.at_end.rho, solved.at_end.e}));
    CHECK(cached.steps == solved.steps);
    CHECK(cached.t_max_compression == solved.t_max_compression);
  }
}
