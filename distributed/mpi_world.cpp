#include "mpi_world.hpp"

#include <cstdio>
#include <cstdlib>
#include <string>

#include "vri/error.hpp"

namespace vri::distributed {

MpiWorld::MpiWorld() {
  int provided = 0;
  if (MPI_Init_thread(nullptr, nullptr, MPI_THREAD_MULTIPLE, &provided) != MPI_SUCCESS)
    throw Error("MPI_Init_thread failed");
  // A failure in a collective returns here instead of aborting the job, so
  // that each rank can say why (agree) and exit non-zero by itself.
  MPI_Comm_set_errhandler(MPI_COMM_WORLD, MPI_ERRORS_RETURN);
  MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
  MPI_Comm_size(MPI_COMM_WORLD, &size_);
  if (provided >= MPI_THREAD_MULTIPLE) watchdog_ = std::make_unique<RankWatchdog>(MPI_COMM_WORLD, rank_, size_);
  else if (rank_ == 0)
    std::fprintf(stderr, "vri: note: this MPI library gives no MPI_THREAD_MULTIPLE: no watchdog for stopped ranks\n");
}

MpiWorld::~MpiWorld() {
  watchdog_.reset();
  MPI_Finalize();
}

bool MpiWorld::launched_with_several_ranks() {
  for (const char* name : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "PMIX_SIZE"})
    if (const char* v = std::getenv(name)) return std::atoi(v) > 1;
  return false;
}

void MpiWorld::agree(const std::optional<std::string>& failure) const {
  int mine = failure ? rank_ : size_, first = size_;
  if (MPI_Allreduce(&mine, &first, 1, MPI_INT, MPI_MIN, MPI_COMM_WORLD) != MPI_SUCCESS)
    throw Error("rank " + std::to_string(rank_) + ": MPI_Allreduce failed");
  if (first == size_) return;
  std::string why = rank_ == first ? *failure : std::string();
  int length = static_cast<int>(why.size());
  MPI_Bcast(&length, 1, MPI_INT, first, MPI_COMM_WORLD);
  why.resize(length);
  MPI_Bcast(why.data(), length, MPI_CHAR, first, MPI_COMM_WORLD);
  throw JobFailed("rank " + std::to_string(first) + ": " + why);
}

std::vector<std::uint64_t> MpiWorld::all_gather(std::uint64_t value) const {
  std::vector<std::uint64_t> all(size_);
  if (MPI_Allgather(&value, 1, MPI_UINT64_T, all.data(), 1, MPI_UINT64_T, MPI_COMM_WORLD) != MPI_SUCCESS)
    throw Error("rank " + std::to_string(rank_) + ": MPI_Allgather failed");
  return all;
}

std::pair<float, float> MpiWorld::all_min_max(float lo, float hi) const {
  float in[2] = {lo, -hi}, out[2];
  if (MPI_Allreduce(in, out, 2, MPI_FLOAT, MPI_MIN, MPI_COMM_WORLD) != MPI_SUCCESS)
    throw Error("rank " + std::to_string(rank_) + ": MPI_Allreduce failed");
  return {out[0], -out[1]};
}

}  // namespace vri::distributed
