#pragma once
// The processes of one `mpirun`: MPI initialised on construction with
// MPI_THREAD_MULTIPLE (the main thread's collectives, and the watchdog's
// heartbeats on a thread of their own: rank_watchdog.hpp; TBB renders in
// between without MPI) and finalised on destruction.
#include <cstdint>
#include <exception>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <mpi.h>

#include "rank_watchdog.hpp"
#include "vri/error.hpp"

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

  // Thrown on every rank by agree() when some rank failed: it was agreed on
  // already, so no catch block should call agree() for it again.
  class JobFailed : public Error {
   public:
    using Error::Error;
  };
  // Collective: every rank passes its failure, if any; if some rank failed,
  // every rank throws JobFailed "rank R: why" for the lowest such rank, so
  // no rank waits in a collective for one that gave up.
  void agree(const std::optional<std::string>& failure) const;
  // Collective: f() on every rank, then agree() on whether it threw.
  template <class F>
  auto agreed(F&& f) const {
    std::optional<std::string> failure;
    std::optional<decltype(f())> result;
    try {
      result.emplace(f());
    } catch (const JobFailed&) {
      throw;  // agreed on inside f
    } catch (const std::exception& e) {
      failure = e.what();
    }
    agree(failure);
    return std::move(*result);
  }
  // Collective: every rank's value, by rank.
  std::vector<std::uint64_t> all_gather(std::uint64_t value) const;
  // Collective: the smallest lo and the largest hi over the ranks.
  std::pair<float, float> all_min_max(float lo, float hi) const;

 private:
  int rank_ = 0, size_ = 1;
  std::unique_ptr<RankWatchdog> watchdog_;
};

}  // namespace vri::distributed
