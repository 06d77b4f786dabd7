// Unit tests and gates of the gravity area: tree build, tree neighbour search against the grid
// search, tree gravity against the direct sum, the point-mass scene term.
#include <catch2/catch.hpp>
#include <cmath>
#include <omp.h>
#include <random>

#include "sph/core/threads.hpp"
#include "sph/gravity/point_mass.hpp"
#include "sph/gravity/tree_gravity.hpp"
#include "sph/search/grid_search.hpp"
#include "sph/search/tree.hpp"
#include "sph/search/tree_search.hpp"
#include "verification/cases/gravity/compare.hpp"
#include "verification/cases/gravity/models.hpp"
#include "verification/harness/sweep.hpp"
#include "verification/tests/isa_path.hpp"

using namespace sphv::gravity;
using V3 = sph::Vec<3>;

TEST_CASE("tree: every particle in one leaf, moments add up", "[gravity][tree]") {
  const auto s = clustered(3000, 7);
  const auto t = sph::build_tree<3>(s.x, s.m);
  std::vector<int> seen(s.x.size(), 0);
  for (const auto& nd : t.nodes)
    if (nd.leaf()) {
      CHECK(nd.end - nd.begin == 1);  // leaf_size 1: the leaves are the particles (9.4.3)
      for (int q = nd.begin; q < nd.end; ++q) ++seen[t.order[q]];
    }
  for (int c : seen) REQUIRE(c == 1);
  // Root moments against a plain sum.
  V3 com = V3::Zero();
  for (std::size_t i = 0; i < s.x.size(); ++i) com += s.m[i] * s.x[i];
  Eigen::Matrix3d S = Eigen::Matrix3d::Zero();
  for (std::size_t i = 0; i < s.x.size(); ++i) S += s.m[i] * (s.x[i] - com) * (s.x[i] - com).transpose();
  CHECK(t.nodes[0].mass == Approx(1.0).epsilon(1e-13));
  CHECK((t.nodes[0].com - com).norm() < 1e-13);
  CHECK((t.nodes[0].S - S).norm() < 1e-12 * S.norm());
}

