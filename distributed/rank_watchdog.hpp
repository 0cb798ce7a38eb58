#pragma once
// RankWatchdog: ends the job when a rank stops answering (issue 47: a rank
// stopped with SIGSTOP, or hung, held every other rank in a collective until
// an outside timeout). Every rank's thread sends rank 0 a heartbeat each
// second, and rank 0's sends one back to each rank, on a communicator of
// their own; a rank not heard from for `silence` seconds is named on stderr
// and the job aborted (MPI_Abort). A slow rank keeps beating: only a stopped
// or hung process (or its link) falls silent. Needs MPI_THREAD_MULTIPLE; off,
// with a note, where the MPI library does not give it.
#include <atomic>
#include <chrono>
#include <thread>

#include <mpi.h>

namespace vri::distributed {

class RankWatchdog {
 public:
  static constexpr std::chrono::seconds kBeat{1};
  static constexpr std::chrono::seconds kSilence{10};

  // Collective (MPI_Comm_dup of `world`).
  RankWatchdog(MPI_Comm world, int rank, int size, std::chrono::seconds silence = kSilence);
  // Collective: the heartbeats stop, their communicator is freed.
  ~RankWatchdog();
  RankWatchdog(const RankWatchdog&) = delete;
  RankWatchdog& operator=(const RankWatchdog&) = delete;

 private:
  void run();

  MPI_Comm comm_ = MPI_COMM_NULL;
  int rank_ = 0, size_ = 1;
  std::chrono::seconds silence_;
  std::atomic<bool> stop_{false};
  std::thread thread_;
};

}  // namespace vri::distributed
