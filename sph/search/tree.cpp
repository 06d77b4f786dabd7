// The tree's build (sph/search/tree.hpp), compiled once for 3D. The nodes of more than task_size
// particles are divided first, level by level, by the team; the subtrees below them are then built
// side by side, each by one thread, and joined in the order of their roots. A division is a stable
// sort, which has one result however the work is split: the tree, its nodes' order included, does
// not depend on the number of threads. Its cells, particle order and moments are those of a serial
// depth-first build.
#include "sph/search/tree.hpp"

#include <omp.h>

#include <algorithm>
#include <array>
#include <stdexcept>
#include <utility>

#include "sph/core/threads.hpp"

namespace sph {

namespace {

// A particle's position beside its index. The divisions move the two together, so that they read
// memory in order rather than through x[order[q]], which jumps across memory when the particles
// are stored in no spatial order.
template <int D>
struct Point {
  Vec<D> x;
  int i;
};
template <int D>
using Points = std::vector<Point<D>, DefaultInitAllocator<Point<D>>>;
template <int D>
using Node = typename Tree<D>::Node;
template <int D>
using Nodes = std::vector<Node<D>, DefaultInitAllocator<Node<D>>>;
template <int D>
constexpr int n_octants = 1 << D;
constexpr int max_chunks = 64;

template <int D>
Node<D> make_node(const Vec<D>& c, double s, int b, int e) {
  Node<D> nd;
  nd.centre = c, nd.size = s;
  nd.first_child = -1, nd.n_children = 0;
  nd.begin = b, nd.end = e;
  return nd;
}

// The octant of x about the centre c: bit d is set when x_d >= c_d.
template <int D>
int octant(const Vec<D>& x, const Vec<D>& c) {
  int o = 0;
  for (int d = 0; d < D; ++d) o |= (x[d] >= c[d]) << d;
  return o;
}

// Where a node's particles of octant o lie once sorted by octant: p[b + start[o] .. b + start[o + 1]).
template <int D>
using Starts = std::array<int, n_octants<D> + 1>;

// f(ch) for the chunks ch < chunks, by the team when there are several; one chunk is called
// directly, without a parallel region (a subtree's divisions, millions of them, would each pay one).
template <class F>
void each_chunk(int chunks, F&& f) {
  if (chunks == 1) return f(0);
#pragma omp parallel for
  for (int ch = 0; ch < chunks; ++ch) f(ch);
}

// p[b .. e) sorted by their octant about c, stably, through tmp[b .. e). With chunks > 1 the team
// counts and moves the particles, a chunk a thread.
template <int D>
Starts<D> sort_by_octant(Points<D>& p, Points<D>& tmp, int b, int e, const Vec<D>& c, int chunks) {
  auto first = [&](int ch) { return b + static_cast<int>(static_cast<long>(e - b) * ch / chunks); };
  std::array<std::array<int, n_octants<D>>, max_chunks> at;  // a chunk's count, then where it writes
  auto count = [&](int ch) {
    at[ch].fill(0);
    for (int q = first(ch); q < first(ch + 1); ++q) tmp[q] = p[q], ++at[ch][octant<D>(p[q].x, c)];
  };
  auto move = [&](int ch) {
    for (int q = first(ch); q < first(ch + 1); ++q) p[at[ch][octant<D>(tmp[q].x, c)]++] = tmp[q];
  };
  each_chunk(chunks, count);
  Starts<D> start{};
  for (int o = 0; o < n_octants<D>; ++o) {
    start[o + 1] = start[o];
    for (int ch = 0; ch < chunks; ++ch) start[o + 1] += std::exchange(at[ch][o], b + start[o + 1]);
  }
  each_chunk(chunks, move);
  return start;
}

// Node k, its particles sorted by octant, gets its non-empty octants as children, appended to
// nodes.
template <int D>
void add_children(Nodes<D>& nodes, int k, const Starts<D>& start) {
  const int b = nodes[k].begin;
  const Vec<D> c = nodes[k].centre;
  const double s = nodes[k].size;
  nodes[k].first_child = static_cast<int>(nodes.size());
  for (int o = 0; o < n_octants<D>; ++o) {
    if (start[o + 1] == start[o]) continue;
    Vec<D> cc;
    for (int d = 0; d < D; ++d) cc[d] = c[d] + ((o >> d) & 1 ? 0.25 : -0.25) * s;
    nodes.push_back(make_node<D>(cc, 0.5 * s, b + start[o], b + start[o + 1]));
    ++nodes[k].n_children;
  }
}

// Mass (88), centre of mass (87), second moment S and bounding box of node k, from its particles (a
// leaf) or from its children, whose moments are known.
template <int D>
void set_moments(Nodes<D>& nodes, int k, const Points<D>& p, const std::vector<double>& m) {
  Node<D>& nd = nodes[k];
  nd.mass = 0.0;
  nd.com.setZero();
  nd.S.setZero();
  if (nd.leaf()) {
    nd.lo = nd.hi = p[nd.begin].x;
    for (int q = nd.begin; q < nd.end; ++q) {
      nd.lo = nd.lo.cwiseMin(p[q].x), nd.hi = nd.hi.cwiseMax(p[q].x);
      nd.mass += m[p[q].i];
      nd.com += m[p[q].i] * p[q].x;
    }
    nd.com = nd.mass > 0.0 ? Vec<D>(nd.com / nd.mass) : nd.centre;
    for (int q = nd.begin; q < nd.end; ++q) {
      const Vec<D> dx = p[q].x - nd.com;
      nd.S += m[p[q].i] * dx * dx.transpose();
    }
    return;
  }
  const Node<D>& c0 = nodes[nd.first_child];
  nd.lo = c0.lo, nd.hi = c0.hi;
  for (int q = 0; q < nd.n_children; ++q) {
    const Node<D>& ch = nodes[nd.first_child + q];
    nd.lo = nd.lo.cwiseMin(ch.lo), nd.hi = nd.hi.cwiseMax(ch.hi);
    nd.mass += ch.mass;
    nd.com += ch.mass * ch.com;
  }
  nd.com = nd.mass > 0.0 ? Vec<D>(nd.com / nd.mass) : nd.centre;
  for (int q = 0; q < nd.n_children; ++q) {  // parallel-axis theorem
    const Node<D>& ch = nodes[nd.first_child + q];
    const Vec<D> dx = ch.com - nd.com;
    nd.S += ch.S + ch.mass * dx * dx.transpose();
  }
}

// The subtree below root (at depth), depth first, on one thread, appended to nodes with its
// moments: root first, children indices into nodes.
template <int D>
void build_subtree(Nodes<D>& nodes, const Node<D>& root, int depth, int leaf_size, Points<D>& p, Points<D>& tmp,
                   const std::vector<double>& m) {
  const int base = static_cast<int>(nodes.size());
  nodes.push_back(root);
  std::vector<std::pair<int, int>> stack{{base, depth}};  // (node, depth)
  while (!stack.empty()) {
    const auto [k, dk] = stack.back();
    stack.pop_back();
    if (nodes[k].end - nodes[k].begin <= leaf_size || dk >= Tree<D>::max_depth) continue;
    add_children<D>(nodes, k, sort_by_octant<D>(p, tmp, nodes[k].begin, nodes[k].end, nodes[k].centre, 1));
    for (int q = 0; q < nodes[k].n_children; ++q) stack.push_back({nodes[k].first_child + q, dk + 1});
  }
  for (int k = static_cast<int>(nodes.size()) - 1; k >= base; --k) set_moments<D>(nodes, k, p, m);
}

}  // namespace

template <int D>
Tree<D> build_tree(const std::vector<Vec<D>>& x, const std::vector<double>& m, int leaf_size) {
  if (leaf_size < 1) throw std::invalid_argument("tree: leaf_size must be >= 1");
  if (m.size() != x.size()) throw std::invalid_argument("tree: one mass per particle");
  Tree<D> t;
  const int n = static_cast<int>(x.size());
  if (n == 0) return t;
  const bool team = static_cast<std::size_t>(n) >= parallel_threshold;
  Points<D> p(n), tmp(n);
  Vec<D> lo = x[0], hi = x[0];
#pragma omp parallel if (team)
  {
    Vec<D> l = x[0], h = x[0];
#pragma omp for nowait
    for (int i = 0; i < n; ++i) p[i] = {x[i], i}, l = l.cwiseMin(x[i]), h = h.cwiseMax(x[i]);
#pragma omp critical
    {
      lo = lo.cwiseMin(l);  // min and max: the same in any order
      hi = hi.cwiseMax(h);
    }
  }
  t.nodes.push_back(make_node<D>(0.5 * (lo + hi), std::max((hi - lo).maxCoeff(), 1e-300), 0, n));

  // The top: nodes of more than task_size particles, divided level by level, each by the whole team
  // while a level has fewer such nodes than threads, else a node a thread; below them the tasks,
  // the roots of the subtrees (with their depths).
  const int task_size = static_cast<int>(std::max<std::size_t>(leaf_size, parallel_threshold));
  const int threads = team ? omp_get_max_threads() : 1;
  std::vector<std::pair<int, int>> tasks, divided;
  for (std::vector<std::pair<int, int>> level{{0, 0}}, next; !level.empty(); level.swap(next)) {
    const std::size_t first = divided.size();
    for (const auto& [k, depth] : level)
      (t.nodes[k].end - t.nodes[k].begin <= task_size || depth >= Tree<D>::max_depth ? tasks : divided)
          .push_back({k, depth});
    const int split = static_cast<int>(divided.size() - first);
    std::vector<Starts<D>> start(split);
    auto sort = [&](int i, int chunks) {
      const Node<D>& nd = t.nodes[divided[first + i].first];
      start[i] = sort_by_octant<D>(p, tmp, nd.begin, nd.end, nd.centre, chunks);
    };
    if (team && split < threads) {
      for (int i = 0; i < split; ++i) sort(i, std::min(threads, max_chunks));
    } else {
#pragma omp parallel for schedule(dynamic, 1) if (team)
      for (int i = 0; i < split; ++i) sort(i, 1);
    }
    next.clear();
    for (int i = 0; i < split; ++i) {
      const auto [k, depth] = divided[first + i];
      add_children<D>(t.nodes, k, start[i]);
      for (int q = 0; q < t.nodes[k].n_children; ++q) next.push_back({t.nodes[k].first_child + q, depth + 1});
    }
  }
  const int top = static_cast<int>(t.nodes.size()), n_tasks = static_cast<int>(tasks.size());
  // The subtrees, side by side: a thread appends those it builds to its own list. Each list is
  // reserved here, on the calling thread, for twice a thread's share of 1.5 nodes a leaf (a lattice
  // makes 1.3, a Gaussian cloud 1.5; only the pages written are ever mapped): glibc would serve a
  // list growing on another thread from that thread's own heap, and fault it in again at the next
  // build.
  struct Built {
    int thread, first, size;  // a subtree's place in its thread's list
  };
  std::vector<Nodes<D>> list(threads);
  for (auto& l : list) l.reserve(3 * static_cast<std::size_t>(n / leaf_size) / threads + 4 * task_size);
  std::vector<Built> built(n_tasks);
#pragma omp parallel num_threads(threads) if (team)
  {
    const int me = omp_get_thread_num();
#pragma omp for schedule(dynamic, 1)
    for (int s = 0; s < n_tasks; ++s) {
      const int first = static_cast<int>(list[me].size());
      build_subtree<D>(list[me], t.nodes[tasks[s].first], tasks[s].second, leaf_size, p, tmp, m);
      built[s] = {me, first, static_cast<int>(list[me].size()) - first};
    }
  }

  // Joined: subtree s's root stays where it is, its other nodes follow the top's in task order.
  std::vector<int> offset(n_tasks + 1, top);
  for (int s = 0; s < n_tasks; ++s) offset[s + 1] = offset[s] + built[s].size - 1;
  t.nodes.resize(offset[n_tasks]);
#pragma omp parallel for schedule(dynamic, 16) if (team)
  for (int s = 0; s < n_tasks; ++s) {
    const auto [th, first, size] = built[s];
    for (int l = 0; l < size; ++l) {
      Node<D>& nd = t.nodes[l == 0 ? tasks[s].first : offset[s] + l - 1];
      nd = list[th][first + l];
      if (!nd.leaf()) nd.first_child += offset[s] - first - 1;
    }
  }
  for (auto k = divided.rbegin(); k != divided.rend(); ++k) set_moments<D>(t.nodes, k->first, p, m);  // children first
  t.order.resize(n);
#pragma omp parallel for if (team)
  for (int q = 0; q < n; ++q) t.order[q] = p[q].i;
  return t;
}

template Tree<3> build_tree<3>(const std::vector<Vec<3>>&, const std::vector<double>&, int);

}  // namespace sph
