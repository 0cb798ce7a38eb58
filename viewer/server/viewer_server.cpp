#include "viewer_server.hpp"

#include <boost/asio/io_context.hpp>
#include <boost/asio/ip/tcp.hpp>
#include <boost/asio/post.hpp>
#include <boost/asio/signal_set.hpp>

#include <csignal>

#include "access_token.hpp"
#include "client_session.hpp"
#include "http_session.hpp"
#include "server_state.hpp"
#include "vri/core/error.hpp"

namespace vri::viewer {

namespace net = boost::asio;
using tcp = net::ip::tcp;

struct ViewerServer::Impl {
  ServerState state;  // first: outlives the sessions, which die with the io_context's handlers
  net::io_context io{1};
  tcp::acceptor acceptor{io};
  net::signal_set signals{io};
  bool stopping = false;

  Impl(const ServerOptions& o)
      : state{make_token(), o.host, 0, DatasetCatalog(o.file, o.bundled_dir), o.threads, o.backend, {}, {}} {}

  void accept() {
    acceptor.async_accept([this](boost::system::error_code ec, tcp::socket socket) {
      if (ec) return;  // closed by stop()
      // Frames leave at once: Nagle's algorithm with the browser's delayed
      // ACK held the tail of each frame back 40 ms.
      boost::system::error_code ignored;
      socket.set_option(tcp::no_delay(true), ignored);
      std::make_shared<HttpSession>(std::move(socket), state)->run();
      accept();
    });
  }

  // On the I/O thread: no new connections, every WebSocket closed, the loop ended.
  void shut_down() {
    if (stopping) return;
    stopping = true;
    boost::system::error_code ignored;
    acceptor.close(ignored);
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
  // The loop has ended: no handler runs now. Stop every worker before the
  // sessions, and the I/O objects they post to, are destroyed.
  std::lock_guard lock(impl_->state.sessions_mutex);
  for (const auto& weak : impl_->state.sessions)
    if (auto s = weak.lock()) s->stop_worker();
}

void ViewerServer::stop() {
  net::post(impl_->io, [m = impl_.get()] { m->shut_down(); });
}

}  // namespace vri::viewer
