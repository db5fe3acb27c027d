// A WebSocket client of the live view without a browser (bench/live/run_live_bench.sh):
// connects to tridem run --live, asks for frames as fast as the server gives them, and
// prints what it received in `seconds` (or until the run ends) as one JSON line: fps and
// steps_per_s between its first and last frames.
//   tridem_live_client HOST PORT SECONDS [FPS_LIMIT]
#include <boost/asio/connect.hpp>
#include <boost/asio/ip/tcp.hpp>
#include <boost/beast/core.hpp>
#include <boost/beast/websocket.hpp>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <string>

namespace asio = boost::asio;
namespace beast = boost::beast;
namespace websocket = beast::websocket;

int main(int argc, char** argv) {
  if (argc < 4) {
    std::fprintf(stderr, "usage: %s HOST PORT SECONDS [FPS_LIMIT]\n", argv[0]);
    return 2;
  }
  const std::string host = argv[1], port = argv[2];
  const double seconds = std::stod(argv[3]);
  const std::string fps = argc > 4 ? argv[4] : "120";
  try {
    asio::io_context ioc;
    asio::ip::tcp::resolver resolver(ioc);
    websocket::stream<asio::ip::tcp::socket> ws(ioc);
    asio::connect(ws.next_layer(), resolver.resolve(host, port));
    ws.read_message_max(std::size_t{1} << 31);
    ws.handshake(host + ":" + port, "/ws");
    ws.text(true);
    ws.write(asio::buffer("fps " + fps));
    ws.write(asio::buffer(std::string("next")));
    using clock = std::chrono::steady_clock;
    const auto start = clock::now();
    std::int64_t frames = 0, first_step = -1, last_step = -1;
    double bytes = 0, first_frame_at = -1, last_frame_at = -1;
    beast::flat_buffer buffer;
    while (std::chrono::duration<double>(clock::now() - start).count() < seconds) {
      buffer.clear();
      beast::error_code ec;
      ws.read(buffer, ec);
      if (ec) break;                // the run has ended and the server closed
      if (ws.got_text()) continue;  // state and stats
      const auto* data = static_cast<const unsigned char*>(buffer.data().data());
      std::uint32_t kind = 0;
      std::memcpy(&kind, data, 4);
      if (kind != 2) continue;  // geometry
      std::int64_t step = 0;
      std::memcpy(&step, data + 24, 8);
      if (first_step < 0) {
        first_step = step;
        first_frame_at = std::chrono::duration<double>(clock::now() - start).count();
      }
      last_step = step;
      last_frame_at = std::chrono::duration<double>(clock::now() - start).count();
      ++frames;
      bytes += static_cast<double>(buffer.size());
      ws.write(asio::buffer(std::string("next")), ec);
      if (ec) break;
    }
    const double span = std::chrono::duration<double>(clock::now() - start).count() -
                        (first_frame_at < 0 ? 0 : first_frame_at);
    // The run's stepping rate while watched: from the steps of the first and last frames.
    const double watched = last_frame_at - first_frame_at;
    std::printf("{\"frames\": %lld, \"seconds\": %.3f, \"fps\": %.2f, \"mb_per_s\": %.2f, "
                "\"first_step\": %lld, \"last_step\": %lld, \"steps_per_s\": %.4g}\n",
                static_cast<long long>(frames), span,
                frames > 1 && watched > 0 ? static_cast<double>(frames - 1) / watched : 0.0,
                bytes / span / 1e6, static_cast<long long>(first_step),
                static_cast<long long>(last_step),
                watched > 0 ? static_cast<double>(last_step - first_step) / watched : 0.0);
    beast::error_code ec;
    ws.close(websocket::close_code::normal, ec);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "live client: %s\n", e.what());
    return 1;
  }
  return 0;
}
