#pragma once
#include <algorithm>
#include <array>
#include <cstddef>
#include <stdexcept>
#include <vector>

#include <Eigen/Core>

#include "sph/core/vec.hpp"

namespace sph {

// Barnes-Hut tree of 9.4.3 (an octree in 3D, 2^D children per node). The root is the cube
// around all particles; a node holding more than leaf_size particles is divided into 2^D
// children of half the edge length (the chapter: leaf_size = 1, the leaves are the particles).
// Coincident particles stop the division at max_depth. During the build every node also gets
// its mass (88), centre of mass (87) and second mass moment about the centre of mass
// S = sum_j m_j (r_j - r_CM)(r_j - r_CM)^T, from which the quadrupole (84) is Q = 3 S - tr(S) I.
template <int D>
struct Tree {
  struct Node {
    Vec<D> centre;     // geometric centre of the cell
    double size;       // edge length d of the cell (89)
    Vec<D> lo, hi;     // bounding box of the node's particles
    int first_child;   // children are nodes first_child .. first_child + n_children - 1
    int n_children;    // 0: a leaf
    int begin, end;    // the node's particles are order[begin .. end)
    double mass;
    Vec<D> com;
    Eigen::Matrix<double, D, D> S;
    bool leaf() const { return n_children == 0; }
  };
  std::vector<Node> nodes;  // nodes[0] is the root; children come after their parent
  std::vector<int> order;   // particle indices grouped by node

  static constexpr int max_depth = 60;
};

template <int D>
Tree<D> build_tree(const std::vector<Vec<D>>& x, const std::vector<double>& m, int leaf_size = 1) {
  if (leaf_size < 1) throw std::invalid_argument("tree: leaf_size must be >= 1");
  if (m.size() != x.size()) throw std::invalid_argument("tree: one mass per particle");
  Tree<D> t;
  const int n = static_cast<int>(x.size());
  if (n == 0) return t;
  t.order.resize(n);
  for (int i = 0; i < n; ++i) t.order[i] = i;
  Vec<D> lo = x[0], hi = x[0];
  for (const auto& xi : x) lo = lo.cwiseMin(xi), hi = hi.cwiseMax(xi);
  using Node = typename Tree<D>::Node;
  auto make = [](const Vec<D>& c, double s, int b, int e) {
    Node nd;
    nd.centre = c;
    nd.size = s;
    nd.first_child = -1;
    nd.n_children = 0;
    nd.begin = b;
    nd.end = e;
    return nd;
  };
  t.nodes.push_back(make(0.5 * (lo + hi), std::max((hi - lo).maxCoeff(), 1e-300), 0, n));

  // Divide nodes depth first; a child's octant bit d is set when x_d >= centre_d.
  constexpr int nchild = 1 << D;
  std::vector<std::pair<int, int>> stack{{0, 0}};  // (node, depth)
  std::vector<int> tmp;
  while (!stack.empty()) {
    const auto [k, depth] = stack.back();
    stack.pop_back();
    const int b = t.nodes[k].begin, e = t.nodes[k].end;
    if (e - b <= leaf_size || depth >= Tree<D>::max_depth) continue;
    const Vec<D> c = t.nodes[k].centre;
    const double s = t.nodes[k].size;
    auto octant = [&](int i) {
      int o = 0;
      for (int d = 0; d < D; ++d) o |= (x[i][d] >= c[d]) << d;
      return o;
    };
    std::array<int, nchild + 1> start{};
    for (int q = b; q < e; ++q) ++start[octant(t.order[q]) + 1];
    for (int o = 0; o < nchild; ++o) start[o + 1] += start[o];
    tmp.assign(t.order.begin() + b, t.order.begin() + e);
    std::array<int, nchild> fill;
    std::copy(start.begin(), start.end() - 1, fill.begin());
    for (int i : tmp) t.order[b + fill[octant(i)]++] = i;
    t.nodes[k].first_child = static_cast<int>(t.nodes.size());
    for (int o = 0; o < nchild; ++o) {
      if (start[o + 1] == start[o]) continue;
      Vec<D> cc;
      for (int d = 0; d < D; ++d) cc[d] = c[d] + ((o >> d) & 1 ? 0.25 : -0.25) * s;
      t.nodes.push_back(make(cc, 0.5 * s, b + start[o], b + start[o + 1]));
      ++t.nodes[k].n_children;
    }
    for (int q = 0; q < t.nodes[k].n_children; ++q) stack.push_back({t.nodes[k].first_child + q, depth + 1});
  }

  // Moments from the leaves up (children have larger indices than their parents).
  for (int k = static_cast<int>(t.nodes.size()) - 1; k >= 0; --k) {
    Node& nd = t.nodes[k];
    nd.mass = 0.0;
    nd.com.setZero();
    nd.S.setZero();
    if (nd.leaf()) {
      nd.lo = nd.hi = x[t.order[nd.begin]];
      for (int q = nd.begin; q < nd.end; ++q) {
        const int i = t.order[q];
        nd.lo = nd.lo.cwiseMin(x[i]), nd.hi = nd.hi.cwiseMax(x[i]);
        nd.mass += m[i];
        nd.com += m[i] * x[i];
      }
      nd.com = nd.mass > 0.0 ? Vec<D>(nd.com / nd.mass) : nd.centre;
      for (int q = nd.begin; q < nd.end; ++q) {
        const int i = t.order[q];
        const Vec<D> dx = x[i] - nd.com;
        nd.S += m[i] * dx * dx.transpose();
      }
    } else {
      const Node& c0 = t.nodes[nd.first_child];
      nd.lo = c0.lo, nd.hi = c0.hi;
      for (int q = 0; q < nd.n_children; ++q) {
        const Node& ch = t.nodes[nd.first_child + q];
        nd.lo = nd.lo.cwiseMin(ch.lo), nd.hi = nd.hi.cwiseMax(ch.hi);
        nd.mass += ch.mass;
        nd.com += ch.mass * ch.com;
      }
      nd.com = nd.mass > 0.0 ? Vec<D>(nd.com / nd.mass) : nd.centre;
      for (int q = 0; q < nd.n_children; ++q) {  // parallel-axis theorem
        const Node& ch = t.nodes[nd.first_child + q];
        const Vec<D> dx = ch.com - nd.com;
        nd.S += ch.S + ch.mass * dx * dx.transpose();
      }
    }
  }
  return t;
}

// Compiled once, in sph/search/tree.cpp (the gravity tree is 3D).
extern template Tree<3> build_tree<3>(const std::vector<Vec<3>>&, const std::vector<double>&, int);

}  // namespace sph
