// viewer_soak VRI SCENE [--clients N] [--seconds S] [--seed K] [--max-memory-mb B] [--max-rss-mb M]
//
// The viewer under careless and hostile use for a while (issue 47): N
// clients (default 20) connect and leave, send valid and invalid messages,
// leave mid render, never read, hammer HTTP, for S seconds (default 600; the
// test command runs a short one). Checks, printed and in the exit status:
//  - every reply a client waits for comes (30 s at most), and a probe's GET
//    is answered every second (5 s at most): the server answers throughout;
//  - the server, run with `--max-memory B` (default 1024 MiB: what its tables
//    and images may hold together, docs/RELIABILITY.md), stays under M MiB
//    resident (default 1536: the budget and what it does not count);
//  - SIGTERM ends it within 20 s with status 0: no thread is left blocked.
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <boost/asio/ip/tcp.hpp>
#include <boost/beast/core.hpp>
#include <boost/beast/http.hpp>
#include <boost/beast/websocket.hpp>

#include <atomic>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <mutex>
#include <nlohmann/json.hpp>
#include <random>
#include <string>
#include <thread>
#include <vector>

extern char** environ;

namespace {

using Clock = std::chrono::steady_clock;
using json = nlohmann::json;
namespace net = boost::asio;
using tcp = net::ip::tcp;
namespace beast = boost::beast;
namespace http = beast::http;
namespace websocket = beast::websocket;

struct Server {
  pid_t pid = -1;
  unsigned short port = 0;
  std::string token;
};

std::atomic<long> g_actions{0}, g_replies{0}, g_refused{0}, g_failures{0};
std::mutex g_log_mutex;

void failure(const std::string& what) {
  ++g_failures;
  std::lock_guard lock(g_log_mutex);
  std::fprintf(stderr, "viewer_soak: FAILURE: %s\n", what.c_str());
}

Server start(const char* vri, const char* scene, long max_memory_mib) {
  int out[2];
  if (pipe(out) != 0) throw std::runtime_error("pipe");
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_adddup2(&actions, out[1], 1);
  posix_spawn_file_actions_addclose(&actions, out[0]);
  const std::string budget = std::to_string(max_memory_mib) + "M";
  const char* argv[] = {vri, "--max-memory", budget.c_str(), "view", scene, "--port", "0", "--threads", "1", nullptr};
  Server s;
  const int spawned = posix_spawn(&s.pid, vri, &actions, nullptr, const_cast<char**>(argv), environ);
  posix_spawn_file_actions_destroy(&actions);
  if (spawned != 0) throw std::runtime_error(std::string("cannot start ") + vri);
  close(out[1]);
  std::string line;
  char c;
  while (read(out[0], &c, 1) == 1 && c != '\n') line += c;
  close(out[0]);
  // http://127.0.0.1:PORT/?token=TOKEN
  const auto colon = line.rfind(':'), slash = line.find('/', colon), eq = line.find("token=");
  if (colon == std::string::npos || slash == std::string::npos || eq == std::string::npos)
    throw std::runtime_error("vri view printed '" + line + "', not its address");
  s.port = static_cast<unsigned short>(std::stoi(line.substr(colon + 1, slash - colon - 1)));
  s.token = line.substr(eq + 6);
  return s;
}

long rss_mib(pid_t pid) {
  std::ifstream in("/proc/" + std::to_string(pid) + "/status");
  std::string key;
  long kb = 0;
  while (in >> key) {
    if (key == "VmRSS:") {
      in >> kb;
      return kb / 1024;
    }
    in.ignore(1 << 20, '\n');
  }
  return 0;
}

// One HTTP request; the status, or 0 when no answer came within `seconds`.
int http_request(const Server& s, http::verb verb, const std::string& target, const std::string& host, int seconds) {
  try {
    net::io_context io;
    beast::tcp_stream stream(io);
    stream.expires_after(std::chrono::seconds(seconds));
    stream.connect(tcp::endpoint(net::ip::make_address("127.0.0.1"), s.port));
    http::request<http::empty_body> req{verb, target, 11};
    req.set(http::field::host, host);
    http::write(stream, req);
    beast::flat_buffer buffer;
    http::response_parser<http::string_body> parser;
    parser.body_limit(16 << 20);
    if (verb == http::verb::head) parser.skip(true);
    http::read(stream, buffer, parser);
    return parser.get().result_int();
  } catch (const std::exception&) {
    return 0;
  }
}

class Client {
 public:
  Client(const Server& server, std::uint64_t seed) : s_(server), rng_(seed) {}

