#include "live/live_server.hpp"

#include "live/live_assets.hpp"
#include "tridem/error.hpp"

#include <boost/asio/ip/tcp.hpp>
#include <boost/asio/post.hpp>
#include <boost/asio/steady_timer.hpp>
#include <boost/beast/core.hpp>
#include <boost/beast/http.hpp>
#include <boost/beast/websocket.hpp>
#include <chrono>
#include <deque>
#include <fmt/format.h>
#include <map>
#include <thread>
#include <utility>

namespace tridem::live {

namespace asio = boost::asio;
namespace beast = boost::beast;
namespace http = beast::http;
namespace websocket = beast::websocket;
using tcp = asio::ip::tcp;

namespace {

/// A WebSocket message above this closes the connection unread (Beast refuses it); one
/// between kMaxCommandBytes and this is read and dropped with a log line.
constexpr std::size_t kMaxWebSocketMessage = 64 * 1024;
constexpr std::size_t kMaxRequestHeader = 8 * 1024;
constexpr std::size_t kMaxRequestBody = 1024;

class WsSession;

}  // namespace

struct LiveServer::Impl {
  Events& events;
  std::FILE* log;
  asio::io_context ioc{1};
  tcp::acceptor acceptor{ioc};
  std::map<int, std::shared_ptr<WsSession>> sessions;
  int next_id = 1;
  bool stopping = false;
  std::thread thread;

  Impl(Events& e, std::FILE* l) : events(e), log(l) {}
  void accept();
  template <class... Args>
  void say(fmt::format_string<Args...> format, Args&&... args) {
    if (!log) return;
    fmt::print(log, "live: {}\n", fmt::format(format, std::forward<Args>(args)...));
    std::fflush(log);
  }
};

namespace {

class WsSession : public std::enable_shared_from_this<WsSession> {
 public:
  WsSession(tcp::socket socket, LiveServer::Impl& server, int id)
      : ws_(std::move(socket)), server_(server), id_(id) {}

  void start(http::request<http::string_body> request) {
    // Kept by the session: the accept reads it until its handler runs.
    upgrade_ = std::move(request);
    beast::get_lowest_layer(ws_).expires_never();
    ws_.set_option(websocket::stream_base::timeout::suggested(beast::role_type::server));
    ws_.read_message_max(kMaxWebSocketMessage);
    // A frame goes out as one WebSocket frame, in one write: Beast's default splits
    // messages into frames of 4 KiB, some 5000 writes for a frame of 10^6 triangles.
    ws_.auto_fragment(false);
    ws_.async_accept(upgrade_,
                     [self = shared_from_this()](beast::error_code ec) { self->on_accept(ec); });
  }

  void send(LiveServer::Message message, bool binary) {
    if (closing_) return;
    queue_.emplace_back(std::move(message), binary);
    if (queue_.size() == 1) write_next();
  }
  std::size_t queued() const { return queue_.size(); }

  /// A graceful close once what is queued has gone.
  void close() {
    closing_ = true;
    if (queue_.empty()) send_close();
  }

 private:
  void on_accept(beast::error_code ec) {
    if (ec) {
      server_.say("client {}: WebSocket handshake failed: {}", id_, ec.message());
      return;
    }
    if (server_.stopping) return;
    server_.sessions[id_] = shared_from_this();
    open_ = true;
    server_.say("client {} connected", id_);
    server_.events.opened(id_);
    read();
  }

  void read() {
    ws_.async_read(buffer_, [self = shared_from_this()](beast::error_code ec, std::size_t) {
      self->on_read(ec);
    });
  }

  void on_read(beast::error_code ec) {
    if (ec) {
      if (ec == websocket::error::message_too_big)
        server_.say("client {}: message over {} bytes: connection closed", id_,
                    kMaxWebSocketMessage);
      finish();
      return;
    }
    const std::string text = beast::buffers_to_string(buffer_.data());
    buffer_.consume(buffer_.size());
    if (!ws_.got_text()) {
      server_.say("client {}: binary message of {} bytes dropped", id_, text.size());
    } else {
      const ClientMessage message = parse_client_message(text);
      if (message.kind == ClientMessage::Kind::Invalid)
        server_.say("client {}: message dropped: {}", id_, message.error);
      else
        server_.events.received(id_, message);
    }
    read();
  }

  void write_next() {
    ws_.binary(queue_.front().second);
    ws_.async_write(
        asio::buffer(*queue_.front().first),
        [self = shared_from_this()](beast::error_code ec, std::size_t) { self->on_write(ec); });
  }

  void on_write(beast::error_code ec) {
    if (ec) {  // the read sees the same broken connection and ends the session
      queue_.clear();
      return;
    }
    queue_.pop_front();
    if (!queue_.empty())
      write_next();
    else if (closing_)
      send_close();
  }

  void send_close() {
    if (close_sent_) return;
    close_sent_ = true;
    ws_.async_close(websocket::close_code::going_away,
                    [self = shared_from_this()](beast::error_code) {});
  }

  /// The connection has ended: tell the owner once.
  void finish() {
    if (!open_) return;
    open_ = false;
    server_.sessions.erase(id_);
    server_.say("client {} disconnected", id_);
    server_.events.closed(id_);
    if (server_.stopping && server_.sessions.empty()) server_.ioc.stop();
  }

