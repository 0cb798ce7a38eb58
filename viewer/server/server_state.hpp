#pragma once
// What every connection of one viewer server shares: the token, the address
// it answers as, the datasets, and the live WebSocket sessions (so that a
// stop can close them).
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include "dataset.hpp"
#include "vri/render/backend.hpp"

namespace vri::viewer {

class ClientSession;

struct ServerState {
  std::string token;
  std::string host;  // as given with --host
  unsigned short port = 0;
  DatasetCatalog catalog;
  int threads = 0;  // render threads per client (0: every core)
  Backend backend = Backend::Cpu;

  std::mutex sessions_mutex;
  std::vector<std::weak_ptr<ClientSession>> sessions;
};

}  // namespace vri::viewer
