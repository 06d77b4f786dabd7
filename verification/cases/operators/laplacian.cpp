// Case `laplacian`: SPH second derivatives of section 9.4.6 applied to T = prod_a sin(2 pi x_a) in
// the periodic unit box, on lattices and jittered sets in 1D/2D/3D: the Brookshaw Laplacian (69)
// (and (67) in 1D), the two-pass flux forms (56)+(58) and (57)+(59), and the tensor (73) with the
// errata's (d + 2) factor, against the analytic derivatives.
#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <string>

#include "sph/kernel/laplacian.hpp"
#include "verification/harness/case.hpp"
#include "verification/cases/common/disorder.hpp"
#include "verification/cases/heat/lattice.hpp"
#include "verification/harness/sweep.hpp"

namespace sphv::laplacian_case {
namespace {

constexpr double two_pi = 2.0 * std::numbers::pi;

// The support radius in lattice spacings at level n: hfact (n / 16)^hgrow. hgrow = 0 keeps h/dx
// fixed; hgrow = 1/2 lets it grow as sqrt(n) from hfact at n = 16, the coarsest level, so that h
// still falls as n^(-1/2) while the lattice moments' errors, powers of dx/h, vanish.
double h_over_dx(const Params& p) { return p.real("hfact") * std::pow(p.integer("n") / 16.0, p.real("hgrow")); }

// The anisotropy of the lattice's fourth moments that (73) weighs off the diagonal,
// sum x^4 F / (3 sum x^2 y^2 F) - 1 with F = -W'(r) / r over the lattice offsets within h: 0 for
// an isotropic set (the continuum), a power of dx/h on a cubic lattice at fixed h/dx.
template <int D>
double fourth_moment_anisotropy(double ratio) {
  double xxxx = 0.0, xxyy = 0.0;
  heat::for_each_offset<D>(ratio, [&](const sph::Vec<D>& o) {
    const double r2 = o.squaredNorm(), F = -sph::CubicSpline<D>::dWdr(std::sqrt(r2), ratio) / std::sqrt(r2);
    xxxx += o[0] * o[0] * o[0] * o[0] / r2 * F;
    xxyy += o[0] * o[0] * o[1] * o[1] / r2 * F;
  });
  return xxxx / (3.0 * xxyy) - 1.0;
}

// Each form's disorder terms (common/disorder.hpp): a first moment over h in (69) and (73); the
// two-pass forms' outer sums on the smooth gradient and on the inner form's noise.
std::map<std::string, disorder::Terms> disorder_terms() {
  return {{"brookshaw", {{1, 1}}}, {"flux_56_58", {{1, 1}, {2, 2}}}, {"flux_57_59", {{1, 0}, {2, 1}}}, {"tensor_73", {{1, 1}}}};
}

// Every form's residual against the exact derivatives at each particle of a set: the Laplacian
// forms' op_i - lap_i in "brookshaw", "flux_56_58", "flux_57_59", and (73)'s H_i - H_exact,i.
template <int D>
struct Residuals {
  std::vector<double> T, lap;  // the field prod sin(2 pi x_a) and its Laplacian
  std::map<std::string, std::vector<double>> forms;
  std::vector<Eigen::Matrix<double, D, D>> hess, tensor;
  double trace_gap = 0.0, lap_scale = 0.0;

