#pragma once
// The live view's HTTP and WebSocket server (Boost.Beast, one thread of its own): serves
// the page's embedded assets (live_assets.hpp; no request path reaches the file system)
// and a WebSocket at /ws for each of several clients. What clients say is parsed
// (client_message.hpp) and handed to `Events` on the server's thread; malformed and
// oversized messages are dropped with a log line.
#include "live/client_message.hpp"

#include <cstdio>
#include <functional>
#include <memory>
#include <string>

namespace tridem::live {

class LiveServer {
 public:
  using Message = std::shared_ptr<const std::string>;

  /// Called on the server's thread.
  class Events {
   public:
    virtual ~Events() = default;
    virtual void opened(int client) = 0;
    virtual void received(int client, const ClientMessage& message) = 0;
    virtual void closed(int client) = 0;
  };

  /// Listens on host:port (port 0: one the system picks) and starts the server's thread.
  /// Throws tridem::Error when the address cannot be used (a port taken, a bad host).
  LiveServer(const std::string& host, unsigned short port, Events& events, std::FILE* log);
  /// stop().
  ~LiveServer();
  /// Closes every connection (waiting up to a second for messages in flight) and joins
  /// the thread; the tasks posted before run first. Once; later calls do nothing. The
  /// owner of Events calls it while they can still be called (they may use the server).
  void stop();
  LiveServer(const LiveServer&) = delete;
  LiveServer& operator=(const LiveServer&) = delete;

  unsigned short port() const;
  /// Runs `task` on the server's thread; from any thread.
  void post(std::function<void()> task);

  // On the server's thread only:
  /// Queues a message for a client (no-op for one that has gone).
  void send(int client, Message message, bool binary);
  /// Messages queued for a client and not yet written: one still writing means it is slow,
  /// and the caller drops the frame for it.
  std::size_t queued(int client) const;

  struct Impl;

 private:
  std::unique_ptr<Impl> impl_;
};

}  // namespace tridem::live
