// The server over real sockets: the token on every request, the WebSocket's
// origin, a malformed message answered without ending the session, frames
// for several clients at once, a client vanishing mid-frame, and stop().
#include "server_fixture.hpp"

namespace vri::viewer {
namespace {

using namespace server_testing;  // the fixture, and the names of Beast and Asio it uses

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
