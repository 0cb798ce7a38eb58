#pragma once
// A viewer server on a free port of 127.0.0.1 serving neghip, run on a
// thread of the test, and clients for it over real sockets.
#include <gtest/gtest.h>

#include <boost/asio/connect.hpp>
#include <boost/asio/ip/tcp.hpp>
#include <boost/beast/core.hpp>
#include <boost/beast/http.hpp>
#include <boost/beast/websocket.hpp>

#include <chrono>
#include <nlohmann/json.hpp>
#include <thread>

#include "protocol.hpp"
#include "viewer_server.hpp"

namespace vri::viewer::server_testing {

namespace beast = boost::beast;
namespace http = beast::http;
namespace websocket = beast::websocket;
namespace net = boost::asio;
using tcp = net::ip::tcp;
using nlohmann::json;

const std::filesystem::path kRoot = VRI_SOURCE_DIR;

struct ServerFixture : ::testing::Test {
  ServerFixture() : ServerFixture(options()) {}
  explicit ServerFixture(ServerOptions o) : server(std::move(o)), thread([this] { server.run(); }) {}
  ~ServerFixture() override {
    server.stop();
    thread.join();
  }
  static ServerOptions options() {
    ServerOptions o;
    o.port = 0;
    o.file = kRoot / "scenes/neghip.json";
    o.bundled_dir = kRoot / "scenes";
    o.threads = 1;
    o.handle_signals = false;
    return o;
  }
  std::string host() const { return "127.0.0.1:" + std::to_string(server.port()); }

  // A request and its response; throws if none comes within 20 s.
  http::response<http::string_body> get(const std::string& target, http::verb verb = http::verb::get,
                                        const std::string& cookie = "", const std::string& host_header = "") {
    net::io_context io;
    beast::tcp_stream stream(io);
    stream.expires_after(std::chrono::seconds(20));
    stream.connect(tcp::endpoint(net::ip::make_address("127.0.0.1"), server.port()));
    http::request<http::string_body> req{verb, target, 11};
    req.set(http::field::host, host_header.empty() ? host() : host_header);
    if (!cookie.empty()) req.set(http::field::cookie, cookie);
    req.prepare_payload();
    http::write(stream, req);
    beast::flat_buffer buffer;
    http::response<http::string_body> res;
    if (verb == http::verb::head) {  // a HEAD's response says Content-Length but has no body
      http::response_parser<http::string_body> parser;
      parser.skip(true);
      http::read(stream, buffer, parser);
      return parser.release();
    }
    http::read(stream, buffer, res);
    return res;
  }

  // A WebSocket to /ws with the given token and origin; throws if the handshake is refused.
  std::unique_ptr<websocket::stream<tcp::socket>> connect(net::io_context& io, const std::string& token,
                                                          const std::string& origin) {
    auto ws = std::make_unique<websocket::stream<tcp::socket>>(io);
    ws->next_layer().connect(tcp::endpoint(net::ip::make_address("127.0.0.1"), server.port()));
    ws->set_option(websocket::stream_base::decorator(
        [origin](websocket::request_type& req) { req.set(http::field::origin, origin); }));
    ws->handshake(host(), "/ws?token=" + token);
    return ws;
  }
  // The next message: JSON for text, the header for a binary frame.
  static json receive(websocket::stream<tcp::socket>& ws, bool* binary = nullptr) {
    beast::flat_buffer buffer;
    ws.read(buffer);
    const std::string data = beast::buffers_to_string(buffer.data());
    if (binary) *binary = ws.got_binary();
    if (!ws.got_binary()) return json::parse(data);
    const auto n = std::uint32_t(std::uint8_t(data[0])) | std::uint32_t(std::uint8_t(data[1])) << 8 |
                   std::uint32_t(std::uint8_t(data[2])) << 16 | std::uint32_t(std::uint8_t(data[3])) << 24;
    return json::parse(data.substr(4, n));
  }
  static std::string render(const json& scene, int seq, int size = 64) {
    json s = scene;
    s["camera"]["width"] = size;
    s["camera"]["height"] = size;
    return json{{"type", "render"}, {"seq", seq}, {"quality", "final"}, {"scene", s}}.dump();
  }

  ViewerServer server;
  std::thread thread;
};

}  // namespace vri::viewer::server_testing
