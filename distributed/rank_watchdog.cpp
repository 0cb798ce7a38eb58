#include "rank_watchdog.hpp"

#include <cstdio>
#include <vector>

namespace vri::distributed {

namespace {
constexpr int kTag = 7;
using Clock = std::chrono::steady_clock;
}  // namespace

RankWatchdog::RankWatchdog(MPI_Comm world, int rank, int size, std::chrono::seconds silence)
    : rank_(rank), size_(size), silence_(silence) {
  if (size_ < 2) return;
  MPI_Comm_dup(world, &comm_);
  thread_ = std::thread([this] { run(); });
}

RankWatchdog::~RankWatchdog() {
  if (comm_ == MPI_COMM_NULL) return;
  stop_ = true;
  thread_.join();
  // Every rank has stopped beating before any frees the communicator (the
  // last beats may still wait, unreceived: freeing it drops them).
  MPI_Barrier(comm_);
  MPI_Comm_free(&comm_);
}

// Rank 0 hears every rank and beats to each; the others hear rank 0 and beat to it.
void RankWatchdog::run() {
  std::vector<int> peers;
  if (rank_ == 0)
    for (int r = 1; r < size_; ++r) peers.push_back(r);
  else
    peers.push_back(0);
  std::vector<MPI_Request> receives(peers.size(), MPI_REQUEST_NULL);
  std::vector<int> inbox(peers.size());
  std::vector<Clock::time_point> heard(peers.size(), Clock::now());
  const int beat = 0;
  Clock::time_point next_beat = Clock::now();
  while (!stop_) {
    const Clock::time_point now = Clock::now();
    if (now >= next_beat) {
      for (int p : peers) {
        MPI_Request r;  // small and eager: it completes at once, received or not
        MPI_Isend(&beat, 1, MPI_INT, p, kTag, comm_, &r);
        MPI_Request_free(&r);
      }
      next_beat = now + kBeat;
    }
    for (std::size_t i = 0; i < peers.size(); ++i) {
      if (receives[i] == MPI_REQUEST_NULL) MPI_Irecv(&inbox[i], 1, MPI_INT, peers[i], kTag, comm_, &receives[i]);
      int done = 0;
      MPI_Test(&receives[i], &done, MPI_STATUS_IGNORE);  // drives the progress of the sends too
      if (done) heard[i] = now;
      else if (now - heard[i] > silence_) {
        std::fprintf(stderr,
                     "vri: error: rank %d: rank %d has not been heard from for %lld s (stopped or hung): "
                     "ending the job\n",
                     rank_, peers[i], static_cast<long long>(silence_.count()));
        std::fflush(stderr);
        MPI_Abort(MPI_COMM_WORLD, 1);
      }
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
  }
  for (MPI_Request& r : receives)
    if (r != MPI_REQUEST_NULL) {
      MPI_Cancel(&r);
      MPI_Wait(&r, MPI_STATUS_IGNORE);
    }
}

}  // namespace vri::distributed