// The build divides the top by the team and the subtrees on their own threads (sph/search/tree.cpp).
// On one thread, on three, and with every loop forked (parallel_threshold 0: the whole tree made
// by team divisions), the tree is the same node for node. Each node is checked against its
// definition (9.4.3): its children's ranges tile its own, each child's particles lie in the child's
// octant of the parent's cell, and its mass, centre of mass and second moment are sums over its
// own particles (to round-off). The divisions are stable sorts: a leaf's particles are in index
// order, as a serial build leaves them.
TEST_CASE("tree: the same on any number of threads, each node as defined", "[gravity][tree]") {
  const auto s = clustered(20000, 5);  // above parallel_threshold (4096): a top, then subtrees
  const std::size_t threshold = sph::parallel_threshold;
  const int threads = omp_get_max_threads();
  omp_set_num_threads(1);
  const auto one = sph::build_tree<3>(s.x, s.m);
  omp_set_num_threads(3);
  const auto three = sph::build_tree<3>(s.x, s.m);
  sph::parallel_threshold = 0;
  const auto forked = sph::build_tree<3>(s.x, s.m, 4);
  omp_set_num_threads(1);
  const auto forked_one = sph::build_tree<3>(s.x, s.m, 4);
  omp_set_num_threads(threads);
  sph::parallel_threshold = threshold;
  auto same = [](const sph::Tree<3>& a, const sph::Tree<3>& b) {
    if (a.order != b.order || a.nodes.size() != b.nodes.size()) return false;
    for (std::size_t k = 0; k < a.nodes.size(); ++k) {
      const auto &u = a.nodes[k], &v = b.nodes[k];
      if (u.centre != v.centre || u.size != v.size || u.lo != v.lo || u.hi != v.hi || u.first_child != v.first_child ||
          u.n_children != v.n_children || u.begin != v.begin || u.end != v.end || u.mass != v.mass || u.com != v.com ||
          u.S != v.S)
        return false;
    }
    return true;
  };
  CHECK(same(one, three));
  CHECK(same(forked, forked_one));
  for (const auto* t : {&one, &forked}) {
    std::size_t wrong = 0;
    for (const auto& nd : t->nodes) {
      int next = nd.begin;
      for (int c = nd.first_child; c < nd.first_child + nd.n_children; ++c) {
        const auto& ch = t->nodes[c];
        wrong += ch.begin != next || ch.end <= ch.begin;
        next = ch.end;
        for (int q = ch.begin; q < ch.end; ++q)
          for (int d = 0; d < 3; ++d) wrong += (s.x[t->order[q]][d] >= nd.centre[d]) != (ch.centre[d] > nd.centre[d]);
      }
      wrong += !nd.leaf() && next != nd.end;
      for (int q = nd.begin; nd.leaf() && q + 1 < nd.end; ++q) wrong += t->order[q] >= t->order[q + 1];
      double mass = 0.0;
      V3 com = V3::Zero();
      for (int q = nd.begin; q < nd.end; ++q) mass += s.m[t->order[q]], com += s.m[t->order[q]] * s.x[t->order[q]];
      com /= mass;
      Eigen::Matrix3d S = Eigen::Matrix3d::Zero();
      for (int q = nd.begin; q < nd.end; ++q) {
        const V3 dx = s.x[t->order[q]] - com;
        S += s.m[t->order[q]] * dx * dx.transpose();
      }
      // S from the children's moments (parallel-axis theorem) or from the particles differs by the
      // rounding of the offsets r - r_CM, u |r| each (u = 1.1e-16, sizes here O(1)): |dS| up to
      // 2 M sqrt(3) d u |r|, which exceeds 1e-12 |S| for two particles 1e-4 apart in a clump.
      const double u = 1.1e-16, offsets = 4.0 * mass * nd.size * u * (com.norm() + nd.size);
      wrong += std::abs(nd.mass - mass) > 1e-12 * mass || (nd.com - com).norm() > 1e-12 * (1.0 + com.norm()) ||
               (nd.S - S).norm() > 1e-12 * S.norm() + offsets;
    }
    CHECK(wrong == 0);
  }
}

TEST_CASE("tree: coincident particles end in one leaf at max depth", "[gravity][tree]") {
  std::vector<V3> x(5, V3(0.3, 0.3, 0.3));
  x.push_back(V3(1, 1, 1));
  const auto t = sph::build_tree<3>(x, std::vector<double>(6, 1.0));
  int leaves = 0;
  for (const auto& nd : t.nodes) leaves += nd.leaf();
  CHECK(leaves == 2);
}

// The gate of the issue: tree walk and linked-cell grid give identical neighbour sets (open
// boundaries), on a uniform set with one h and on a clustered set with variable h.
TEST_CASE("gate: tree search returns the grid search neighbour sets", "[gate][gravity][tree]") {
  for (const bool clumpy : {false, true}) {
    const auto s = clumpy ? clustered(4000, 3) : uniform_sphere(4000, 3);
    std::vector<double> h(s.x.size(), 0.2);
    std::mt19937_64 rng(5);
    std::uniform_real_distribution<double> f(0.2, 1.5);
    if (clumpy)
      for (auto& hi : h) hi = 0.05 * f(rng);
    const auto t = sph::build_tree<3>(s.x, s.m);
    const auto a = sph::tree_search<3>(t, s.x, h);
    const auto b = sph::grid_search<3>(s.x, h, sph::unit_box<3>(false));
    REQUIRE(a.offset == b.offset);
    std::size_t mismatched = 0;
    for (std::size_t i = 0; i < s.x.size(); ++i) {
      std::vector<int> la(a.of(i).begin(), a.of(i).end()), lb(b.of(i).begin(), b.of(i).end());
      std::sort(la.begin(), la.end());
      std::sort(lb.begin(), lb.end());
      mismatched += la != lb;
    }
    CHECK(mismatched == 0);
    CHECK(a.pairs() > 10 * s.x.size());  // the sets are not trivially small
  }
}

