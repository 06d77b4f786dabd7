#pragma once
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <vector>

#include "sph/search/tree.hpp"

namespace sph {

// Self-gravity with the Barnes-Hut tree (9.4.7), 3D, Plummer softening eps (77) (the same as
// add_plummer and the direct sum), units of G given.
enum class Multipole { monopole, quadrupole };
// plain: accept a node when d / r < theta (89), r = |r_i - r_CM|. Unbounded errors above
// theta = 1/sqrt(3) when r_CM sits near the edge of the cell (Salmon & Warren 1994).
// robust: accept when r > d / theta + delta, delta = |r_CM - centre of the cell| (Barnes 1994),
// and never accept the cell that contains r_i: every accepted cell lies outside the sphere of
// radius d / theta about its centre.
enum class Opening { plain, robust };

struct GravityOptions {
  double theta = 0.5;
  double eps = 0.0;
  double G = 1.0;
  Multipole multipole = Multipole::quadrupole;
  Opening opening = Opening::robust;
};

// Accelerations, potentials and the work done per target (particle-particle plus
// particle-node interactions).
struct GravityField {
  std::vector<Vec<3>> a;
  std::vector<double> phi;
  std::vector<long> interactions;
};

namespace detail {

// The walk's sources: entries 0 .. nodes - 1 are the tree's nodes (centre of mass, G M, second
// moment S), entries nodes + q the particles in tree order, with S = 0, for which a node's
// expansion below reduces to a Plummer point mass (77). One record per source: a listed source's
// fields are read together.
struct Source {
  double x, y, z, GM, S00, S01, S02, S11, S12, S22, tr, pad;
};

inline std::vector<Source> sources_of(const Tree<3>& t, const std::vector<Vec<3>>& x, const std::vector<double>& m,
                                      double G) {
  const std::size_t nodes = t.nodes.size();
  std::vector<Source> s(nodes + t.order.size(), Source{});
  for (std::size_t k = 0; k < s.size(); ++k) {
    const bool node = k < nodes;
    const Vec<3>& r = node ? t.nodes[k].com : x[t.order[k - nodes]];
    s[k].x = r[0], s[k].y = r[1], s[k].z = r[2];
    s[k].GM = G * (node ? t.nodes[k].mass : m[t.order[k - nodes]]);
    if (!node) continue;
    const auto& S = t.nodes[k].S;  // symmetric: built from sums of m dx dx^T
    s[k].S00 = S(0, 0), s[k].S01 = S(0, 1), s[k].S02 = S(0, 2), s[k].S11 = S(1, 1), s[k].S12 = S(1, 2);
    s[k].S22 = S(2, 2), s[k].tr = S.trace();
  }
  return s;
}

// A group of targets, walked together (see Group below): 32, one a bit of Lanes.
constexpr int group_size = 32;
using Lanes = unsigned;  // bit l set: target l takes part (at a node), or takes a source
static_assert(group_size == 32 && sizeof(Lanes) == 4, "a group's targets are the bits of a 32-bit unsigned");

// One source's terms at the targets (lanes) first .. first + block - 1 of a group, added where
// bits takes it. A node's terms are its expansion about the centre of mass, y = r - r_CM ((81)
// with the dipole (86) zero), as a Taylor series of the softened Green's function
// g = (|y|^2 + eps^2)^(-1/2): phi = -G [M g + 1/2 S_ab d_a d_b g]. With eps = 0 the second term
// is (81)'s -G Q_ab y_a y_b / (2 r^5), Q = 3 S - tr(S) I (84). a = -grad phi, so the quadrupole
// enters the force. A particle (S = 0) takes the point-mass terms alone (Quadrupole false): its
// second-order terms are exact zeros. The lanes compute the terms and keep them where they take
// the source (a select: a lane that does not, such as the target itself, may see an infinite
// term).
constexpr int block = 8;
template <bool Quadrupole>
inline void add_source(const Source& src, Lanes bits, int first, const double* r0, const double* r1,
                       const double* r2, double G, double eps2, double* ax, double* ay, double* az, double* phi,
                       int* count) {
  const double hG = 0.5 * G;
  const double x = src.x, y = src.y, z = src.z, GM = src.GM;
  const double S00 = src.S00, S01 = src.S01, S02 = src.S02, S11 = src.S11, S12 = src.S12, S22 = src.S22,
               tr = src.tr;
  for (int l = first; l < first + block; ++l) {
    const double y0 = r0[l] - x, y1 = r1[l] - y, y2 = r2[l] - z;
    const double inv = 1.0 / std::sqrt(y0 * y0 + y1 * y1 + y2 * y2 + eps2), inv2 = inv * inv, inv3 = inv * inv2;
    double f = -(GM * inv), k3 = GM * inv3, g0 = -(k3 * y0), g1 = -(k3 * y1), g2 = -(k3 * y2);
    if constexpr (Quadrupole) {
      const double Sy0 = S00 * y0 + S01 * y1 + S02 * y2, Sy1 = S01 * y0 + S11 * y1 + S12 * y2,
                   Sy2 = S02 * y0 + S12 * y1 + S22 * y2;
      const double ySy = y0 * Sy0 + y1 * Sy1 + y2 * Sy2, inv5 = inv3 * inv2;
      const double q = G * inv5, t = 1.5 * tr - 7.5 * ySy * inv2;
      f -= hG * (3.0 * ySy * inv5 - tr * inv3);
      g0 += q * (3.0 * Sy0 + t * y0), g1 += q * (3.0 * Sy1 + t * y1), g2 += q * (3.0 * Sy2 + t * y2);
    }
    const bool in = (bits >> l) & 1u;
    phi[l] += in ? f : 0.0, ax[l] += in ? g0 : 0.0, ay[l] += in ? g1 : 0.0, az[l] += in ? g2 : 0.0;
    count[l] += in;
  }
}

// Potential and acceleration at the targets (lanes) of a group from the sources list[0 .. n),
// entries below `nodes` the tree's nodes, lane l taking source list[k] when bit l of take[k] is
// set; each lane's terms are added in list order. A source's fields are read once for the
// lanes, block lanes at a time; a block none of whose lanes takes the source is skipped (it
// would add +0.0 to sums that start at +0.0 and never reach -0.0: the same sums). Fewer than half
// of the lanes take a given source, and about a third of the blocks none (an Evrard sphere of 7208
// particles at theta 0.5), yet this is faster than per-target lists, whose sources would have to be
// gathered.
template <Multipole M>
inline void sum_sources(const std::vector<Source>& s, const int* list, const Lanes* take, int n, int nodes,
                        const double* r0, const double* r1, const double* r2, double G, double eps2, double* ax,
                        double* ay, double* az, double* phi, int* count) {
  static_assert(group_size % block == 0);
  std::fill_n(ax, group_size, 0.0), std::fill_n(ay, group_size, 0.0), std::fill_n(az, group_size, 0.0);
  std::fill_n(phi, group_size, 0.0), std::fill_n(count, group_size, 0);
  for (int k = 0; k < n; ++k) {
    const Lanes bits = take[k];
    const Source& src = s[list[k]];
    const bool quadrupole = M == Multipole::quadrupole && list[k] < nodes;
    for (int b = 0; b < group_size; b += block) {
      if (((bits >> b) & ((Lanes{1} << block) - 1)) == 0) continue;
      if (quadrupole)
        add_source<true>(src, bits, b, r0, r1, r2, G, eps2, ax, ay, az, phi, count);
      else
        add_source<false>(src, bits, b, r0, r1, r2, G, eps2, ax, ay, az, phi, count);
    }
  }
}

// What the walk reads of a node to decide, in one cache line (Cell): the centre of mass, the
// squared distance from it beyond which the node is accepted (plain (d / theta)^2, robust
// (d / theta + delta)^2), the cell's centre and half its edge; and where its children or
// particles are (Link). The 200-byte tree nodes would spread each decision over several cache
// lines.
struct Cell {
  double cx, cy, cz, rc2, mx, my, mz, half;
};
struct Link {
  int first_child, n_children, begin, end;
};

template <Opening O>
void cells_of(const Tree<3>& t, double theta, std::vector<Cell>& cells, std::vector<Link>& links) {
  cells.resize(t.nodes.size()), links.resize(t.nodes.size());
  for (std::size_t k = 0; k < cells.size(); ++k) {
    const auto& nd = t.nodes[k];
    double rc = nd.size / theta;
    if constexpr (O == Opening::robust) rc += (nd.com - nd.centre).norm();
    cells[k] = {nd.com[0], nd.com[1], nd.com[2], rc * rc, nd.centre[0], nd.centre[1], nd.centre[2], 0.5 * nd.size};
    links[k] = {nd.first_child, nd.n_children, nd.begin, nd.end};
  }
}

// Targets are walked in groups of up to group_size consecutive targets of the visiting order
// (tree order for the particles themselves, so a group is a small patch of space). The group
// shares the traversal: one stack and one fetch of each node for all its targets. Every decision
// is still made per target, as in that target's own walk (9.4.7): the walk lists, per target and
// in the order of its own walk, the nodes it accepts and the leaf particles it meets.
struct Group {
  alignas(64) double x[group_size], y[group_size], z[group_size];  // target positions
  long first = -1;  // the tree position of target 0 when the targets are the particles, else -1
  double ax[group_size], ay[group_size], az[group_size], phi[group_size];  // the field found
  int length[group_size];  // the number of sources each target takes
  // The sources of all the targets in walk order, list[k] taken by the targets in take[k]: a
  // target's own list, in the order of its own walk, is the entries it takes.
  std::vector<int> list;
  std::vector<Lanes> take;
  std::vector<int> todo;  // the walk's stack of nodes, and the targets taking part at each
  std::vector<Lanes> todo_lanes;
};

// The targets l with yes[l] = 1 (yes[l] is 0 or 1). Eight at a time: the product places byte i's
// bit at bit 56 + i, and no two of its partial products overlap.
inline Lanes lanes_of(const unsigned char (&yes)[group_size]) {
  Lanes bits = 0;
  for (int b = 0; b < group_size; b += 8) {
    std::uint64_t u = 0;
    for (int i = 0; i < 8; ++i) u |= std::uint64_t{yes[b + i]} << (8 * i);
    bits |= static_cast<Lanes>((u * 0x0102040810204080ull) >> 56) << b;
  }
  return bits;
}

// The targets accepting a node (its cell) of those taking part (in); the others open it.
template <Opening O>
inline Lanes accept(const Cell& cell, const Group& g, Lanes in) {
  const double c0 = cell.cx, c1 = cell.cy, c2 = cell.cz, rc2 = cell.rc2;
  const double m0 = cell.mx, m1 = cell.my, m2 = cell.mz, half = cell.half;
  unsigned char ok[group_size];
  for (int l = 0; l < group_size; ++l) {
    const double y0 = g.x[l] - c0, y1 = g.y[l] - c1, y2 = g.z[l] - c2;
    bool far = y0 * y0 + (y1 * y1 + y2 * y2) > rc2;  // |y|^2 summed as Eigen's squaredNorm
    if constexpr (O == Opening::robust)  // never the cell that contains the target
      far &= (std::abs(g.x[l] - m0) > half) | (std::abs(g.y[l] - m1) > half) | (std::abs(g.z[l] - m2) > half);
    ok[l] = far;
  }
  return in & lanes_of(ok);
}

// What every walk reads: the nodes' cells and links, the particles' tree order, the sources.
struct Walk {
  std::vector<Cell> cells;
  std::vector<Link> links;
  const std::vector<int>& order;  // the tree's
  std::vector<Source> sources;
  double G, eps2;
};

template <Opening O>
Walk walk_of(const Tree<3>& t, const std::vector<Vec<3>>& x, const std::vector<double>& m, const GravityOptions& o) {
  Walk w{{}, {}, t.order, sources_of(t, x, m, o.G), o.G, o.eps * o.eps};
  cells_of<O>(t, o.theta, w.cells, w.links);
  return w;
}

// Lists the sources of the group's targets (the targets taking part: in). The children of an
// opened node that are leaves are listed at once, the others walked after them: every target's list
// follows from its own decisions alone.
template <Opening O>
void walk(const Walk& w, Lanes in, Group& g) {
  g.list.clear(), g.take.clear();
  const int nodes = static_cast<int>(w.links.size());
  auto list_leaf = [&](const Link& leaf, Lanes here) {
    for (int q = leaf.begin; q < leaf.end; ++q) {  // a target skips itself (tree position q)
      const long l = q - g.first;
      const Lanes self = g.first >= 0 && l >= 0 && l < group_size ? Lanes{1} << l : 0;
      g.list.push_back(nodes + q), g.take.push_back(here & ~self);
    }
  };
  if (w.links.empty()) return;
  if (w.links[0].n_children == 0) return list_leaf(w.links[0], in);
  g.todo.assign(1, 0);
  g.todo_lanes.assign(1, in);
  while (!g.todo.empty()) {
    const int k = g.todo.back();
    const Lanes here = g.todo_lanes.back();
    g.todo.pop_back(), g.todo_lanes.pop_back();
    const Lanes acc = accept<O>(w.cells[k], g, here), open = here & ~acc;
    if (acc) g.list.push_back(k), g.take.push_back(acc);
    if (!open) continue;
    const Link& nd = w.links[k];
    for (int c = nd.first_child; c < nd.first_child + nd.n_children; ++c)
      if (w.links[c].n_children == 0)
        list_leaf(w.links[c], open);
      else
        g.todo.push_back(c), g.todo_lanes.push_back(open);
  }
}

// The field at a group's targets: the walk lists each target's sources, then they are summed.
template <Multipole M, Opening O>
void group_field(const Walk& w, Lanes in, Group& g) {
  walk<O>(w, in, g);
  sum_sources<M>(w.sources, g.list.data(), g.take.data(), static_cast<int>(g.list.size()),
                 static_cast<int>(w.links.size()), g.x, g.y, g.z, w.G, w.eps2, g.ax, g.ay, g.az, g.phi, g.length);
}
using GroupField = void (*)(const Walk&, Lanes, Group&);

// Every target's field, the groups' fields found by group (group_field, in the copy for this
// run's instruction-set path: tree_gravity.cpp).
inline GravityField field(const Walk& w, const std::vector<Vec<3>>& targets, bool at_particles, GroupField group) {
  const std::size_t n = targets.size();
  GravityField f{std::vector<Vec<3>>(n), std::vector<double>(n), std::vector<long>(n)};
  const std::size_t groups = (n + group_size - 1) / group_size;
#pragma omp parallel
  {
    Group g;
#pragma omp for schedule(dynamic, 2)
    for (std::size_t b = 0; b < groups; ++b) {
      // Particles are visited in tree order: a group's targets lie close together.
      const int size = static_cast<int>(std::min<std::size_t>(group_size, n - b * group_size));
      auto target = [&](int l) {  // spare lanes repeat the last target and take no part
        const std::size_t k = b * group_size + std::min(l, size - 1);
        return at_particles ? static_cast<std::size_t>(w.order[k]) : k;
      };
      for (int l = 0; l < group_size; ++l) {
        const Vec<3>& r = targets[target(l)];
        g.x[l] = r[0], g.y[l] = r[1], g.z[l] = r[2];
      }
      g.first = at_particles ? static_cast<long>(b * group_size) : -1L;
      group(w, size == group_size ? ~Lanes{0} : (Lanes{1} << size) - 1, g);
      for (int l = 0; l < size; ++l) {
        const std::size_t i = target(l);
        f.a[i] = Vec<3>(g.ax[l], g.ay[l], g.az[l]), f.phi[i] = g.phi[l], f.interactions[i] = g.length[l];
      }
    }
  }
  return f;
}

}  // namespace detail

// Gravity at `targets`; at_particles: the targets are the particles x themselves (each skips
// its own mass). The method choice is dispatched once, outside the walks
// (sph/gravity/tree_gravity.cpp: the four walks are compiled there once).
GravityField tree_gravity_at(const Tree<3>& t, const std::vector<Vec<3>>& x, const std::vector<double>& m,
                             const GravityOptions& o, const std::vector<Vec<3>>& targets, bool at_particles = false);

// Gravity at every particle from all the others.
inline GravityField tree_gravity(const Tree<3>& t, const std::vector<Vec<3>>& x, const std::vector<double>& m,
                                 const GravityOptions& o) {
  return tree_gravity_at(t, x, m, o, x, true);
}

}  // namespace sph
