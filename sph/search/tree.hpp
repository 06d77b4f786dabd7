#pragma once
#include <cstddef>
#include <vector>

#include <Eigen/Core>

#include "sph/core/uninitialized.hpp"
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
  // nodes[0] is the root; children come after their parent, the children of a node side by side.
  std::vector<Node, DefaultInitAllocator<Node>> nodes;
  std::vector<int> order;  // particle indices grouped by node

  static constexpr int max_depth = 60;
};

// The tree of particles x with masses m; leaves of at most leaf_size particles (1: the chapter's).
// Built in parallel (sph/search/tree.cpp); the same tree, node for node, on any number of threads.
template <int D>
Tree<D> build_tree(const std::vector<Vec<D>>& x, const std::vector<double>& m, int leaf_size = 1);

// Defined and compiled once in sph/search/tree.cpp (the gravity tree is 3D).
extern template Tree<3> build_tree<3>(const std::vector<Vec<3>>&, const std::vector<double>&, int);

}  // namespace sph
