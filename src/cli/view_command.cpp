// vri view [SCENE.json | VOLUME_FILE] [--host H] [--port P] [--open]
// (SPEC §11; docs/VIEWER.md): the viewer in the browser. Prints the page's
// address as the first line on stdout and serves until Ctrl-C.
#include <spawn.h>
#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <memory>
#include <string>

#include "commands.hpp"
#include "vri/error.hpp"
#include "vri/render.hpp"
#if VRI_VIEWER
#include "viewer_server.hpp"
#endif

extern char** environ;

namespace vri::cli {

namespace {

struct ViewArgs {
  std::string file;
  std::string host = "127.0.0.1";
  int port = 8765;
  bool open = false;
  int threads = 0;
  std::string backend = "cpu";
  bool host_given = false;
};

#if VRI_VIEWER
// The desktop's browser (xdg-open), not waited for; a warning if there is none.
void open_browser(const std::string& url) {
  pid_t pid = 0;
  const char* argv[] = {"xdg-open", url.c_str(), nullptr};
  if (posix_spawnp(&pid, "xdg-open", nullptr, nullptr, const_cast<char**>(argv), environ) != 0)
    std::cerr << "vri: warning: cannot start a browser (xdg-open); open the address above\n";
}

int run_view(const ViewArgs& args) {
  if (args.port < 0 || args.port > 65535) throw Error("--port must be 0..65535, not " + std::to_string(args.port));
  if (args.threads < 0 || args.threads > 1024) throw Error("--threads must be 0..1024");
  namespace fs = std::filesystem;
  if (!args.file.empty() && !fs::is_regular_file(args.file))
    throw FileError("cannot read '" + args.file + "': no such file");
  viewer::ServerOptions options;
  options.host = args.host;
  options.port = static_cast<unsigned short>(args.port);
  options.file = args.file;
  const char* scenes = std::getenv("VRI_SCENES");  // where the bundled scenes are, if not in the source tree
  options.bundled_dir = fs::path(scenes ? scenes : VRI_BUNDLED_SCENES);
  options.threads = args.threads;
  options.backend = parse_backend(args.backend);
  viewer::ViewerServer server(options);
  std::cout << server.url() << std::endl;
  if (!server.loopback())
    std::cerr << "vri: warning: listening on " << args.host
              << ", beyond this machine: anyone who can reach it and has the token can see the listed volumes\n";
  if (args.open) open_browser(server.url());
  server.run();
  return 0;
}
#else
int run_view(const ViewArgs&) {
  throw Error("this vri was built without the viewer (it needs libboost-dev and libturbojpeg0-dev)");
}
#endif

}  // namespace

Runner add_view_command(CLI::App& app) {
  auto args = std::make_shared<ViewArgs>();
  CLI::App* cmd = app.add_subcommand("view", "Show a scene or volume in the browser (prints the address to open)");
  cmd->add_option("file", args->file, "Scene JSON or volume file (default: the bundled scenes)");
  cmd->add_option("--host", args->host, "Address to listen on (default 127.0.0.1; another one is reachable from the network)");
  cmd->add_option("--port", args->port, "Port (default 8765; 0: a free one)");
  cmd->add_flag("--open", args->open, "Open the address in the desktop's browser");
  cmd->add_option("--threads", args->threads, "Render threads per client (0: all cores)");
  cmd->add_option("--backend", args->backend, "cpu (default) or vulkan: render the frames on a Vulkan device");
  return [args] { return run_view(*args); };
}

}  // namespace vri::cli
