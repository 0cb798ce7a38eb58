#pragma once
// ClientSession: one page's WebSocket. Reads the client's messages (size-
// limited, checked; a bad one gets an error reply and the session goes on),
// hands them to the client's RenderWorker, and writes what the worker sends
// back one message at a time, dropping frames a newer request has made stale
// before they leave. While more than kMaxQueuedBytes wait to leave (a client
// that does not read), it reads no more of the client's messages, so replies
// cannot pile up. A vanished client cancels its work; the worker is joined
// off the I/O thread (WorkerReaper).
#include <boost/beast/core.hpp>
#include <boost/beast/http.hpp>
#include <boost/beast/websocket.hpp>

#include <cstdint>
#include <deque>
#include <memory>
#include <string>
#include <vector>

#include "render_worker.hpp"
#include "server_state.hpp"

namespace vri::viewer {

class ClientSession : public std::enable_shared_from_this<ClientSession> {
 public:
  ClientSession(boost::asio::ip::tcp::socket&& socket, ServerState& state);
  ~ClientSession();

  // Accepts the upgrade request (already checked for token and origin).
  void run(boost::beast::http::request<boost::beast::http::empty_body> request);
  // Closes the connection (server stop); on the I/O thread.
  void close();
  // Cancels the render worker's work and hands it to the server's reaper.
  void retire_worker();

 private:
  struct Outgoing {
    bool binary;
    std::int64_t seq;  // frames: the request they answer
    std::shared_ptr<const std::string> data;
  };

  void on_accept(boost::beast::error_code ec);
  void read();
  void on_read(boost::beast::error_code ec, std::size_t bytes);
  void enqueue(Outgoing message);
  void pop_front();
  void read_if_room();
  void write_next();

  boost::beast::websocket::stream<boost::beast::tcp_stream> ws_;
  boost::beast::flat_buffer buffer_;
  ServerState& state_;
  std::unique_ptr<RenderWorker> worker_;
  std::deque<Outgoing> queue_;
  std::size_t queued_bytes_ = 0;
  bool writing_ = false;
  bool reading_ = false;  // a read is in flight
};

}  // namespace vri::viewer