// The quadrupole force must be minus the gradient of the quadrupole potential (softened and not):
// central differences of phi, step 1e-4 (truncation ~1e-8 relative).
TEST_CASE("gravity: quadrupole force is -grad phi", "[gravity]") {
  const auto s = plummer_sphere(500, 11, 0.3, 2.0);
  const auto t = sph::build_tree<3>(s.x, s.m);
  for (double eps : {0.0, 0.05}) {
    const sph::GravityOptions o{.theta = 1e9, .eps = eps, .multipole = sph::Multipole::quadrupole,
                                .opening = sph::Opening::plain};  // root node only
    const std::vector<V3> p{V3(2.5, -1.0, 3.0)};
    const auto f = sph::tree_gravity_at(t, s.x, s.m, o, p);
    REQUIRE(f.interactions[0] == 1);
    const double d = 1e-4;
    for (int k = 0; k < 3; ++k) {
      std::vector<V3> pp{p[0], p[0]};
      pp[0][k] += d, pp[1][k] -= d;
      const auto g = sph::tree_gravity_at(t, s.x, s.m, o, pp);
      CHECK(f.a[0][k] == Approx(-(g.phi[0] - g.phi[1]) / (2 * d)).epsilon(1e-7));
    }
  }
}

// A single target's walk written out from the opening criteria (89) and Barnes' robust one: the
// number of interactions it counts. The group walk must make each target's decisions exactly so.
long single_walk_count(const sph::Tree<3>& t, int k, const V3& r, long self, double theta, sph::Opening o) {
  const auto& nd = t.nodes[k];
  if (nd.leaf()) {
    long c = 0;
    for (int q = nd.begin; q < nd.end; ++q) c += t.order[q] != self;
    return c;
  }
  const bool robust = o == sph::Opening::robust;
  const double rc = nd.size / theta + (robust ? (nd.com - nd.centre).norm() : 0.0);
  const bool inside = robust && ((r - nd.centre).cwiseAbs().array() <= 0.5 * nd.size).all();
  if ((r - nd.com).squaredNorm() > rc * rc && !inside) return 1;
  long c = 0;
  for (int q = 0; q < nd.n_children; ++q) c += single_walk_count(t, nd.first_child + q, r, self, theta, o);
  return c;
}

// The walk goes in groups of nearby targets (tree_gravity.hpp) on each instruction-set path.
// A target's interactions are those of its own walk, and its field is the same bit for bit
// whether it is walked with others or alone.
TEST_CASE("gravity: the group walk decides per target, as a single target's walk", "[gravity]") {
  const sph::IsaPath path = GENERATE(sph::IsaPath::portable, sph::IsaPath::avx2, sph::IsaPath::avx512);
  const OnIsaPath on(path);
  if (!on.supported()) return;
  INFO("instruction-set path " << sph::isa_name(path));
  const auto s = clustered(3000, 13);
  const auto t = sph::build_tree<3>(s.x, s.m);
  std::vector<V3> points(s.x.begin(), s.x.begin() + 100);
  for (auto& q : points) q += V3(0.01, -0.02, 0.005);
  for (const auto o : {sph::Opening::plain, sph::Opening::robust})
    for (const double theta : {0.5, 0.9}) {
      INFO("theta " << theta << (o == sph::Opening::robust ? " robust" : " plain"));
      const sph::GravityOptions go{.theta = theta, .eps = 0.01, .opening = o};
      const auto f = sph::tree_gravity(t, s.x, s.m, go);
      long mismatched = 0;
      for (std::size_t i = 0; i < s.x.size(); ++i)
        mismatched += f.interactions[i] != single_walk_count(t, 0, s.x[i], static_cast<long>(i), theta, o);
      CHECK(mismatched == 0);
      const auto together = sph::tree_gravity_at(t, s.x, s.m, go, points);
      for (std::size_t k = 0; k < points.size(); ++k) {
        const auto alone = sph::tree_gravity_at(t, s.x, s.m, go, {points[k]});
        REQUIRE(alone.interactions[0] == single_walk_count(t, 0, points[k], -1, theta, o));
        REQUIRE(alone.interactions[0] == together.interactions[k]);
        REQUIRE(alone.a[0] == together.a[k]);
        REQUIRE(alone.phi[0] == together.phi[k]);
      }
    }
}