  explicit Residuals(const heat::ParticleSet<D>& s) {
    const auto& p = s.p;
    const std::size_t N = p.size();
    T.resize(N), lap.resize(N), hess.resize(N);
    for (std::size_t i = 0; i < N; ++i) {
      sph::Vec<D> sn, cs;
      for (int a = 0; a < D; ++a) sn[a] = std::sin(two_pi * p.x[i][a]), cs[a] = std::cos(two_pi * p.x[i][a]);
      T[i] = sn.prod();
      lap[i] = -D * two_pi * two_pi * T[i];
      for (int a = 0; a < D; ++a)
        for (int b = 0; b < D; ++b) {
          double v = two_pi * two_pi;
          for (int c = 0; c < D; ++c) v *= (c == a || c == b) ? (a == b ? 1.0 : cs[c]) : sn[c];
          hess[i](a, b) = a == b ? -v * sn[a] : v;
        }
    }
    const auto brook = sph::brookshaw_laplacian<D>(p, T, s.nb());
    const auto sym = sph::two_pass_laplacian<D, sph::SymmetricForm>(p, T, s.nb());
    const auto diff = sph::two_pass_laplacian<D, sph::DifferenceForm>(p, T, s.nb());
    const auto H = sph::hessian<D>(p, T, s.nb());
    const std::pair<const char*, const std::vector<double>*> ops[] = {
        {"brookshaw", &brook}, {"flux_56_58", &sym}, {"flux_57_59", &diff}};
    for (const auto& [name, op] : ops) {
      auto& r = forms[name];
      r.resize(N);
      for (std::size_t i = 0; i < N; ++i) r[i] = (*op)[i] - lap[i];
    }
    tensor.resize(N);
    for (std::size_t i = 0; i < N; ++i) {
      tensor[i] = H[i] - hess[i];
      trace_gap = std::max(trace_gap, std::abs(H[i].trace() - brook[i]));
      lap_scale = std::max(lap_scale, std::abs(lap[i]));
    }
  }
  // Relative L2 of a form's residual, or of its difference with another set's: the error, or the
  // disorder part (common/disorder.hpp).
  double relative(const std::string& e, const Residuals* minus = nullptr) const {
    if (e == "tensor_73") return disorder::relative_l2(tensor, minus ? &minus->tensor : nullptr, hess);
    return disorder::relative_l2(forms.at(e), minus ? &minus->forms.at(e) : nullptr, lap);
  }
  // A form's value at particle i (its residual plus the exact Laplacian).
  double value(const std::string& e, std::size_t i) const { return forms.at(e)[i] + lap[i]; }
};

// Whether the Brookshaw error at these settings tends to a lattice floor rather than to zero: a
// lattice (no jitter) at fixed h/dx whose second moment is not the continuum's (2D and 3D at h/dx
// 4; not 1D at 2 or 4, where the sums are exact). Its claim is then on the distance to the floor.
bool floor_claim(const Params& p) {
  return p.real("jitter") == 0.0 && p.real("hgrow") == 0.0 &&
         heat::has_lattice_floor(static_cast<int>(p.integer("dim")), "brookshaw", p.real("hfact"));
}

template <int D>
Result run_dim(const Params& prm) {
  const int n = static_cast<int>(prm.integer("n"));
  const double hfact = h_over_dx(prm), jitter = prm.real("jitter");
  const heat::ParticleSet<D> s(n, hfact, jitter);
  const auto& p = s.p;
  const std::size_t N = p.size();
  const Residuals<D> res(s);
  const auto& lap = res.lap;
  const double trace_gap = res.trace_gap, lap_scale = res.lap_scale;
  Result r;
  r.n_particles = N;
  for (const char* e : {"brookshaw", "flux_56_58", "flux_57_59", "tensor_73"}) r.errors[e] = res.relative(e);
  const double eps = heat::long_wave_rate_error<D>("brookshaw", hfact, 1.0 / n);
  if (floor_claim(prm)) r.errors["brookshaw_above_floor"] = std::abs(r.errors["brookshaw"] - std::abs(eps));
  // On a lattice the sine product is an eigenmode: the Brookshaw error is exactly the relative
  // error of the lattice symbol at k = 2 pi (1, ..., 1), and its limit at fixed h/dx (k dx -> 0)
  // is the lattice second-moment floor.
  const double dx = 1.0 / n;
  const sph::Vec<D> k = sph::Vec<D>::Constant(two_pi);
  r.extra = {{"dim", D}, {"hfact", hfact}, {"jitter", jitter}, {"h", hfact * dx}, {"h_over_dx", hfact},
             {"neighbours_mean", double(s.nl.pairs()) / N},
             {"lattice_symbol_error", std::abs(heat::brookshaw_symbol<D>(k, hfact, dx) / k.squaredNorm() - 1.0)},
             {"lattice_floor", std::abs(eps)},
             {"lattice_symbol_error_two_pass", std::abs(heat::two_pass_symbol<D>(k, hfact, dx) / k.squaredNorm() - 1.0)},
             {"lattice_symbol_error_tensor", heat::hessian_symbol_error<D>(two_pi, hfact, dx)},
             {"trace_73_minus_69", trace_gap / lap_scale}};
  if constexpr (D > 1) r.extra["fourth_moment_anisotropy"] = std::abs(fourth_moment_anisotropy<D>(hfact));
  if (jitter > 0.0) {
    // The disorder part: the residual's difference with the unjittered lattice's at the same n and
    // h/dx, particle by particle (the lattice's residual is smooth, so moving it by the jitter
    // changes it by O(jitter k dx) of itself).
    const Residuals<D> lattice(heat::ParticleSet<D>(n, hfact, 0.0));
    for (const auto& [e, terms] : disorder_terms())
      r.extra["disorder_" + e] = res.relative(e, &lattice),
      r.extra["disorder_order_" + e] = disorder::disorder_order(D, prm.real("hgrow"), terms);
  }
  if constexpr (D == 1) {
    const auto b67 = sph::brookshaw_laplacian_1d(p, res.T, s.nb());
    double gap = 0.0;
    for (std::size_t i = 0; i < N; ++i) gap = std::max(gap, std::abs(b67[i] - res.value("brookshaw", i)));
    r.extra["eq67_minus_eq69"] = gap / lap_scale;
  }
  // Profile along the first axis (the particles nearest the line x_b = 1/4 for b > 0).
  Series se{"exact", {}, {}, "line"}, sb{"Brookshaw (69)", {}, {}, "points"}, sf{"two-pass (56)+(58)", {}, {}, "points"};
  const double row = (std::floor(0.25 * n) + 0.5) * dx;  // the lattice row nearest 1/4
  for (std::size_t i = 0; i < N; ++i) {
    bool on_line = true;
    for (int a = 1; a < D; ++a) on_line = on_line && std::abs(p.x[i][a] - row) < 0.5 * dx;
    if (!on_line) continue;
    se.x.push_back(p.x[i][0]), se.y.push_back(lap[i] / (D * two_pi * two_pi));
    sb.x.push_back(p.x[i][0]), sb.y.push_back(res.value("brookshaw", i) / (D * two_pi * two_pi));
    sf.x.push_back(p.x[i][0]), sf.y.push_back(res.value("flux_56_58", i) / (D * two_pi * two_pi));
  }
  r.figures.push_back({"laplacian_profile", "SPH Laplacian of prod sin(2 pi x_a) along x (other axes near 1/4)",
                       "x", "lap T / (d (2 pi)^2) (dimensionless)", "linear", "linear", {se, sb, sf}});
  return r;
}

Result run(const Params& p) {
  return by_dimension(p, [&](auto d) { return run_dim<d>(p); });
}

void validate(const Params& p) {
  const long d = p.integer("dim");
  if (d < 1 || d > 3) throw InputError("laplacian: dim must be 1, 2 or 3");
  if (h_over_dx(p) >= 0.5 * p.integer("n"))
    throw InputError("laplacian: support radius hfact (n/16)^hgrow / n must be below half the periodic box");
  if (p.real("hgrow") < 0.0 || p.real("hgrow") >= 1.0)
    throw InputError("laplacian: hgrow must be in [0, 1) (h must fall with n), got " + p.text("hgrow"));
  if (p.real("jitter") >= 0.5) throw InputError("laplacian: jitter must be < 0.5 (particles may not swap cells)");
}

// Theory: O(h^2) smoothing error of a symmetric kernel. On a lattice every error is that of the
// operator's lattice symbol (gates), so the fitted slopes are a deterministic function of the
// levels (their se reflects the curvature of the symbol's error, not noise). Bands: Brookshaw
// 0.15 (measured slopes 1.88 to 1.98 on the quick and standard levels); two-pass 0.3 (measured
// down to 1.72, quick levels in 3D): its symbol |g(k)|^2 is the square of the gradient's, a kernel
// twice as wide, so the (k h)^4 term weighs more at kh near pi/2 (n = 16). The slopes per form
// and dimension: docs/cases/operators.md.
OrderClaims orders(const Params& p) {
  const long dim = p.integer("dim");
  if (p.real("jitter") > 0.0) {
    OrderClaims o;
    for (const auto& [e, terms] : disorder_terms())
      o[e] = disorder::jittered_claim(dim, p.real("hgrow"), terms, e.rfind("flux", 0) == 0 ? 0.3 : 0.15, e);
    return o;
  }
  if (p.real("hgrow") > 0.0) {
    // h = hfact (n/16)^hgrow / n: the smoothing error O(h^2) falls as n^(-2 (1 - hgrow)), the
    // lattice moments' errors as powers of dx/h (the fourth moments' anisotropy as (dx/h)^4,
    // n^(-4 hgrow)), so at hgrow = 1/2 every error is first order in n (second in h). Bands as
    // at fixed h/dx: 0.15, and 0.3 for the two-pass forms, whose (k h)^4 term weighs more (h
    // falls only as n^(-1/2) here: k h ~ 1 on the quick levels; measured at hfact 4 there: 0.82
    // to 1.06, docs/cases/operators.md).
    const std::string why = "h/dx growing as (n/16)^hgrow: the O(h^2) smoothing error, h ~ n^(hgrow - 1), "
                            "dominates the lattice moments' errors, which fall as powers of dx/h";
    const double order = 2.0 * (1.0 - p.real("hgrow"));
    const OrderClaim smoothing{order, 0.15, why}, two_pass{order, 0.3, why};
    return {{"brookshaw", smoothing}, {"flux_56_58", two_pass}, {"flux_57_59", two_pass}, {"tensor_73", smoothing}};
  }
  const std::string why = "lattice: O(h^2) (second moment of a symmetric kernel) until the fixed-h/dx lattice "
                          "second-moment floor |M2/S0 - 1| (0 in 1D at hfact 2 or 4; 8.6e-4 in 2D, 1.3e-4 in 3D at 4)";
  const OrderClaim two{2.0, 0.15, why}, two_pass{2.0, 0.3, why};
  OrderClaims o{{"brookshaw", two}, {"flux_56_58", two_pass}, {"flux_57_59", two_pass}};
  // On the sine mode the Brookshaw error is the symbol's, |eps + c (k h)^2 + O((k h)^4)| with eps
  // the floor (gates): its distance to |eps| is |c| (k h)^2 to leading order, exactly second order
  // (band 0.15 as above).
  if (floor_claim(p)) {
    o["brookshaw_above_floor"] = {2.0, 0.15, "on the lattice the error is the symbol's |eps + c (k h)^2 + O((k h)^4)|, "
                                             "eps = {extra.lattice_floor} from the lattice's second moment at this h/dx: "
                                             "its distance to the floor is |c| (k h)^2, second order"};
    o["brookshaw"] = no_order("at fixed h/dx the error tends to the lattice's second-moment floor |M2/S0 - 1| = "
                              "{extra.lattice_floor}, not to zero; brookshaw_above_floor claims its approach");
  }
  // (73) off the diagonal weighs the fourth lattice moments, isotropic in 1D (where (73) is (69))
  // but not on a square or cubic lattice at fixed h/dx: their anisotropy (fourth_moment_anisotropy,
  // 3.4e-2 in 2D and 1.8e-2 in 3D at h/dx = 4) is a floor of the off-diagonal error that no n
  // removes. With h/dx growing with n it falls as (dx/h)^4 and (73) converges: the experiment.
  o["tensor_73"] = dim == 1 ? two
                            : known_failure(2.0, 0.15,
                                            "fixed-h/dx lattice floor of (73): its off-diagonal part weighs the fourth "
                                            "lattice moments, whose anisotropy sum x^4 F / (3 sum x^2 y^2 F) - 1 is "
                                            "{extra.fourth_moment_anisotropy} at this h/dx whatever n (isotropic: 0); "
                                            "tensor_73 {tensor_73} at {levels}, order {order.tensor_73}, against "
                                            "brookshaw (the trace) {brookshaw}",
                                            "dim=" + std::to_string(dim) + ",hgrow=0.5");
  return o;
}

// Jittered sets (jitter 0.1 dx, seed 7): the errors at the finest quick and standard levels,
// measured. Deterministic for the fixed seed; a window of 1.5x either side catches a form that
// got worse and an error that vanished (the disorder error must stay: no convergence).
struct JitterErrors {
  int dim;
  long n;
  double brookshaw, flux_56_58, flux_57_59, tensor_73;
};
constexpr JitterErrors jitter_measured[] = {
    {1, 32, 0.13984, 0.21082, 0.07754, 0.13984}, {1, 64, 0.25543, 0.66599, 0.09818, 0.25543},
    {2, 32, 0.05826, 0.14598, 0.10075, 0.16145}, {2, 64, 0.10568, 0.36446, 0.05553, 0.31544},
    {3, 32, 0.04308, 0.13971, 0.13225, 0.11465}, {3, 48, 0.04136, 0.11879, 0.06415, 0.15571}};

std::vector<Check> gates(const Sweep& s) {
  using K = Check::Kind;
  std::vector<Check> c;
  const auto& fine = s.runs.back();
  const auto& x = fine.extra;
  const int dim = x["dim"];
  const long n = fine.params["n"];
  auto err = [&](const char* e) { return fine.errors.at(e); };
  const bool jittered = x["jitter"].get<double>() > 0.0;
  if (!jittered) {
    // The lattice operator is a convolution: its error on an eigenmode is the symbol's error,
    // computed independently by direct lattice sums; agreement to round-off (1e-9 relative).
    c.push_back({"brookshaw_equals_symbol", std::abs(err("brookshaw") / x["lattice_symbol_error"].get<double>() - 1.0), 0.0,
                 1e-9, "sine mode is an eigenmode of the lattice operator", K::verification, "brookshaw"});
    // Its distance to the floor likewise: | |symbol error| - floor | from the same direct sums, 1e-9
    // relative as above (the distance is at least 0.6 of the error at every level it is claimed on).
    if (fine.errors.count("brookshaw_above_floor"))
      c.push_back({"brookshaw_above_floor_equals_symbol",
                   std::abs(err("brookshaw_above_floor") /
                                std::abs(x["lattice_symbol_error"].get<double>() - x["lattice_floor"].get<double>()) -
                            1.0),
                   0.0, 1e-9, "the sine mode's distance to the lattice floor from the lattice symbol", K::verification,
                   "brookshaw_above_floor"});
    // The same for the two-pass forms with the squared gradient symbol (both forms agree on a
    // lattice); 1e-9 relative.
    for (const char* e : {"flux_56_58", "flux_57_59"})
      c.push_back({std::string(e) + "_equals_symbol", std::abs(err(e) / x["lattice_symbol_error_two_pass"].get<double>() - 1.0),
                   0.0, 1e-9, "sine mode is an eigenmode of the two-pass lattice operator, symbol |g(k)|^2", K::verification, e});
    if (dim == 1) {
      // In 1D the tensor is the scalar (69): the same symbol.
      c.push_back({"tensor_73_equals_symbol", std::abs(err("tensor_73") / x["lattice_symbol_error"].get<double>() - 1.0),
                   0.0, 1e-9, "1D: (73) is (69)", K::verification, "tensor_73"});
    } else {
      // 2D/3D: the error of (73) is its lattice symbol's (heat::hessian_symbol_error, direct
      // lattice sums), 1e-9 relative as above.
      c.push_back({"tensor_73_equals_symbol", std::abs(err("tensor_73") / x["lattice_symbol_error_tensor"].get<double>() - 1.0),
                   0.0, 1e-9, "sine product: every mode has the (73) lattice symbol's diagonal and off-diagonal errors",
                   K::verification, "tensor_73"});
      if (find_case(s.case_name).parse(s.settings).real("hgrow") == 0.0) {
        // At fixed h/dx the off-diagonal error adds to the trace's: tensor_73 / brookshaw measured
        // 1.52 to 3.5 (n = 32-64), at least 1.2. No upper bound: the ratio grows without one as
        // brookshaw falls as n^-2 and tensor_73 levels off at its floor (8.2 at n = 128 in 2D).
        // tensor_73 at most 0.08 (1.5x the largest finest value, 5.2e-2 at n = 32 in 3D).
        c.push_back({"tensor_73_over_brookshaw", err("tensor_73") / err("brookshaw"), 1.2, 1e9,
                     "off-diagonal lattice moments are not isotropic", K::verification, "tensor_73"});
        c.push_back({"tensor_73_bound", err("tensor_73"), 0.0, 0.08, "measured <= 5.2e-2 at the finest levels, margin 1.5x",
                     K::drift, "tensor_73"});
      }
    }
  } else {
    // Disorder adds to the lattice error (which the lattice symbol gives): the jittered error
    // exceeds it, measured 1.26 (3D, n = 32) to 600 (1D, n = 256), at least 1. No upper bound:
    // at fixed h/dx the disorder part grows with n while the lattice error falls; the disorder
    // part's own order is gated below.
    c.push_back({"jitter_error_over_lattice", err("brookshaw") / x["lattice_symbol_error"].get<double>(), 1.0, 1e9,
                 "jittered set at fixed h/dx: zeroth-order error does not vanish", K::verification, "brookshaw"});
    // The chapter's warning, measured: the two-pass symmetric form is noisier than Brookshaw,
    // 1.51 to 3.45 times at every finest level of quick and standard (6.8 and 7.6 at n = 128):
    // at least 1.2. Its disorder part grows one power of n faster at fixed h/dx (common/disorder.hpp),
    // so the ratio has no upper bound.
    c.push_back({"flux_56_58_over_brookshaw", err("flux_56_58") / err("brookshaw"), 1.2, 1e9,
                 "section 9.4.6 and Brookshaw (1985): the two-pass form is sensitive to disorder", K::verification,
                 "flux_56_58"});
    for (const auto& m : jitter_measured) {
      if (m.dim != dim || m.n != n || x["jitter"].get<double>() != 0.1 || fine.params["hfact"] != 4.0 ||
          fine.params["hgrow"] != 0.0)
        continue;
      const std::pair<const char*, double> errs[] = {{"brookshaw", m.brookshaw}, {"flux_56_58", m.flux_56_58},
                                                     {"flux_57_59", m.flux_57_59}, {"tensor_73", m.tensor_73}};
      for (const auto& [e, v] : errs)
        c.push_back({std::string(e) + "_jittered_window", err(e), v / 1.5, v * 1.5,
                     "measured " + std::to_string(v) + " at this level (seed 7), margin 1.5x", K::drift, e});
    }
    // The disorder parts' fitted orders, measured on the quick and standard levels of the five
    // jittered variants: at most 0.42 outside their terms' range (3D (57)+(59) at fixed h/dx,
    // n = 16-32: 0.42 against [-1, 0], pre-asymptotic; 0.23 at most on the standard levels);
    // tol 0.45. A disorder part that levelled off where it must grow, or grew where it must fall,
    // misses by 0.8 or more.
    for (auto& k : disorder::disorder_scaling(s, disorder_terms(), dim, fine.params["hgrow"].get<double>(), 0.45,
                                              "measured within 0.42 of the range, tol 0.45"))
      c.push_back(std::move(k));
  }
  // Errata (72)/(73): with the (d + 2) factor the trace of the tensor is (69) (round-off 1e-12).
  c.push_back({"trace_73_equals_69", x["trace_73_minus_69"], 0.0, 1e-12, "errata: (d+2) r^a r^b / r^2 - delta^ab"});
  if (x.contains("eq67_minus_eq69"))
    c.push_back({"eq67_equals_eq69", x["eq67_minus_eq69"], 0.0, 1e-12, "(69) reduces to (67) in 1D"});
  return c;
}

// Cost ~ N at fixed neighbours: 1D and 2D are cheap, 3D grows as n^3, so the 3D standard sweep
// stops at 48 and 64, 96 are full only (CPU times: docs/cases/operators.md).
const Levels levels = {.quick = {16, 24, 32}, .standard = {16, 24, 32, 48, 64}, .full = {16, 24, 32, 48, 64, 96, 128}};
Levels levels_for(const Params& p) {
  // h/dx growing as sqrt(n/16) in 3D: 2.8 times the neighbours of h/dx = 4 at n = 32 (5.66),
  // 5.2 times at 48 (6.93, about 6 times the cost of fixed h/dx there): n = 48 is full only.
  if (p.integer("dim") == 3 && p.real("hgrow") > 0.0)
    return {.quick = {16, 24, 32}, .standard = {16, 24, 32}, .full = {16, 24, 32, 48}};
  if (p.integer("dim") == 3) return {.quick = {16, 24, 32}, .standard = {16, 24, 32, 48}, .full = {16, 24, 32, 48, 64, 96}};
  // A lattice with h/dx growing: the lattice moments' errors oscillate with h/dx as the kernel's
  // lattice sums do (operators/kernel.cpp); on 16, 24, 32 (h/dx 4, 4.9, 5.7 at hgrow 1/2) the
  // Brookshaw form's local orders are 1.10 and 0.73 (se 0.10), on 16, 32, 64 (h/dx 4, 5.7, 8)
  // 0.95 and 1.00: the quick sweep doubles n.
  if (p.real("hgrow") > 0.0 && p.real("jitter") == 0.0)
    return {.quick = {16, 32, 64}, .standard = levels.standard, .full = levels.full};
  return levels;
}

const Registration reg{Case{
    .name = "laplacian",
    .summary = "SPH Laplacians (67)/(69), two-pass (56)-(59), tensor (73) of a sine product, lattice and jittered",
    .n_counts = "particles per unit length (box [0,1)^d periodic), h = hfact / n",
    .tags = {"gate", "sweep"},
    .params = {integer_param("n", 32, "particles per side"),
               integer_param("dim", 1, "dimension 1, 2 or 3"),
               real_param("hfact", 4.0, "support radius / spacing h/dx (4: 1D lattice sums exact, 2D/3D floors 9e-4/1.3e-4)", 0.0),
               ParamSpec{"jitter", ParamSpec::Kind::Real, "0", "uniform displacement per axis, fraction of dx", std::nullopt, 0.0},
               real_param("hgrow", 0.0, "h/dx = hfact (n/16)^hgrow (0: fixed h/dx)", -1e-300)},
    .levels = levels,
    .orders = orders,
    .error_defs = {{"brookshaw", "relative L2 over particles of Brookshaw's (67)/(69) against the exact Laplacian of the sine product"},
                   {"brookshaw_above_floor", "|brookshaw - |eps||, eps = symbol(k) / k^2 - 1 as k dx -> 0 by direct "
                                             "lattice sums (heat/lattice.hpp): the distance to the lattice floor, on "
                                             "lattices at fixed h/dx whose eps is not 0"},
                   {"flux_56_58", "relative L2 of the two-pass symmetric form (56)+(58) against the exact Laplacian"},
                   {"flux_57_59", "relative L2 of the two-pass difference form (57)+(59) against the exact Laplacian"},
                   {"tensor_73", "sqrt(sum_i |H_i - H_exact|^2 / sum_i |H_exact|^2), Hessian tensor (73) (Frobenius)"}},
    .variants = {{}, {"dim=2"}, {"dim=3"}, {"jitter=0.1"}, {"dim=2", "jitter=0.1"}, {"dim=3", "jitter=0.1"},
                 {"dim=2", "hgrow=0.5"}, {"dim=3", "hgrow=0.5"},
                 {"dim=2", "jitter=0.1", "hgrow=0.6"}, {"dim=3", "jitter=0.1", "hgrow=0.6"}},
    .levels_for = levels_for,
    .validate = validate,
    .run = run,
    .gates = gates,
}};

}  // namespace
}  // namespace sphv::laplacian_case
