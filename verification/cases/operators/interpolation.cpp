// Case `interpolation`: accuracy of the SPH interpolant (18) and of the gradient in the direct
// form (19) and the difference form (32), for a smooth periodic field on lattices and on
// jittered particle sets, against the analytic field.
#include <cmath>
#include <map>
#include <numbers>
#include <string>

#include "reference/fields.hpp"
#include "sph/core/lattice.hpp"
#include "sph/density/summation.hpp"
#include "sph/kernel/interpolation.hpp"
#include "sph/search/grid_search.hpp"
#include "verification/harness/case.hpp"
#include "verification/cases/common/disorder.hpp"
#include "verification/cases/heat/lattice.hpp"
#include "verification/cases/common/lattice_sums.hpp"
#include "verification/harness/sweep.hpp"

namespace sphv::interpolation_case {
namespace {


const std::string root_2d = "hfact=2.48492", root_3d = "hfact=2.62689";
constexpr double floor_none = 1e-6;

// |S1/S0 - 1| at h/dx = hfact: the gradients' relative error as k dx -> 0.
double gradient_floor(long dim, double hfact) {
  const LatticeSums s = dim == 1 ? lattice_sums<1>(hfact) : dim == 2 ? lattice_sums<2>(hfact) : lattice_sums<3>(hfact);
  return std::abs(s.S1 / s.S0 - 1.0);
}

// The support radius in lattice spacings at level n: hfact (n / 16)^hgrow (hgrow = 0: fixed h/dx;
// hgrow > 0 lets the neighbour count grow with n, so that the disorder of a jittered set averages
// out, common/disorder.hpp).
double h_over_dx(const Params& p) { return p.real("hfact") * std::pow(p.integer("n") / 16.0, p.real("hgrow")); }

// Each error's disorder terms (common/disorder.hpp): (18) and (32) cancel the first moment, (19) keeps it
// over h.
std::map<std::string, disorder::Terms> disorder_terms() {
  return {{"L2_f", {{1, 0}}}, {"L2_grad19", {{1, 1}}}, {"L2_grad32", {{1, 0}}}};
}

// A particle set with (27)'s densities and the residuals of (18), (19) and (32) against the
// field at each particle.
template <int D>
struct Residuals {
  sph::Box<D> box = sph::unit_box<D>(true);
  sph::Particles<D> p;
  sph::NeighbourList nl;
  std::vector<double> f, fi, res_f;
  std::vector<sph::Vec<D>> grad, res19, res32;