  void run(Clock::time_point end) {
    while (Clock::now() < end) {
      ++g_actions;
      int pick = pick_in(0, 99);
      if (const char* only = std::getenv("SOAK_ONLY")) pick = std::atoi(only);
      try {
        if (pick < 45) page();
        else if (pick < 70) http_action();
        else if (pick < 80) raw_connection();
        else silent_page();
      } catch (const std::exception& e) {
        failure(std::string(pick < 45 ? "page: " : pick < 70 ? "http: " : pick < 80 ? "raw: " : "silent: ") + e.what());
      }
    }
  }

 private:
  int pick_in(int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng_); }
  std::string host() const { return "127.0.0.1:" + std::to_string(s_.port); }

  using Ws = websocket::stream<beast::tcp_stream>;
  // A page's socket, or null when the server refused it (sessions at the cap).
  std::unique_ptr<Ws> open_page(net::io_context& io) {
    auto ws = std::make_unique<Ws>(io);
    beast::get_lowest_layer(*ws).connect(tcp::endpoint(net::ip::make_address("127.0.0.1"), s_.port));
    ws->set_option(websocket::stream_base::timeout{std::chrono::seconds(30), std::chrono::seconds(30), false});
    const std::string origin = "http://" + host();
    ws->set_option(websocket::stream_base::decorator(
        [origin](websocket::request_type& r) { r.set(http::field::origin, origin); }));
    websocket::response_type res;
    beast::error_code ec;
    ws->handshake(res, host(), "/ws?token=" + s_.token, ec);
    if (ec == websocket::error::upgrade_declined) {  // 503: the pages are at the cap
      ++g_refused;
      std::this_thread::sleep_for(std::chrono::milliseconds(pick_in(10, 100)));  // as a page would retry
      return nullptr;
    }
    if (ec) {
      failure("handshake: " + ec.message());
      return nullptr;
    }
    return ws;
  }
  // The next text message or frame header; null json on a timeout or a closed socket.
  static json receive(Ws& ws) {
    beast::flat_buffer buffer;
    beast::error_code ec;
    ws.read(buffer, ec);
    if (ec) return json();
    const std::string data = beast::buffers_to_string(buffer.data());
    if (!ws.got_binary()) return json::parse(data, nullptr, false);
    if (data.size() < 4) return json();
    const std::uint32_t n = std::uint32_t(std::uint8_t(data[0])) | std::uint32_t(std::uint8_t(data[1])) << 8 |
                            std::uint32_t(std::uint8_t(data[2])) << 16 | std::uint32_t(std::uint8_t(data[3])) << 24;
    return json::parse(data.substr(4, n), nullptr, false);
  }
  // Waits for the reply to seq (a frame or an error; -1: an error without one).
  bool await(Ws& ws, std::int64_t seq) {
    for (;;) {
      const json m = receive(ws);
      if (m.is_null() || m.is_discarded()) return false;
      if (m.value("seq", std::int64_t{-2}) == seq && (m["type"] == "frame" || m["type"] == "error")) {
        ++g_replies;
        return true;
      }
    }
  }

