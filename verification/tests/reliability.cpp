// What the harness writes and prints is what ran: no result file holds NaN or infinity (the
// verdict names the quantity instead), defaults print in a form that reads back exactly, and
// level lists are parsed strictly.
#include <catch2/catch.hpp>

#include <unistd.h>

#include <cfloat>
#include <charconv>
#include <cmath>
#include <fstream>
#include <iterator>
#include <limits>
#include <numbers>

#include "verification/harness/case.hpp"

namespace {
constexpr double not_a_number = std::numeric_limits<double>::quiet_NaN();
constexpr double infinity = std::numeric_limits<double>::infinity();

// A case (not registered) whose run produces non-finite numbers in every part of a result.
sphv::Case non_finite_case(std::string verdict) {
  sphv::Case c;
  c.name = "non_finite";
  c.params = {sphv::integer_param("n", 4, "size")};
  c.run = [verdict](const sphv::Params&) {
    sphv::Result r;
    r.verdict = verdict;
    r.errors = {{"L1", not_a_number}, {"Linf", 0.5}};
    r.functionals = {{"energy", -infinity}, {"mass", 1.0}};
    r.extra = {{"profile", {1.0, infinity, 2.0}}, {"ok", 3}};
    r.particles.add("x", {0.0, 1.0});
    r.particles.add("rho", {1.0, not_a_number});
    r.figures.push_back({"f", "t", "x", "y", "linear", "linear", {{"s", {0.0, 1.0}, {not_a_number, 1.0}, "line"}}});
    return r;
  };
  return c;
}
}  // namespace

TEST_CASE("a run that produces NaN or infinity writes none and names each in its verdict", "[result][non-finite]") {
  const auto c = non_finite_case("ok");
  const sphv::Result r = sphv::run_case(c, c.parse({}));
  CHECK(r.verdict.rfind("non-finite ", 0) == 0);
  for (const char* q : {"errors.L1=nan", "functionals.energy=-inf", "extra.profile[1]=inf", "particles.rho[1]=nan"})
    CHECK(r.verdict.find(q) != std::string::npos);
  CHECK(r.errors.count("L1") == 0);
  CHECK(r.errors.at("Linf") == 0.5);
  CHECK(r.particles.empty());

  const auto dir = std::filesystem::temp_directory_path() / ("sphv-non-finite-" + std::to_string(getpid()));
  sphv::write_result(r, dir);
  std::ifstream f(dir / "result.json");
  const std::string text{std::istreambuf_iterator<char>(f), {}};
  for (const char* bad : {"nan", "NaN", "inf", "Infinity"}) CHECK(text.find(std::string(": ") + bad) == std::string::npos);
  const auto j = nlohmann::json::parse(text);
  CHECK(j.at("errors") == nlohmann::json{{"Linf", 0.5}});
  CHECK(j.at("functionals") == nlohmann::json{{"mass", 1.0}});
  CHECK(j.at("extra").at("profile")[1].is_null());
  CHECK(j.at("figures")[0].at("series")[0].at("y")[0].is_null());  // a gap in a line, not a number
  CHECK_FALSE(std::filesystem::exists(dir / "particles.csv"));
  std::filesystem::remove_all(dir);
}

TEST_CASE("an unstable verdict keeps its word and gains the non-finite names", "[result][non-finite]") {
  const auto c = non_finite_case("unstable: blew up at t = 0.3");
  const sphv::Result r = sphv::run_case(c, c.parse({}));
  CHECK(r.verdict.rfind("unstable: blew up at t = 0.3; non-finite errors.L1=nan", 0) == 0);
}

TEST_CASE("writing a result that still holds a non-finite number is refused", "[result][non-finite]") {
  sphv::Result r;
  r.errors["L1"] = not_a_number;
  CHECK_THROWS_WITH(sphv::to_json(r), Catch::Contains("errors.L1=nan"));
  r.errors["L1"] = 1.0;
  r.particles.add("m", {1.0, -infinity});
  CHECK_THROWS_WITH(sphv::to_json(r), Catch::Contains("particles.m[1]=-inf"));
}

TEST_CASE("defaults print in the shortest form that reads back to the same double", "[params]") {
  CHECK(sphv::real_param("gamma", 5.0 / 3.0, "").default_value == "1.6666666666666667");
  CHECK(sphv::real_param("h", 0.1, "").default_value == "0.1");
  for (double v : {5.0 / 3.0, 0.1, 1.0 / 3.0, std::numbers::pi, 1e-300, 4.9e-324, DBL_MAX, -2.5e-7, 7.0}) {
    const std::string text = sphv::real_param("x", v, "").default_value;
    double back = 0;
    std::from_chars(text.data(), text.data() + text.size(), back);
    INFO(text);
    CHECK(back == v);
  }
  // A user who copies a printed default runs the default run: every real default of every case.
  for (const auto& c : sphv::catalogue())
    for (const auto& p : c.params)
      if (p.kind == sphv::ParamSpec::Kind::Real) {
        INFO(c.name << " " << p.name << " " << p.default_value);
        CHECK(c.parse({p.name + "=" + p.default_value}).to_json() == c.parse({}).to_json());
      }
}

TEST_CASE("level lists are positive integers separated by commas, and nothing else", "[params][levels]") {
  CHECK(sphv::parse_levels("16,32,64") == std::vector<long>{16, 32, 64});
  CHECK(sphv::parse_levels("8") == std::vector<long>{8});
  CHECK_THROWS_WITH(sphv::parse_levels(""), Catch::Contains("at least one value"));
  for (const char* bad : {",", "16,", ",16", "16,,32", "16, 32", "0", "-16", "16.5", "1e2", "x", "99999999999999999999"})
    CHECK_THROWS_AS(sphv::parse_levels(bad), sphv::InputError);
}
