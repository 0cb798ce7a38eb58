#pragma once
// The processes of one `mpirun`: MPI initialised on construction with
// MPI_THREAD_FUNNELED (only the main thread calls MPI; TBB renders in
// between) and finalised on destruction.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <mpi.h>

namespace vri::distributed {

class MpiWorld {
 public:
  MpiWorld();
  ~MpiWorld();
  MpiWorld(const MpiWorld&) = delete;
  MpiWorld& operator=(const MpiWorld&) = delete;

  // True when this process was started by mpirun (Open MPI, or a PMI
  // launcher) among several: `vri render` then renders sort-last unasked.
  static bool launched_with_several_ranks();

  int rank() const { return rank_; }
  int size() const { return size_; }
  MPI_Comm comm() const { return MPI_COMM_WORLD; }

  // Collective: every rank passes its failure, if any; if some rank failed,
  // every rank throws vri::Error "rank R: why" for the lowest such rank, so
  // no rank waits in a collective for one that gave up.
  void agree(const std::optional<std::string>& failure) const;
  // Collective: every rank's value, by rank.
  std::vector<std::uint64_t> all_gather(std::uint64_t value) const;

 private:
  int rank_ = 0, size_ = 1;
};

}  // namespace vri::distributed