  json render(const json& scene, std::int64_t seq) {
    json s = scene;
    const int size = pick_in(16, 160);
    s["camera"]["width"] = size;
    s["camera"]["height"] = size;
    static const char* methods[] = {"preint1", "preint2", "riemann", "adaptive", "exact"};
    s["method"] = {{"name", methods[pick_in(0, 4)]}};
    if (pick_in(0, 3) == 0) s["camera"]["eye"][0] = pick_in(-500, 500);
    json m = {{"type", "render"}, {"seq", seq}, {"quality", pick_in(0, 1) ? "final" : "preview"}, {"scene", s}};
    if (pick_in(0, 4) == 0) m["error_map"] = {{"enabled", true}};
    return m;
  }
  // A message the server must refuse with an error reply for seq (or -1).
  std::pair<std::string, std::int64_t> invalid(const json& scene, std::int64_t seq) {
    switch (pick_in(0, 7)) {
      case 0: return {"not json {", -1};
      case 1: return {json{{"type", "fly"}, {"seq", seq}}.dump(), seq};
      case 2: return {std::string(300, '[') + std::string(300, ']'), -1};
      case 3: {
        json m = render(scene, seq);
        m["scene"]["transfer_function"] = {{"file", "/etc/passwd"}};
        return {m.dump(), seq};
      }
      case 4: {
        json m = render(scene, seq);
        m["scene"]["camera"]["width"] = 5000;
        return {m.dump(), seq};
      }
      case 5: {
        json m = render(scene, seq);
        m["quality"] = 3;
        return {m.dump(), seq};
      }
      case 6: {
        json m = render(scene, seq);
        m["scene"]["method"] = {{"name", "preint2"}, {"table_size", -4}};
        return {m.dump(), seq};
      }
      default: return {json{{"type", "open"}, {"dataset", "../../etc/passwd"}}.dump(), -1};
    }
  }

  void page() {
    net::io_context io;
    auto ws = open_page(io);
    if (!ws) return;
    const json welcome = receive(*ws);
    if (!welcome.is_object() || welcome["type"] != "welcome") return failure("no welcome");
    const json scene = welcome["scene"];
    const int messages = pick_in(1, 8);
    int kind = -1;
    for (int i = 0; i < messages; ++i) {
      const std::int64_t seq = ++seq_;
      const int previous = kind;
      kind = pick_in(0, 9);
      ws->text(true);
      if (!beast::get_lowest_layer(*ws).socket().is_open())
        return failure("page closed after a message of kind " + std::to_string(previous));
      if (kind < 5) {
        beast::error_code wec;
        ws->write(net::buffer(render(scene, seq).dump()), wec);
        if (wec) return failure("a render could not be sent (" + wec.message() + ") after a message of kind " +
                                std::to_string(previous));
        if (pick_in(0, 9) == 0) break;  // leaves mid render
        if (!await(*ws, seq)) return failure("no frame for a render");
      } else if (kind < 9) {
        const auto [text, expect] = invalid(scene, seq);
        beast::error_code wec;
        ws->write(net::buffer(text), wec);
        if (wec) return failure("an invalid message could not be sent (" + wec.message() + ") after a message of kind " +
                                std::to_string(previous));
        if (!await(*ws, expect)) return failure("no error for " + text.substr(0, 60));
      } else {
        // Small: an error reply. Large (over the read limit): the server ends
        // the session as soon as it reads the header, so the rest of the write
        // may meet a closed socket (broken pipe, reset): that is the end asked for.
        const bool small = pick_in(0, 1) == 1;
        ws->binary(true);
        beast::error_code wec;
        ws->write(net::buffer(std::string(small ? 16 : 300 * 1024, 'b')), wec);
        if (small && wec) return failure("a small binary message could not be sent (" + wec.message() + ")");
        if (small && !await(*ws, -1)) return failure("no error for a binary message");
        break;
      }
    }
    beast::error_code ec;
    if (pick_in(0, 1)) ws->close(websocket::close_code::normal, ec);
    else beast::get_lowest_layer(*ws).close();
  }

  // Asks for many replies and reads none, then goes.
  void silent_page() {
    net::io_context io;
    auto ws = open_page(io);
    if (!ws) return;
    ws->text(true);
    const std::string bad = R"({"type":")" + std::string(900, 'q') + R"("})";
    beast::get_lowest_layer(*ws).expires_after(std::chrono::seconds(5));
    beast::error_code ec;
    for (int i = 0; i < 2000 && !ec; ++i) ws->write(net::buffer(bad), ec);
    beast::get_lowest_layer(*ws).close();
  }

  void http_action() {
    static const char* paths[] = {"/", "/viewer.js", "/ws", "/nope", "/../etc/passwd", "/style.css"};
    std::string target = paths[pick_in(0, 5)];
    if (pick_in(0, 3)) target += "?token=" + s_.token;
    const std::string h = pick_in(0, 5) == 0 ? "rebound.example" : host();
    const http::verb verb = pick_in(0, 4) == 0 ? http::verb::head : pick_in(0, 9) == 0 ? http::verb::post : http::verb::get;
    if (http_request(s_, verb, target, h, 10) == 0) failure("no answer to an HTTP request for " + target);
    else ++g_replies;
  }