// The walk contracts no multiply-add (CMakeLists.txt): its field is the same on every
// instruction-set path bit for bit, for every method (sph/core/isa.hpp), though the AVX2 copy
// computes 4 targets a vector and the AVX-512 copy 8.
TEST_CASE("gravity: the tree walk's field is the same on every instruction-set path", "[gravity]") {
  const auto s = clustered(4000, 17);
  const auto t = sph::build_tree<3>(s.x, s.m);
  std::vector<V3> points(s.x.begin(), s.x.begin() + 77);
  for (auto& q : points) q += V3(-0.013, 0.02, 0.007);
  for (const auto mp : {sph::Multipole::monopole, sph::Multipole::quadrupole})
    for (const auto o : {sph::Opening::plain, sph::Opening::robust}) {
      const sph::GravityOptions go{.theta = 0.6, .eps = 0.005, .multipole = mp, .opening = o};
      const auto portable = [&] {
        const OnIsaPath on(sph::IsaPath::portable);
        return std::pair(sph::tree_gravity(t, s.x, s.m, go), sph::tree_gravity_at(t, s.x, s.m, go, points));
      }();
      for (const auto path : {sph::IsaPath::avx2, sph::IsaPath::avx512}) {
        const OnIsaPath on(path);
        if (!on.supported()) continue;
        INFO(sph::isa_name(path) << (mp == sph::Multipole::quadrupole ? " quadrupole" : " monopole")
                                 << (o == sph::Opening::robust ? " robust" : " plain"));
        const auto f = sph::tree_gravity(t, s.x, s.m, go), g = sph::tree_gravity_at(t, s.x, s.m, go, points);
        for (const auto& [a, b] : {std::pair(&f, &portable.first), std::pair(&g, &portable.second)}) {
          REQUIRE(a->interactions == b->interactions);
          REQUIRE(a->phi == b->phi);
          REQUIRE(a->a == b->a);
        }
      }
    }
}

// With every node opened the tree is a direct sum in another order: agreement to round-off.
TEST_CASE("gravity: tree with theta -> 0 equals the direct sum", "[gravity]") {
  const sph::IsaPath path = GENERATE(sph::IsaPath::portable, sph::IsaPath::avx2, sph::IsaPath::avx512);
  const OnIsaPath on(path);
  if (!on.supported()) return;
  INFO("instruction-set path " << sph::isa_name(path));
  const auto s = uniform_sphere(800, 2);
  const auto t = sph::build_tree<3>(s.x, s.m);
  const auto f = sph::tree_gravity(t, s.x, s.m, {.theta = 1e-6, .eps = 0.01});
  const auto d = direct(s.x, s.m, 0.01);
  const auto p = percentiles(relative_force_error(f, d));
  CHECK(p.max < 1e-12);
  for (std::size_t i = 0; i < s.x.size(); ++i) REQUIRE(f.phi[i] == Approx(d.phi[i]).epsilon(1e-12));
}

TEST_CASE("gravity: point-mass term adds (76)-(77) to dv/dt", "[gravity]") {
  sph::Particles<3> p;
  p.resize(2);
  p.x[0] = V3(1, 0, 0);
  p.x[1] = V3(0, 0.1, 0);
  sph::Scene<3, sph::PointMassGravity<3>> scene;
  scene.term<sph::PointMassGravity<3>>().GM = 2.0;
  scene.term<sph::PointMassGravity<3>>().eps = 0.1;
  sph::NeighbourList nl;
  nl.offset.assign(3, 0);
  const auto box = sph::unit_box<3>(false);
  sph::Derivatives<3> d;
  scene.derivatives(p, {nl, box}, d);
  CHECK(d.dvdt[0][0] == Approx(-2.0 / std::pow(1.01, 1.5)));
  CHECK(d.dvdt[1][1] == Approx(-2.0 * 0.1 / std::pow(0.02, 1.5)));
}
