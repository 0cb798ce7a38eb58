#pragma once
// ViewerServer: `vri view`'s web server (Boost.Beast on one I/O thread):
// serves the page's embedded files and, on /ws, one ClientSession per page.
// Every request needs the token; the WebSocket also its own origin.
#include <filesystem>
#include <memory>
#include <string>

#include "server_limits.hpp"
#include "vri/render.hpp"

namespace vri::viewer {

struct ServerOptions {
  std::string host = "127.0.0.1";
  unsigned short port = 8765;           // 0: a free port
  std::filesystem::path file;           // the scene or volume given (may be empty)
  std::filesystem::path bundled_dir;    // bundled scenes, offered in the list (may be missing)
  int threads = 0;                      // render threads per client (0: every core)
  Backend backend = Backend::Cpu;       // where frames are rendered (--backend)
  bool handle_signals = true;           // SIGINT and SIGTERM stop the server
  std::uint64_t page_memory = kPageMemory;  // what one page's renders may hold (server_limits.hpp)
};

class ViewerServer {
 public:
  // Loads nothing yet; binds the address (vri::Error with one line if it cannot).
  explicit ViewerServer(ServerOptions options);
  ~ViewerServer();
  ViewerServer(const ViewerServer&) = delete;
  ViewerServer& operator=(const ViewerServer&) = delete;

  unsigned short port() const;
  const std::string& token() const;
  // http://HOST:PORT/?token=TOKEN
  std::string url() const;
  // Whether the address it listens on is loopback only.
  bool loopback() const;

  // Serves until stop() or, with handle_signals, SIGINT / SIGTERM; then closes
  // every connection and joins the render workers.
  void run();
  // From any thread.
  void stop();

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace vri::viewer