  websocket::stream<beast::tcp_stream> ws_;
  http::request<http::string_body> upgrade_;  ///< the Upgrade request being accepted
  beast::flat_buffer buffer_;
  std::deque<std::pair<LiveServer::Message, bool>> queue_;
  LiveServer::Impl& server_;
  int id_;
  bool open_ = false, closing_ = false, close_sent_ = false;
};

/// One HTTP connection: GET of an asset, or the upgrade of /ws to a WebSocket.
class HttpSession : public std::enable_shared_from_this<HttpSession> {
 public:
  HttpSession(tcp::socket socket, LiveServer::Impl& server)
      : stream_(std::move(socket)), server_(server) {}

  void read() {
    parser_.emplace();
    parser_->header_limit(kMaxRequestHeader);
    parser_->body_limit(kMaxRequestBody);
    stream_.expires_after(std::chrono::seconds(30));
    http::async_read(
        stream_, buffer_, *parser_,
        [self = shared_from_this()](beast::error_code ec, std::size_t) { self->on_read(ec); });
  }

 private:
  void on_read(beast::error_code ec) {
    if (ec == http::error::end_of_stream) {
      stream_.socket().shutdown(tcp::socket::shutdown_send, ec);
      return;
    }
    if (ec) {
      if (ec != beast::error::timeout && ec != asio::error::operation_aborted)
        server_.say("HTTP request dropped: {}", ec.message());
      return;
    }
    http::request<http::string_body> request = parser_->release();
    if (websocket::is_upgrade(request) && request.target() == "/ws" && !server_.stopping) {
      const int id = server_.next_id++;
      std::make_shared<WsSession>(stream_.release_socket(), server_, id)->start(std::move(request));
      return;
    }
    respond(request);
  }

  void respond(const http::request<http::string_body>& request) {
    auto response = std::make_shared<http::response<http::string_body>>();
    response->version(request.version());
    response->keep_alive(request.keep_alive());
    response->set(http::field::server, "tridem");
    const std::optional<Asset> asset =
        find_asset(std::string_view(request.target().data(), request.target().size()));
    if (request.method() != http::verb::get && request.method() != http::verb::head) {
      response->result(http::status::method_not_allowed);
      response->set(http::field::content_type, "text/plain");
      response->body() = "only GET\n";
    } else if (!asset) {
      response->result(http::status::not_found);
      response->set(http::field::content_type, "text/plain");
      response->body() = "not found\n";
    } else {
      response->result(http::status::ok);
      response->set(http::field::content_type,
                    beast::string_view(asset->content_type.data(), asset->content_type.size()));
      response->set(http::field::cache_control, "no-store");
      if (request.method() == http::verb::get) response->body() = std::string(asset->body);
    }
    response->prepare_payload();
    if (request.method() == http::verb::head) response->body().clear();
    http::async_write(stream_, *response,
                      [self = shared_from_this(), response](beast::error_code ec, std::size_t) {
                        if (!ec && response->keep_alive()) self->read();
                      });
  }

  beast::tcp_stream stream_;
  beast::flat_buffer buffer_;
  std::optional<http::request_parser<http::string_body>> parser_;
  LiveServer::Impl& server_;
};

}  // namespace

void LiveServer::Impl::accept() {
  acceptor.async_accept(ioc, [this](beast::error_code ec, tcp::socket socket) {
    if (stopping) return;
    if (!ec) std::make_shared<HttpSession>(std::move(socket), *this)->read();
    accept();
  });
}

LiveServer::LiveServer(const std::string& host, unsigned short port, Events& events, std::FILE* log)
    : impl_(std::make_unique<Impl>(events, log)) {
  beast::error_code ec;
  const asio::ip::address address = asio::ip::make_address(host, ec);
  if (ec)
    throw Error(
        fmt::format("--live-host '{}' is not an IP address (e.g. 127.0.0.1 or 0.0.0.0)", host));
  const tcp::endpoint endpoint(address, port);
  tcp::acceptor& a = impl_->acceptor;
  a.open(endpoint.protocol(), ec);
  if (!ec) a.set_option(asio::socket_base::reuse_address(true), ec);
  if (!ec) a.bind(endpoint, ec);
  if (!ec) a.listen(asio::socket_base::max_listen_connections, ec);
  if (!ec) {
    impl_->accept();
    impl_->thread = std::thread([this] { impl_->ioc.run(); });
    return;
  }
  throw Error(fmt::format("live view: cannot listen on {}:{}: {} (pick another port with "
                          "--live PORT)",
                          host, port, ec.message()));
}

LiveServer::~LiveServer() { stop(); }

void LiveServer::stop() {
  if (!impl_->thread.joinable()) return;
  asio::post(impl_->ioc, [impl = impl_.get()] {
    impl->stopping = true;
    beast::error_code ignored;
    impl->acceptor.close(ignored);
    if (impl->sessions.empty()) impl->ioc.stop();
    // close() may end a session at once: iterate over a copy.
    const auto sessions = impl->sessions;
    for (const auto& entry : sessions) entry.second->close();
  });
  // Up to a second for the last messages and the close handshakes, then stop.
  asio::steady_timer limit(impl_->ioc, std::chrono::seconds(1));
  limit.async_wait([impl = impl_.get()](beast::error_code) { impl->ioc.stop(); });
  impl_->thread.join();
}

unsigned short LiveServer::port() const { return impl_->acceptor.local_endpoint().port(); }

void LiveServer::post(std::function<void()> task) { asio::post(impl_->ioc, std::move(task)); }

void LiveServer::send(int client, Message message, bool binary) {
  const auto it = impl_->sessions.find(client);
  if (it != impl_->sessions.end()) it->second->send(std::move(message), binary);
}

std::size_t LiveServer::queued(int client) const {
  const auto it = impl_->sessions.find(client);
  return it == impl_->sessions.end() ? 0 : it->second->queued();
}

}  // namespace tridem::live
