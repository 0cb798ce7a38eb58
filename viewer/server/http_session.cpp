#include "http_session.hpp"

#include <boost/asio/dispatch.hpp>
#include <boost/beast/websocket.hpp>

#include <chrono>
#include <string>

#include "access_token.hpp"
#include "client_session.hpp"
#include "embedded_files.hpp"
#include "host_check.hpp"
#include "server_limits.hpp"
#include "vri/version.hpp"

namespace vri::viewer {

namespace beast = boost::beast;
namespace http = beast::http;
namespace net = boost::asio;

namespace {

using Response = http::response<http::string_body>;

Response text_response(http::status status, unsigned version, const std::string& text) {
  Response r{status, version};
  r.set(http::field::content_type, "text/plain; charset=utf-8");
  r.body() = text + "\n";
  return r;
}

// The WebSocket must come from the page itself: its Origin is the address the page was loaded from.
bool same_origin(const http::request<http::empty_body>& req) {
  const std::string origin(req[http::field::origin]), host(req[http::field::host]);
  return !host.empty() && origin == "http://" + host;
}

}  // namespace

HttpSession::HttpSession(net::ip::tcp::socket&& socket, ServerState& state)
    : stream_(std::move(socket)), state_(state) {
  ++state_.connections;
}

HttpSession::~HttpSession() { --state_.connections; }

void HttpSession::run() {
  net::dispatch(stream_.get_executor(), [self = shared_from_this()] { self->read(); });
}

void HttpSession::read() {
  parser_.emplace();
  parser_->header_limit(16 * 1024);
  parser_->body_limit(0);  // GET only: no request has a body
  stream_.expires_after(std::chrono::seconds(30));
  http::async_read(stream_, buffer_, *parser_,
                   [self = shared_from_this()](beast::error_code ec, std::size_t) { self->on_read(ec); });
}

void HttpSession::on_read(beast::error_code ec) {
  if (ec) {  // end of stream, timeout, or a request over the limits: close
    beast::error_code ignored;
    stream_.socket().shutdown(net::ip::tcp::socket::shutdown_send, ignored);
    return;
  }
  http::request<http::empty_body> req = parser_->release();
  const unsigned version = req.version();
  const std::string target(req.target());
  const std::string_view path = path_of(target);
  const bool head = req.method() == http::verb::head;
  if (req.method() != http::verb::get && !head) {
    Response r = text_response(http::status::method_not_allowed, version, "only GET and HEAD");
    r.set(http::field::allow, "GET, HEAD");
    return respond(std::move(r));
  }
  if (!allowed_host(std::string(req[http::field::host]), state_.host))
    return respond(text_response(http::status::bad_request, version,
                                 "vri view: the Host header must be this machine's address or name"),
                   head);
  const std::string given = token_of(target, std::string(req[http::field::cookie]));
  if (!same_token(given, state_.token))
    return respond(text_response(http::status::forbidden, version,
                                 "vri view: this needs the access token (open the address vri view printed)"),
                   head);
  if (path == "/ws") {
    if (!beast::websocket::is_upgrade(req))
      return respond(text_response(http::status::bad_request, version, "/ws is a WebSocket"));
    if (!same_origin(req))
      return respond(text_response(http::status::forbidden, version, "vri view: WebSocket from another origin"));
    std::shared_ptr<ClientSession> session;
    {
      std::lock_guard lock(state_.sessions_mutex);
      std::erase_if(state_.sessions, [](const auto& w) { return w.expired(); });
      if (state_.sessions.size() >= std::size_t(kMaxSessions))
        return respond(text_response(http::status::service_unavailable, version,
                                     "vri view: " + std::to_string(kMaxSessions) +
                                         " pages are open already, the most at once: close one"));
      stream_.expires_never();
      session = std::make_shared<ClientSession>(stream_.release_socket(), state_);
      state_.sessions.push_back(session);
    }
    session->run(std::move(req));
    return;
  }
  const std::string_view name = path == "/" ? std::string_view("index.html") : path.substr(1);
  for (const EmbeddedFile& f : web_files()) {
    if (f.name != name) continue;
    Response r{http::status::ok, version};
    r.set(http::field::content_type, std::string(content_type(name)));
    r.set(http::field::cache_control, "no-store");
    r.set(http::field::server, std::string("vri/") + kVersion);
    r.set("X-Content-Type-Options", "nosniff");
    r.set("Content-Security-Policy",
          "default-src 'self'; connect-src 'self' ws: ; img-src 'self' blob: data:; style-src 'self' 'unsafe-inline'");
    // The page's scripts and socket then carry the token without it in every URL.
    if (path == "/")
      r.set(http::field::set_cookie,
            std::string(kTokenCookie) + "=" + state_.token + "; HttpOnly; SameSite=Strict; Path=/");
    r.body() = std::string(f.content);
    r.keep_alive(req.keep_alive());
    return respond(std::move(r), head);
  }
  respond(text_response(http::status::not_found, version, "not found"), head);
}

void HttpSession::respond(Response response, bool head) {
  response.prepare_payload();
  if (head) response.body().clear();  // the GET's headers, Content-Length included, and no body
  auto shared = std::make_shared<Response>(std::move(response));
  http::async_write(stream_, *shared, [self = shared_from_this(), shared](beast::error_code ec, std::size_t) {
    if (ec) return;
    if (!shared->keep_alive()) {
      beast::error_code ignored;
      self->stream_.socket().shutdown(net::ip::tcp::socket::shutdown_send, ignored);
      return;
    }
    self->read();
  });
}

}  // namespace vri::viewer
