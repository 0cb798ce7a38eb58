// The server over real sockets: the token on every request, the WebSocket's
// origin, a malformed message answered without ending the session, frames
// for several clients at once, a client vanishing mid-frame, and stop().
#include "viewer_server.hpp"

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

namespace vri::viewer {
namespace {

namespace beast = boost::beast;
namespace http = beast::http;
namespace websocket = beast::websocket;
namespace net = boost::asio;
using tcp = net::ip::tcp;
using nlohmann::json;

const std::filesystem::path kRoot = VRI_SOURCE_DIR;

struct ServerFixture : ::testing::Test {
  ServerFixture() : server(options()), thread([this] { server.run(); }) {}
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

  http::response<http::string_body> get(const std::string& target, http::verb verb = http::verb::get,
                                        const std::string& cookie = "") {
    net::io_context io;
    beast::tcp_stream stream(io);
    stream.connect(tcp::endpoint(net::ip::make_address("127.0.0.1"), server.port()));
    http::request<http::string_body> req{verb, target, 11};
    req.set(http::field::host, host());
    if (!cookie.empty()) req.set(http::field::cookie, cookie);
    req.prepare_payload();
    http::write(stream, req);
    beast::flat_buffer buffer;
    http::response<http::string_body> res;
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

TEST_F(ServerFixture, EveryRequestNeedsTheToken) {
  EXPECT_EQ(get("/").result(), http::status::forbidden);
  EXPECT_EQ(get("/viewer.js").result(), http::status::forbidden);
  EXPECT_EQ(get("/?token=" + std::string(32, '0')).result(), http::status::forbidden);
  const auto page = get("/?token=" + server.token());
  EXPECT_EQ(page.result(), http::status::ok);
  EXPECT_NE(page.body().find("<html"), std::string::npos);
  const std::string cookie(page[http::field::set_cookie]);
  EXPECT_NE(cookie.find("vri_token=" + server.token()), std::string::npos);
  EXPECT_NE(cookie.find("HttpOnly"), std::string::npos);
  // The page's scripts come with the cookie alone.
  const auto script = get("/viewer.js", http::verb::get, "vri_token=" + server.token());
  EXPECT_EQ(script.result(), http::status::ok);
  EXPECT_EQ(script[http::field::content_type], "text/javascript; charset=utf-8");
  EXPECT_EQ(get("/missing.js?token=" + server.token()).result(), http::status::not_found);
  EXPECT_EQ(get("/../etc/passwd?token=" + server.token()).result(), http::status::not_found);
  EXPECT_EQ(get("/?token=" + server.token(), http::verb::post).result(), http::status::method_not_allowed);
  EXPECT_EQ(server.url(), "http://127.0.0.1:" + std::to_string(server.port()) + "/?token=" + server.token());
  EXPECT_TRUE(server.loopback());
}

TEST_F(ServerFixture, WebSocketNeedsTheTokenAndItsOwnOrigin) {
  net::io_context io;
  EXPECT_THROW(connect(io, "wrong", "http://" + host()), boost::system::system_error);
  EXPECT_THROW(connect(io, server.token(), "http://evil.example"), boost::system::system_error);
  auto ws = connect(io, server.token(), "http://" + host());
  EXPECT_EQ(receive(*ws)["type"], "welcome");
}

TEST_F(ServerFixture, MalformedMessagesGetAnErrorAndTheSessionGoesOn) {
  net::io_context io;
  auto ws = connect(io, server.token(), "http://" + host());
  const json welcome = receive(*ws);
  ws->text(true);
  ws->write(net::buffer(std::string(R"({"type":"render","seq":"x"})")));
  json reply = receive(*ws);
  EXPECT_EQ(reply["type"], "error");
  ws->write(net::buffer(std::string("not json at all")));
  EXPECT_EQ(receive(*ws)["message"], "message is not JSON");
  ws->binary(true);
  ws->write(net::buffer(std::string("\x01\x02")));
  EXPECT_EQ(receive(*ws)["message"], "binary messages are not accepted");
  ws->text(true);
  ws->write(net::buffer(render(welcome["scene"], 3)));
  bool binary = false;
  const json frame = receive(*ws, &binary);
  EXPECT_TRUE(binary);
  EXPECT_EQ(frame["stage"], "final");
  EXPECT_EQ(frame["seq"], 3);
}

TEST_F(ServerFixture, OversizedMessageEndsOnlyThatSession) {
  net::io_context io;
  auto bad = connect(io, server.token(), "http://" + host());
  auto good = connect(io, server.token(), "http://" + host());
  receive(*bad);
  const json welcome = receive(*good);
  bad->text(true);
  beast::error_code ec;
  bad->write(net::buffer(std::string(kMaxMessageBytes + 10, ' ')), ec);
  beast::flat_buffer buffer;
  bad->read(buffer, ec);  // the server closes it
  EXPECT_TRUE(ec);
  good->text(true);
  good->write(net::buffer(render(welcome["scene"], 1)));
  EXPECT_EQ(receive(*good)["stage"], "final");
}

TEST_F(ServerFixture, SeveralClientsAndOneVanishingMidFrame) {
  net::io_context io;
  std::vector<std::unique_ptr<websocket::stream<tcp::socket>>> clients;
  for (int i = 0; i < 3; ++i) clients.push_back(connect(io, server.token(), "http://" + host()));
  json scene;
  for (auto& c : clients) scene = receive(*c)["scene"];
  // The first asks for a large frame and vanishes without a close.
  clients[0]->text(true);
  clients[0]->write(net::buffer(render(scene, 1, 1024)));
  clients[0]->next_layer().close();
  for (int i = 1; i < 3; ++i) {
    clients[i]->text(true);
    clients[i]->write(net::buffer(render(scene, 10 + i)));
  }
  for (int i = 1; i < 3; ++i) {
    const json f = receive(*clients[i]);
    EXPECT_EQ(f["seq"], 10 + i);
  }
}

}  // namespace
}  // namespace vri::viewer
