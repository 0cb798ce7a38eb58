#include "viewer_server.hpp"

#include <boost/asio/io_context.hpp>
#include <boost/asio/ip/tcp.hpp>
#include <boost/asio/post.hpp>
#include <boost/asio/signal_set.hpp>
#include <boost/asio/steady_timer.hpp>

#include <csignal>
#include <cstdio>

#include "access_token.hpp"
#include "client_session.hpp"
#include "http_session.hpp"
#include "server_limits.hpp"
#include "server_state.hpp"
#include "vri/error.hpp"

namespace vri::viewer {

namespace net = boost::asio;
using tcp = net::ip::tcp;

struct ViewerServer::Impl {
  ServerState state;  // first: outlives the sessions, which die with the io_context's handlers
  net::io_context io{1};
  tcp::acceptor acceptor{io};
  net::signal_set signals{io};
  net::steady_timer accept_retry{io};
  bool stopping = false;
  bool accept_failing = false;  // said once per run of failures

  Impl(const ServerOptions& o)
      : state{make_token(), o.host, 0, DatasetCatalog(o.file, o.bundled_dir), o.threads, o.backend, o.page_memory, {}, {}, 0, {}} {}

  void accept() {
    acceptor.async_accept([this](boost::system::error_code ec, tcp::socket socket) {
      if (stopping) return;
      if (ec) {
        // Out of file descriptors (or another passing failure): say so once
        // and try again shortly; giving up here left the server deaf for good.
        if (!accept_failing)
          std::fprintf(stderr, "vri view: cannot accept a connection (%s); trying again every %lld ms\n",
                       ec.message().c_str(), static_cast<long long>(kAcceptRetry.count()));
        accept_failing = true;
        accept_retry.expires_after(kAcceptRetry);
        accept_retry.async_wait([this](boost::system::error_code e) {
          if (!e && !stopping) accept();
        });
        return;
      }
      if (accept_failing) std::fprintf(stderr, "vri view: accepting connections again\n");
      accept_failing = false;
      // Over the cap the socket is closed as it goes out of scope: the others keep being served.
      if (state.connections < kMaxConnections) {
        // Frames leave at once: Nagle's algorithm with the browser's delayed
        // ACK held the tail of each frame back 40 ms.
        boost::system::error_code ignored;
        socket.set_option(tcp::no_delay(true), ignored);
        std::make_shared<HttpSession>(std::move(socket), state)->run();
      }
      accept();
    });
  }

  // On the I/O thread: no new connections, every WebSocket closed, the loop ended.
  void shut_down() {
    if (stopping) return;
    stopping = true;
    boost::system::error_code ignored;
    acceptor.close(ignored);
    accept_retry.cancel();
    signals.cancel(ignored);
    std::lock_guard lock(state.sessions_mutex);
    for (const auto& weak : state.sessions)
      if (auto s = weak.lock()) s->close();
    io.stop();
  }
};

ViewerServer::ViewerServer(ServerOptions options) : impl_(std::make_unique<Impl>(options)) {
  Impl& m = *impl_;
  m.state.catalog.open(m.state.catalog.first_id());  // a file that cannot be read fails before the address is printed
  boost::system::error_code ec;
  tcp::resolver resolver(m.io);
  const auto endpoints = resolver.resolve(options.host, std::to_string(options.port), ec);
  if (ec || endpoints.empty()) throw Error("vri view: cannot resolve host '" + options.host + "': " + ec.message());
  const tcp::endpoint endpoint = endpoints.begin()->endpoint();
  m.acceptor.open(endpoint.protocol(), ec);
  if (!ec) m.acceptor.set_option(net::socket_base::reuse_address(true), ec);
  if (!ec) m.acceptor.bind(endpoint, ec);
  if (!ec) m.acceptor.listen(net::socket_base::max_listen_connections, ec);
  if (ec)
    throw Error("vri view: cannot listen on " + options.host + ":" + std::to_string(options.port) + ": " +
                ec.message());
  m.state.port = m.acceptor.local_endpoint().port();
  if (options.handle_signals) {
    m.signals.add(SIGINT);
    m.signals.add(SIGTERM);
    m.signals.async_wait([&m](boost::system::error_code ec, int) {
      if (!ec) m.shut_down();
    });
  }
  m.accept();
}

ViewerServer::~ViewerServer() = default;

unsigned short ViewerServer::port() const { return impl_->state.port; }
const std::string& ViewerServer::token() const { return impl_->state.token; }
bool ViewerServer::loopback() const { return impl_->acceptor.local_endpoint().address().is_loopback(); }

std::string ViewerServer::url() const {
  const std::string& h = impl_->state.host;
  const std::string host = h.find(':') != std::string::npos ? "[" + h + "]" : h;  // IPv6
  return "http://" + host + ":" + std::to_string(port()) + "/?token=" + token();
}

void ViewerServer::run() {
  impl_->io.run();
  // The loop has ended: no handler runs now. Stop every worker, and join
  // them, before the sessions and the I/O objects they post to are destroyed.
  {
    std::lock_guard lock(impl_->state.sessions_mutex);
    for (const auto& weak : impl_->state.sessions)
      if (auto s = weak.lock()) s->retire_worker();
  }
  impl_->state.reaper.drain();
}

void ViewerServer::stop() {
  net::post(impl_->io, [m = impl_.get()] { m->shut_down(); });
}

}  // namespace vri::viewer
