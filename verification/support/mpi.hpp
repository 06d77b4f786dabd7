#pragma once
#include <string>
#include <vector>

// Distribution of sweep points over MPI ranks (OpenMPI). Without MPI at build time, or when
// not started by mpirun, there is one rank and these are no-ops.
namespace sphv::mpi {

bool compiled();
void init(int* argc, char*** argv);  // starts MPI only under mpirun
void finalize();
int rank();
int size();
// Waits until every rank has arrived here.
void barrier();
// Gathers each rank's text to rank 0 (in rank order); other ranks get an empty list.
std::vector<std::string> gather(const std::string& mine);

}  // namespace sphv::mpi
