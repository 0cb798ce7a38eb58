#include "client_session.hpp"

#include <boost/asio/post.hpp>

#include <algorithm>

#include "server_limits.hpp"
#include "vri/error.hpp"

namespace vri::viewer {

namespace beast = boost::beast;
namespace websocket = beast::websocket;
namespace net = boost::asio;

ClientSession::ClientSession(net::ip::tcp::socket&& socket, ServerState& state)
    : ws_(std::move(socket)), state_(state) {}

ClientSession::~ClientSession() { retire_worker(); }

void ClientSession::retire_worker() { state_.reaper.retire(std::move(worker_)); }

void ClientSession::run(beast::http::request<beast::http::empty_body> request) {
  ws_.set_option(websocket::stream_base::timeout::suggested(beast::role_type::server));
  ws_.read_message_max(kMaxMessageBytes);
  ws_.async_accept(request, [self = shared_from_this()](beast::error_code ec) { self->on_accept(ec); });
}

void ClientSession::on_accept(beast::error_code ec) {
  if (ec) return;
  // The worker never holds the session: it posts to the I/O thread, which
  // finds the session if it still lives.
  std::weak_ptr<ClientSession> weak = weak_from_this();
  auto executor = ws_.get_executor();
  WorkerOutput output{
      [weak, executor](std::string text) {
        net::post(executor, [weak, data = std::make_shared<const std::string>(std::move(text))] {
          if (auto self = weak.lock()) self->enqueue({false, -1, data});
        });
      },
      [weak, executor](std::int64_t seq, std::vector<std::byte> frame) {
        auto data = std::make_shared<const std::string>(reinterpret_cast<const char*>(frame.data()), frame.size());
        net::post(executor, [weak, seq, data] {
          if (auto self = weak.lock()) self->enqueue({true, seq, data});
        });
      }};
  worker_ = std::make_unique<RenderWorker>(state_.catalog, state_.catalog.first_id(), std::move(output),
                                           state_.threads, state_.backend, state_.page_memory);
  read();
}

void ClientSession::read() {
  reading_ = true;
  ws_.async_read(buffer_, [self = shared_from_this()](beast::error_code ec, std::size_t n) { self->on_read(ec, n); });
}

void ClientSession::read_if_room() {
  if (!reading_ && worker_ && queued_bytes_ <= kMaxQueuedBytes) read();
}

void ClientSession::on_read(beast::error_code ec, std::size_t) {
  reading_ = false;
  if (ec) {  // closed, vanished, or a message over the limit: end the session, cancel its work
    retire_worker();
    return;
  }
  const std::string text = beast::buffers_to_string(buffer_.data());
  buffer_.consume(buffer_.size());
  if (!ws_.got_text()) {
    enqueue({false, -1, std::make_shared<const std::string>(error_message(-1, "binary messages are not accepted"))});
  } else {
    try {
      worker_->submit(parse_client_message(text));
    } catch (const Error& e) {
      enqueue({false, -1, std::make_shared<const std::string>(error_message(seq_of(text), e.what()))});
    }
  }
  read_if_room();  // else the next write that leaves room reads on
}

void ClientSession::enqueue(Outgoing message) {
  if (message.binary) {
    // A frame of an older request than this one will not be seen: drop it
    // unless it is already leaving (the front, while writing).
    const auto first = queue_.begin() + (writing_ ? 1 : 0);
    const auto is_stale = [&](const Outgoing& q) { return q.binary && q.seq < message.seq; };
    // Counted before remove_if, which leaves the tail's elements moved from.
    for (auto it = first; it != queue_.end(); ++it)
      if (is_stale(*it)) queued_bytes_ -= it->data->size();
    queue_.erase(std::remove_if(first, queue_.end(), is_stale), queue_.end());
  }
  queued_bytes_ += message.data->size();
  queue_.push_back(std::move(message));
  if (!writing_) write_next();
}

void ClientSession::pop_front() {
  queued_bytes_ -= queue_.front().data->size();
  queue_.pop_front();
}

void ClientSession::write_next() {
  if (queue_.empty()) return;
  writing_ = true;
  ws_.binary(queue_.front().binary);
  ws_.async_write(net::buffer(*queue_.front().data), [self = shared_from_this()](beast::error_code ec, std::size_t) {
    self->writing_ = false;
    self->pop_front();
    if (ec) return;
    self->read_if_room();
    self->write_next();
  });
}

void ClientSession::close() {
  beast::error_code ignored;
  beast::get_lowest_layer(ws_).socket().shutdown(net::ip::tcp::socket::shutdown_both, ignored);
  beast::get_lowest_layer(ws_).socket().close(ignored);
}

}  // namespace vri::viewer
