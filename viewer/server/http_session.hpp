#pragma once
// HttpSession: one HTTP connection to the viewer. Answers GET and HEAD for
// the page's files (400 for a Host that is not this machine's, 403 without
// the token, 404 for other paths, 405 for other methods) and hands a checked
// WebSocket upgrade on /ws to a ClientSession (503 over kMaxSessions).
#include <boost/beast/core.hpp>
#include <boost/beast/http.hpp>

#include <memory>
#include <optional>

#include "server_state.hpp"

namespace vri::viewer {

class HttpSession : public std::enable_shared_from_this<HttpSession> {
 public:
  HttpSession(boost::asio::ip::tcp::socket&& socket, ServerState& state);
  ~HttpSession();
  void run();

 private:
  void read();
  void on_read(boost::beast::error_code ec);
  void respond(boost::beast::http::response<boost::beast::http::string_body> response, bool head = false);

  boost::beast::tcp_stream stream_;
  boost::beast::flat_buffer buffer_;
  std::optional<boost::beast::http::request_parser<boost::beast::http::empty_body>> parser_;
  ServerState& state_;
};

}  // namespace vri::viewer
