// The server's limits (server_limits.hpp, docs/RELIABILITY.md), each against
// the way it was broken (issue 47): running out of file descriptors, a page
// closed mid table build, a client that never reads, too many pages, a page's
// memory, the Host header of another name, HEAD.
#include <sys/resource.h>

#include <filesystem>

#include "server_fixture.hpp"
#include "server_limits.hpp"

namespace vri::viewer {
namespace {

using namespace server_testing;  // the fixture, and the names of Beast and Asio it uses

int open_descriptors() {
  return int(std::distance(std::filesystem::directory_iterator("/proc/self/fd"), {}));
}

TEST_F(ServerFixture, AcceptsAgainAfterRunningOutOfFileDescriptors) {
  rlimit old{};
  ASSERT_EQ(getrlimit(RLIMIT_NOFILE, &old), 0);
  rlimit low = old;
  low.rlim_cur = rlim_t(open_descriptors() + 24);
  ASSERT_EQ(setrlimit(RLIMIT_NOFILE, &low), 0);
  // Connect until this process (client and server alike) has no descriptor left.
  net::io_context io;
  std::vector<std::unique_ptr<tcp::socket>> clients;
  for (int i = 0; i < 200; ++i) {
    auto s = std::make_unique<tcp::socket>(io);
    boost::system::error_code ec;
    s->connect(tcp::endpoint(net::ip::make_address("127.0.0.1"), server.port()), ec);
    if (ec) break;
    clients.push_back(std::move(s));
  }
  std::this_thread::sleep_for(std::chrono::milliseconds(300));  // the server's accept fails meanwhile
  clients.clear();
  ASSERT_EQ(setrlimit(RLIMIT_NOFILE, &old), 0);
  EXPECT_EQ(get("/?token=" + server.token()).result(), http::status::ok);  // within the 20 s of get()
}

TEST_F(ServerFixture, AnotherHostNameIsRefusedAndHeadAnswersLikeGet) {
  const std::string page = "/?token=" + server.token();
  EXPECT_EQ(get(page, http::verb::get, "", "evil.example:" + std::to_string(server.port())).result(),
            http::status::bad_request);
  EXPECT_EQ(get(page, http::verb::get, "", "").result(), http::status::ok);
  EXPECT_EQ(get(page, http::verb::get, "", "localhost:9000").result(), http::status::ok);  // a tunnel's port
  EXPECT_EQ(get(page, http::verb::get, "", "[::1]:80").result(), http::status::ok);
  const auto full = get(page);
  const auto head = get(page, http::verb::head);
  EXPECT_EQ(head.result(), http::status::ok);
  EXPECT_EQ(head[http::field::content_length], std::to_string(full.body().size()));
  EXPECT_EQ(head[http::field::content_type], full[http::field::content_type]);
  EXPECT_EQ(get(page, http::verb::put).result(), http::status::method_not_allowed);
}

TEST_F(ServerFixture, PagesOverTheCapAreRefusedAndTheOthersServed) {
  net::io_context io;
  std::vector<std::unique_ptr<websocket::stream<tcp::socket>>> pages;
  for (int i = 0; i < kMaxSessions; ++i) pages.push_back(connect(io, server.token(), "http://" + host()));
  try {
    connect(io, server.token(), "http://" + host());
    FAIL() << "page " << kMaxSessions + 1 << " was let in";
  } catch (const boost::system::system_error&) {
  }
  const json welcome = receive(*pages.back());
  pages.back()->text(true);
  pages.back()->write(net::buffer(render(welcome["scene"], 1)));
  EXPECT_EQ(receive(*pages.back())["stage"], "final");
  pages.front()->close(websocket::close_code::normal);
  for (int tries = 0;; ++tries) {  // the closed page's place frees as the server sees it go
    try {
      connect(io, server.token(), "http://" + host());
      break;
    } catch (const boost::system::system_error&) {
      ASSERT_LT(tries, 100) << "a closed page's place never came free";
      std::this_thread::sleep_for(std::chrono::milliseconds(50));
    }
  }
}

// Error replies that quote the client's bytes, asked for without reading one:
// the server stops reading the client once kMaxQueuedBytes wait, so the
// client's writes stall long before it has sent 4 x that.
TEST_F(ServerFixture, AClientThatNeverReadsCannotGrowTheServer) {
  net::io_context io;
  auto ws = connect(io, server.token(), "http://" + host());
  ws->text(true);
  const std::string message = R"({"type":")" + std::string(1000, 'x') + R"("})";
  const std::size_t most = 4 * kMaxQueuedBytes / message.size();
  std::size_t sent = 0;
  bool stalled = false;
  std::function<void()> send = [&] {
    ws->async_write(net::buffer(message), [&](beast::error_code ec, std::size_t) {
      if (ec) return;
      if (++sent < most) send();
    });
  };
  send();
  for (;;) {
    const std::size_t before = sent;
    io.run_for(std::chrono::seconds(3));
    if (sent >= most) break;
    if (sent == before) {
      stalled = true;
      break;
    }
  }
  EXPECT_TRUE(stalled) << sent << " messages of " << message.size() << " bytes went in without a reply read";
  EXPECT_EQ(get("/?token=" + server.token()).result(), http::status::ok);  // the others are served meanwhile
  beast::get_lowest_layer(*ws).close();
}

// preint2 with a table of 400 and 4096 iterations builds for minutes; the
// page leaves mid build. The worker is joined off the I/O thread and its
// build cancelled: another page's frame and a GET come at once, and the
// server stops within seconds (the fixture's destructor).
TEST_F(ServerFixture, APageLeavingMidTableBuildFreezesNothing) {
  net::io_context io;
  auto leaving = connect(io, server.token(), "http://" + host());
  auto staying = connect(io, server.token(), "http://" + host());
  json scene = receive(*leaving)["scene"];
  receive(*staying);
  json heavy = scene;
  heavy["method"] = {{"name", "preint2"}, {"table_size", 400}, {"iterations", 4096}};
  leaving->text(true);
  leaving->write(net::buffer(render(heavy, 1)));
  std::this_thread::sleep_for(std::chrono::milliseconds(500));
  leaving->next_layer().close();
  std::this_thread::sleep_for(std::chrono::milliseconds(200));
  const auto start = std::chrono::steady_clock::now();
  EXPECT_EQ(get("/?token=" + server.token()).result(), http::status::ok);
  staying->text(true);
  staying->write(net::buffer(render(scene, 2)));
  EXPECT_EQ(receive(*staying)["stage"], "final");
  EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(20));
}

// With 64 MiB a page, a 4096 x 4096 frame (256 MiB of floats) is refused
// before it is rendered, and the page goes on with a smaller one.
struct SmallPages : ServerFixture {
  SmallPages() : ServerFixture(with_page_memory()) {}
  static ServerOptions with_page_memory() {
    ServerOptions o = options();
    o.page_memory = std::uint64_t{64} << 20;
    return o;
  }
};

TEST_F(SmallPages, APageOverItsMemoryGetsAnError) {
  net::io_context io;
  auto ws = connect(io, server.token(), "http://" + host());
  const json scene = receive(*ws)["scene"];
  ws->text(true);
  ws->write(net::buffer(render(scene, 1, 4096)));
  const json reply = receive(*ws);
  EXPECT_EQ(reply["type"], "error");
  EXPECT_NE(reply["message"].get<std::string>().find("over the viewer's memory for one page of 64 MiB"),
            std::string::npos)
      << reply.dump();
  ws->write(net::buffer(render(scene, 2, 256)));
  EXPECT_EQ(receive(*ws)["stage"], "final");
}

}  // namespace
}  // namespace vri::viewer