  Residuals(const Params& prm, double hfact, double jitter) {
    const int n = static_cast<int>(prm.integer("n"));
    p = sph::lattice<D>(n, box, 1.0, hfact, jitter, prm.integer("seed"));
    nl = sph::grid_search<D>(p.x, p.h, box);
    sph::density_summation<D>(p, nl, box);  // m_j / rho_j from (27), as a simulation has them
    const reference::SineProduct<D> field{static_cast<int>(prm.integer("k"))};
    f.resize(p.size()), grad.resize(p.size());
    for (std::size_t i = 0; i < p.size(); ++i) {
      f[i] = field.value(p.x[i].data());
      const auto g = field.gradient(p.x[i].data());
      grad[i] = Eigen::Map<const sph::Vec<D>>(g.data());
    }
    fi = sph::interpolate<D>(p, f, nl, box);
    res19 = sph::gradient_direct<D>(p, f, nl, box);
    res32 = sph::gradient_difference<D>(p, f, nl, box);
    res_f.resize(p.size());
    for (std::size_t i = 0; i < p.size(); ++i) res_f[i] = fi[i] - f[i], res19[i] -= grad[i], res32[i] -= grad[i];
  }
  // Relative L2 of an error's residual, or of its difference with another set's: the error, or the
  // disorder part (common/disorder.hpp).
  double relative(const std::string& e, const Residuals* minus = nullptr) const {
    if (e == "L2_f") return disorder::relative_l2(res_f, minus ? &minus->res_f : nullptr, f);
    const bool direct = e == "L2_grad19";
    const auto* other = minus ? &(direct ? minus->res19 : minus->res32) : nullptr;
    return disorder::relative_l2(direct ? res19 : res32, other, grad);
  }
};

template <int D>
Result run_dim(const Params& prm) {
  const int n = static_cast<int>(prm.integer("n"));
  const double hfact = h_over_dx(prm);
  const Residuals<D> set(prm, hfact, prm.real("jitter"));
  const auto& p = set.p;
  const auto& nl = set.nl;
  const auto& box = set.box;
  double sum20 = 0;
  std::vector<double> col_e19(p.size()), col_e32(p.size());
  for (std::size_t i = 0; i < p.size(); ++i) col_e19[i] = set.res19[i].norm(), col_e32[i] = set.res32[i].norm();
  // Condition (20) at every particle: how far the set is from a partition of unity.
  const auto one = sph::interpolate<D>(p, std::vector<double>(p.size(), 1.0), nl, box);
  for (double s : one) sum20 = std::max(sum20, std::abs(s - 1.0));

  Result r;
  r.n_particles = p.size();
  for (const char* e : {"L2_f", "L2_grad19", "L2_grad32"}) r.errors[e] = set.relative(e);
  r.extra = {{"neighbours_per_particle", double(nl.pairs()) / p.size()}, {"max_condition20_error", sum20},
             {"h", p.h[0]}, {"jitter", prm.real("jitter")}};
  // On a lattice the sine product is a sum of modes k = 2 pi k_w (+-1, ..., +-1), all multiplied
  // by the same symbol: the relative errors are exactly those of the symbols (heat/lattice.hpp,
  // direct lattice sums), and their limit k dx -> 0 at fixed h/dx is the gradient's floor.
  const double dx = 1.0 / n, kw = 2.0 * std::numbers::pi * prm.integer("k");
  const sph::Vec<D> kv = sph::Vec<D>::Constant(kw);
  r.extra["lattice_symbol_error_f"] = std::abs(1.0 - heat::interpolant_symbol<D>(kv, hfact, dx));
  r.extra["lattice_symbol_error_grad"] = std::abs(heat::gradient_symbol<D>(kv, hfact, dx)[0] / kw - 1.0);
  r.extra["lattice_floor_grad"] = gradient_floor(D, hfact);
  if (prm.real("jitter") > 0.0) {
    // The disorder part: the residual's difference with the unjittered lattice's at the same n and
    // h/dx, particle by particle (common/disorder.hpp).
    const Residuals<D> lattice(prm, hfact, 0.0);
    for (const auto& [e, terms] : disorder_terms())
      r.extra["disorder_" + e] = set.relative(e, &lattice),
      r.extra["disorder_order_" + e] = disorder::disorder_order(D, prm.real("hgrow"), terms);
  }
  static const char* axis[] = {"x", "y", "z"};
  for (int d = 0; d < D; ++d) {
    std::vector<double> c(p.size());
    for (std::size_t i = 0; i < p.size(); ++i) c[i] = p.x[i][d];
    r.particles.add(axis[d], std::move(c));
  }
  r.particles.add("m", p.m);
  r.particles.add("rho", p.rho);
  r.particles.add("h", p.h);
  r.particles.add("f", set.f);
  r.particles.add("f_sph", set.fi);
  r.particles.add("grad_err_19", col_e19);
  r.particles.add("grad_err_32", col_e32);
  if (D == 1) {
    Figure fig{"profile", "Interpolant (18) of sin(2 pi k x + 0.3)", "x", "f", "linear", "linear", {}};
    fig.series.push_back({"SPH (18)", r.particles.columns[0], set.fi, "points"});
    fig.series.push_back({"exact", r.particles.columns[0], set.f, "line"});
    r.figures.push_back(fig);
  }
  return r;
}

Result run(const Params& p) {
  return by_dimension(p, [&](auto d) { return run_dim<d>(p); });
}

void validate(const Params& p) {
  const long d = p.integer("dim");
  if (d < 1 || d > 3) throw InputError("parameter dim must be 1, 2 or 3, got " + std::to_string(d));
  if (h_over_dx(p) * 2.0 >= p.integer("n"))
    throw InputError("support radius hfact (n/16)^hgrow / n must be below half the periodic box: raise n or lower hfact");
  if (p.real("hgrow") < 0.0 || p.real("hgrow") >= 1.0)
    throw InputError("parameter hgrow must be in [0, 1) (h must fall with n), got " + p.text("hgrow"));
  if (p.real("jitter") >= 0.5) throw InputError("parameter jitter must be < 0.5 (fraction of the spacing)");
}

// Lattices: the kernel smoothing error is O(h^2) (eq 5) and, with m_j/rho_j from (27), the
// lattice-sum factor cancels in (18), so order 2 in every dimension. The gradients (19), (32)
// keep the lattice sums: as k dx -> 0 at fixed h/dx their symbol tends to S1/S0 times the exact
// gradient (common/lattice_sums.hpp), a floor |S1/S0 - 1| that no resolution removes. It is 0 in 1D at
// h/dx = 2 and 4 (errata), 1.2e-2 (2D) and 2.0e-2 (3D) at 2, 9.0e-3 in 2D at 2.4. S1/S0 - 1
// changes sign with h/dx, and at its roots the gradients converge at order 2 in 2D and 3D as
// well: 2.48492 (2D) and 2.62689 (3D), the roots near the usual 2.4 to five decimals, leave
// floors of 1.3e-7 and 1.5e-9 (slopes d(S1/S0)/d(h/dx) 0.11 and 0.14), far below the finest
// errors (2.9e-4 and 4.7e-4 at n = 256 and 64). A floor at most 1e-6, under a hundredth of
// those, counts as none (a gate holds it below a tenth of the finest error); larger floors make
// the gradients' order 2 a known failure, with the root variant of the same dimension as its
// experiment. Jittered sets: common/disorder.hpp (no limit at fixed h/dx; orders where h/dx grows).
// Band +-0.1 around the theoretical 2: fitted slopes measured 1.978 to 1.996 (se <= 0.01) on the
// quick (16-64) and standard (16-256) levels of every lattice variant (the O(h^4) term lowers
// them at n = 16); a lattice-sum floor or a wrong kernel shape shifts them by more than 0.3. The
// finest error is bounded by its equality with the lattice symbol (gates).
OrderClaims orders(const Params& p) {
  const OrderClaim two{2.0, 0.1, "O(h^2) kernel smoothing, eq (5)"};
  if (p.real("jitter") > 0.0) {
    OrderClaims o;
    for (const auto& [e, terms] : disorder_terms())
      o[e] = disorder::jittered_claim(static_cast<int>(p.integer("dim")), p.real("hgrow"), terms, 0.1, e);
    return o;
  }
  const long dim = p.integer("dim");
  if (gradient_floor(dim, p.real("hfact")) <= floor_none) return {{"L2_f", two}, {"L2_grad19", two}, {"L2_grad32", two}};
  const std::string experiment = dim == 1 ? "hfact=2" : dim == 2 ? "dim=2," + root_2d : "dim=3," + root_3d;
  auto floor = [&](const std::string& e) {
    return known_failure(2.0, 0.1,
                         "lattice-sum floor at fixed h/dx = hfact: the gradient's symbol tends to S1/S0 times the exact "
                         "gradient as k dx -> 0, and |S1/S0 - 1| = {extra.lattice_floor_grad} (common/lattice_sums.hpp); " +
                             e + " = {" + e + "} at {levels} (order {order." + e + "}) tends to that floor, not to 0",
                         experiment);
  };
  return {{"L2_f", two}, {"L2_grad19", floor("L2_grad19")}, {"L2_grad32", floor("L2_grad32")}};
}

// Cost ~ N at fixed h/dx (the 3D root variant's neighbours (2.627/2)^3 = 2.3 times the 3D
// one's; CPU times: docs/cases/operators.md).
const Levels levels = {.quick = {16, 32, 64}, .standard = {16, 32, 64, 128, 256}, .full = {16, 32, 64, 128, 256, 512}};

// 3D lattices above 64^3 take tens of seconds per level: the standard sweep stops there; full
// adds 128^3 (2.1M particles, eight times 64^3 in time and memory).
Levels levels_for(const Params& p) {
  if (p.integer("dim") == 3) return {.quick = {16, 32, 64}, .standard = {16, 32, 64}, .full = {16, 32, 64, 128}};
  // Jittered with growing h/dx: at n = 16 (19)'s lattice first-moment error still weighs (local
  // order 1.31 to n = 32, then 0.79, 0.85, 0.81), so the quick sweep starts at 32.
  if (p.real("jitter") > 0.0 && p.real("hgrow") > 0.0)
    return {.quick = {32, 64, 128}, .standard = levels.standard, .full = levels.full};
  return levels;
}

std::vector<Check> gates(const Sweep& s) {
  using K = Check::Kind;
  std::vector<Check> c;
  const auto& fine = s.runs.back();
  const auto& x = fine.extra;
  const double n = fine.params["n"].get<double>();
  auto err = [&](const char* e) { return fine.errors.at(e); };
  if (x["jitter"].get<double>() == 0.0) {
    // Lattice: each error equals its symbol's relative error (see run) to round-off; measured
    // agreement <= 2.2e-12 relative (quick and standard levels, every lattice variant); bound 1e-10.
    for (const char* e : {"L2_f", "L2_grad19", "L2_grad32"}) {
      const double pred = x[e == std::string("L2_f") ? "lattice_symbol_error_f" : "lattice_symbol_error_grad"];
      c.push_back({std::string(e) + "_equals_symbol", std::abs(err(e) / pred - 1.0), 0.0, 1e-10,
                   "the sine product is an eigenmode of the lattice operator", K::verification, e});
    }
    // Where the gradients claim order 2, their lattice floor at most a tenth of the finest
    // error: the order is the kernel's smoothing, not the floor's.
    if (x["lattice_floor_grad"].get<double>() <= floor_none)
      for (const char* e : {"L2_grad19", "L2_grad32"})
        c.push_back({std::string(e) + "_lattice_floor", x["lattice_floor_grad"].get<double>() / err(e), 0.0, 0.1,
                     "the lattice-sum floor |S1/S0 - 1| at most a tenth of the finest error", K::verification, e});
    return c;
  }
  // Jittered: the disorder parts' fitted orders, measured on the standard levels of both jittered
  // variants: L2_f -0.04 and 1.14, L2_grad32 0.02 and 1.09, L2_grad19 -0.99 and 0.93 against
  // their terms' 0, 1.2 and -1, 0.8 (hgrow 0, 0.6): within 0.13; on the quick levels within 0.26
  // (L2_grad19 1.06 at hgrow 0.6, n = 16-64); tol 0.3.
  for (auto& k : disorder::disorder_scaling(s, disorder_terms(), fine.params["dim"].get<int>(),
                                            fine.params["hgrow"].get<double>(), 0.3, "measured within 0.26, tol 0.3"))
    c.push_back(std::move(k));
  // Bounds measured for the catalogue's fixed-h/dx variant only (other sets: none).
  if (fine.params["dim"] != 2 || fine.params["jitter"] != 0.1 || fine.params["hfact"] != 2.0 ||
      fine.params["seed"] != 1 || fine.params["k"] != 1 || fine.params["hgrow"] != 0.0)
    return c;
  // Jittered (2D, jitter 0.1 dx, hfact 2, seed 1), measured at n = 16..256:
  // - L2_f levels off at the disorder's kernel-sum error: 2.07e-2 (n = 64), 1.97e-2 (n = 256),
  //   ten to a hundred times the lattice smoothing error. Gate: within [1e-2, 3e-2] (margin
  //   1.5x around the measured floor), and above 3x the lattice symbol's error.
  c.push_back({"L2_f_floor", err("L2_f"), 1e-2, 3e-2, "disorder floor at fixed h/dx, measured 2.0e-2 +- 5%",
               K::drift, "L2_f"});
  c.push_back({"L2_f_over_lattice", err("L2_f") / x["lattice_symbol_error_f"].get<double>(), 3.0, 1e9,
               "disorder adds to the lattice smoothing error", K::verification, "L2_f"});
  // - (19) keeps f_i sum_j V_j grad W_ij, O(jitter dx / h^2) per unit f: the error grows as n
  //   at fixed h/dx. L2_grad19 / n measured 1.24e-2 (n = 64), 1.26e-2 (n = 256); gate
  //   [8e-3, 1.9e-2] (margin 1.5x).
  c.push_back({"L2_grad19_over_n", err("L2_grad19") / n, 8e-3, 1.9e-2, "zeroth-order error ~ jitter / h grows as n",
               K::verification, "L2_grad19"});
  // - (32) subtracts that term: a floor, 5.97e-2 (n = 64), 5.92e-2 (n = 256); gate [4e-2, 9e-2]
  //   (margin 1.5x), and at least 4 times below (19) (measured 13 and 55 times).
  c.push_back({"L2_grad32_floor", err("L2_grad32"), 4e-2, 9e-2, "first-order disorder floor of (32), measured 5.9e-2",
               K::drift, "L2_grad32"});
  c.push_back({"L2_grad19_over_grad32", err("L2_grad19") / err("L2_grad32"), 4.0, 1e9,
               "the difference form (32) removes the zeroth-order error of (19)", K::verification, "L2_grad32"});
  return c;
}

const Registration reg{Case{
    .name = "interpolation",
    .summary = "interpolant (18) and gradients (19), (32) of a sine field, periodic lattices/jitter",
    .n_counts = "particles per side of the periodic unit box (h = hfact/n)",
    .tags = {"gate", "sweep"},
    .params = {integer_param("n", 32, "particles per side of the unit box"),
               integer_param("dim", 1, "dimension 1, 2 or 3"),
               real_param("hfact", 2.0, "support radius in lattice spacings h/dx", 0.0),
               real_param("jitter", 0.0, "random displacement per axis, fraction of dx (0 = lattice)", -1e-300),
               integer_param("k", 1, "wave number of the field (periods per box)"),
               integer_param("seed", 1, "random seed of the jitter"),
               real_param("hgrow", 0.0, "h/dx = hfact (n/16)^hgrow (0: fixed h/dx)", -1e-300)},
    .levels = levels,
    .orders = orders,
    .error_defs = {{"L2_f", "sqrt(sum_i (f_SPH(x_i) - f(x_i))^2 / sum_i f(x_i)^2), interpolant (18) of the sine field"},
                   {"L2_grad19", "sqrt(sum_i |grad f_(19) - grad f|^2 / sum_i |grad f|^2), gradient (19)"},
                   {"L2_grad32", "sqrt(sum_i |grad f_(32) - grad f|^2 / sum_i |grad f|^2), difference gradient (32)"}},
    .variants = {{}, {"dim=2"}, {"dim=3"}, {"dim=2", "hfact=2.4"}, {"dim=2", "jitter=0.1"}, {"dim=2", root_2d},
                 {"dim=3", root_3d}, {"dim=2", "jitter=0.1", "hgrow=0.6"}},
    .levels_for = levels_for,
    .validate = validate,
    .run = run,
    .gates = gates,
}};

}  // namespace
}  // namespace sphv::interpolation_case
