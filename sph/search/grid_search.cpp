// The grid search (sph/search/grid_search.hpp) for the three dimensions, compiled once.
#include "sph/search/grid_search.hpp"

namespace sph {

template void grid_search<1>(const std::vector<Vec<1>>&, const std::vector<double>&, const Box<1>&, NeighbourList&,
                               GridSearchBuffers<1>&);
template NeighbourList grid_search<1>(const std::vector<Vec<1>>&, const std::vector<double>&, const Box<1>&);
template void grid_search<2>(const std::vector<Vec<2>>&, const std::vector<double>&, const Box<2>&, NeighbourList&,
                               GridSearchBuffers<2>&);
template NeighbourList grid_search<2>(const std::vector<Vec<2>>&, const std::vector<double>&, const Box<2>&);
template void grid_search<3>(const std::vector<Vec<3>>&, const std::vector<double>&, const Box<3>&, NeighbourList&,
                               GridSearchBuffers<3>&);
template NeighbourList grid_search<3>(const std::vector<Vec<3>>&, const std::vector<double>&, const Box<3>&);

}  // namespace sph