  void raw_connection() {
    net::io_context io;
    tcp::socket socket(io);
    socket.connect(tcp::endpoint(net::ip::make_address("127.0.0.1"), s_.port));
    if (pick_in(0, 1)) {
      boost::system::error_code ec;
      net::write(socket, net::buffer(std::string(pick_in(1, 4000), char(pick_in(0, 255)))), ec);
    }
  }

  const Server& s_;
  std::mt19937_64 rng_;
  std::int64_t seq_ = 0;
};

}  // namespace

int main(int argc, char** argv) {
  if (argc < 3) {
    std::fprintf(stderr, "usage: viewer_soak VRI SCENE [--clients N] [--seconds S] [--seed K] [--max-memory-mb B] [--max-rss-mb M]\n");
    return 2;
  }
  int clients = 20, seconds = 600;
  long max_memory = 1024, max_rss = 1536;
  std::uint64_t seed = 1;
  for (int i = 3; i + 1 < argc; i += 2) {
    const std::string flag = argv[i];
    if (flag == "--clients") clients = std::atoi(argv[i + 1]);
    else if (flag == "--seconds") seconds = std::atoi(argv[i + 1]);
    else if (flag == "--seed") seed = std::strtoull(argv[i + 1], nullptr, 10);
    else if (flag == "--max-memory-mb") max_memory = std::atol(argv[i + 1]);
    else if (flag == "--max-rss-mb") max_rss = std::atol(argv[i + 1]);
    else return std::fprintf(stderr, "viewer_soak: unknown flag %s\n", flag.c_str()), 2;
  }
  signal(SIGPIPE, SIG_IGN);
  Server server;
  try {
    server = start(argv[1], argv[2], max_memory);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "viewer_soak: %s\n", e.what());
    return 2;
  }
  const auto end = Clock::now() + std::chrono::seconds(seconds);
  std::atomic<long> peak{0};
  std::atomic<bool> done{false};
  int ticks = 0;
  std::thread probe([&] {  // the server answers throughout, its memory stays bounded
    while (!done) {
      if (http_request(server, http::verb::get, "/?token=" + server.token, "localhost", 5) != 200)
        failure("the probe's GET was not answered within 5 s");
      const long rss = rss_mib(server.pid);
      peak = std::max(peak.load(), rss);
      if (++ticks % 10 == 0) std::printf("viewer_soak: %d s: RSS %ld MiB, %ld actions\n", ticks, rss, g_actions.load());
      std::this_thread::sleep_for(std::chrono::seconds(1));
    }
  });
  std::vector<std::thread> threads;
  for (int i = 0; i < clients; ++i)
    threads.emplace_back([&, i] { Client(server, seed * 1000 + i).run(end); });
  for (auto& t : threads) t.join();
  done = true;
  probe.join();
  // No thread left blocked: SIGTERM ends the server promptly and cleanly.
  kill(server.pid, SIGTERM);
  int status = 0;
  bool exited = false;
  for (int i = 0; i < 200 && !exited; ++i) {
    exited = waitpid(server.pid, &status, WNOHANG) == server.pid;
    if (!exited) std::this_thread::sleep_for(std::chrono::milliseconds(100));
  }
  if (!exited) {
    failure("the server did not stop within 20 s of SIGTERM");
    kill(server.pid, SIGKILL);
    waitpid(server.pid, &status, 0);
  } else if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) {
    failure("the server ended with status " + std::to_string(status));
  }
  if (peak > max_rss) failure("the server's memory reached " + std::to_string(peak.load()) + " MiB");
  std::printf("viewer_soak: %d clients, %d s: %ld actions, %ld replies, %ld pages refused at the cap, "
              "peak RSS %ld MiB (bound %ld), %ld failures\n",
              clients, seconds, g_actions.load(), g_replies.load(), g_refused.load(), peak.load(), max_rss,
              g_failures.load());
  return g_failures == 0 ? 0 : 1;
}
