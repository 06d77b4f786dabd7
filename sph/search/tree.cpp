// The 3D tree (sph/search/tree.hpp), compiled once.
#include "sph/search/tree.hpp"

namespace sph {

template Tree<3> build_tree<3>(const std::vector<Vec<3>>&, const std::vector<double>&, int);

}  // namespace sph
