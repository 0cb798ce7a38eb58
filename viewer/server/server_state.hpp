#pragma once
// What every connection of one viewer server shares: the token, the address
// it answers as, the datasets, the live WebSocket sessions (so that a stop
// can close them), the count of open connections (server_limits.hpp), and
// the reaper that joins the workers of pages that have gone.
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include "dataset.hpp"
#include "worker_reaper.hpp"
#include "vri/render.hpp"

namespace vri::viewer {

class ClientSession;

struct ServerState {
  std::string token;
  std::string host;  // as given with --host
  unsigned short port = 0;
  DatasetCatalog catalog;
  int threads = 0;  // render threads per client (0: every core)
  Backend backend = Backend::Cpu;
  std::uint64_t page_memory = 0;  // what one page's renders may hold

  std::mutex sessions_mutex;
  std::vector<std::weak_ptr<ClientSession>> sessions;
  int connections = 0;  // HTTP connections open (on the I/O thread only)

  WorkerReaper reaper;  // last: destroyed first, joining the workers while the catalog lives
};

}  // namespace vri::viewer
