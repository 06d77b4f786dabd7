#include "verification/support/mpi.hpp"

#include <cstdlib>

#ifdef SPHV_HAVE_MPI
#include <mpi.h>
#endif

namespace sphv::mpi {

#ifdef SPHV_HAVE_MPI
namespace {
bool started = false;
}

bool compiled() { return true; }

void init(int* argc, char*** argv) {
  // Only under a launcher: a plain `sphv` call never touches MPI.
  if (!std::getenv("OMPI_COMM_WORLD_SIZE") && !std::getenv("PMI_SIZE")) return;
  int provided = 0;
  MPI_Init_thread(argc, argv, MPI_THREAD_FUNNELED, &provided);
  started = true;
}

void finalize() {
  if (started) MPI_Finalize();
  started = false;
}

int rank() {
  int r = 0;
  if (started) MPI_Comm_rank(MPI_COMM_WORLD, &r);
  return r;
}

int size() {
  int s = 1;
  if (started) MPI_Comm_size(MPI_COMM_WORLD, &s);
  return s;
}

void barrier() {
  if (started) MPI_Barrier(MPI_COMM_WORLD);
}

std::vector<std::string> gather(const std::string& mine) {
  if (!started) return {mine};
  const int n = size();
  int len = static_cast<int>(mine.size());
  std::vector<int> lens(n), offs(n);
  MPI_Gather(&len, 1, MPI_INT, lens.data(), 1, MPI_INT, 0, MPI_COMM_WORLD);
  int total = 0;
  for (int r = 0; r < n; ++r) offs[r] = total, total += lens[r];
  std::string all(rank() == 0 ? total : 0, '\0');
  MPI_Gatherv(mine.data(), len, MPI_CHAR, all.data(), lens.data(), offs.data(), MPI_CHAR, 0, MPI_COMM_WORLD);
  if (rank() != 0) return {};
  std::vector<std::string> out;
  for (int r = 0; r < n; ++r) out.push_back(all.substr(offs[r], lens[r]));
  return out;
}
#else
bool compiled() { return false; }
void init(int*, char***) {}
void finalize() {}
int rank() { return 0; }
int size() { return 1; }
void barrier() {}
std::vector<std::string> gather(const std::string& mine) { return {mine}; }
#endif

}  // namespace sphv::mpi
