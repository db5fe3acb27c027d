// The live view on a real run, through its WebSocket, without a browser: frames arrive as
// they are asked for, pause holds the step, single step adds exactly one, resume goes on,
// and an unwatched run keeps its chunks (the time loop is not held to one step).
#include "live/live_view.hpp"
#include "support/scene_builder.hpp"
#include "tridem/run.hpp"
#include "unit/io/io_test_support.hpp"

#include <boost/asio/connect.hpp>
#include <boost/asio/ip/tcp.hpp>
#include <boost/beast/core.hpp>
#include <boost/beast/websocket.hpp>
#include <chrono>
#include <cstring>
#include <gtest/gtest.h>
#include <thread>

namespace tridem::live {
namespace {
namespace TRIDEM_TEST_FILE {  // one per source in a unity batch (tests/CMakeLists.txt)

namespace asio = boost::asio;
namespace websocket = boost::beast::websocket;

/// A client of the live view that asks for frames one after another, as the page does.
class FrameClient {
 public:
  explicit FrameClient(unsigned short port) : ws_(ioc_) {
    asio::ip::tcp::resolver resolver(ioc_);
    asio::connect(ws_.next_layer(), resolver.resolve("127.0.0.1", std::to_string(port)));
    ws_.read_message_max(std::size_t{1} << 26);
    ws_.handshake("127.0.0.1", "/ws");
    say("fps 120");
  }
  void say(const std::string& command) {
    ws_.text(true);
    ws_.write(asio::buffer(command));
  }
  /// Asks for a frame and returns its step.
  std::int64_t next_frame() {
    say("next");
    for (;;) {
      boost::beast::flat_buffer buffer;
      ws_.read(buffer);
      if (ws_.got_text()) continue;  // state and stats
      const auto* data = static_cast<const unsigned char*>(buffer.data().data());
      std::uint32_t kind = 0;
      std::memcpy(&kind, data, 4);
      if (kind != kFrameMessage) continue;  // the geometry
      std::int64_t step = 0;
      std::memcpy(&step, data + 24, 8);
      return step;
    }
  }
  void close() { ws_.close(websocket::close_code::normal); }

 private:
  asio::io_context ioc_;
  websocket::stream<asio::ip::tcp::socket> ws_;
};

struct WatchedRun {
  test::TempDir dir;
  std::atomic<int> interrupt{0};
  LiveView view;
  RunSummary summary;
  std::thread thread;

  WatchedRun(std::int64_t steps, bool paused) : view(options(paused), {0, -9.81}, nullptr) {
    Scene s = test::jostling_pile(4, 3);
    s.simulation.backend = Backend::Cpu;
    s.simulation.steps = steps;
    s.output.dir = dir.path().string();
    s.output.every = 0;
    thread = std::thread([this, s] {
      RunOptions o;
      o.progress = false;
      o.log = nullptr;
      o.interrupt = &interrupt;
      o.observer = &view;
      summary = run_scene(s, o);
    });
  }
  ~WatchedRun() {
    interrupt.store(2);
    if (thread.joinable()) thread.join();
  }
  static LiveOptions options(bool paused) {
    LiveOptions o;
    o.port = 0;
    o.fps = 120;
    o.start_paused = paused;
    return o;
  }
};

TEST(LiveView, PauseStepAndResumeOverTheSocket) {
  WatchedRun run(50'000'000, true);
  FrameClient client(run.view.port());
  // Paused after the first step: frames keep coming, the step holds.
  EXPECT_EQ(client.next_frame(), 1);
  EXPECT_EQ(client.next_frame(), 1);
  EXPECT_EQ(client.next_frame(), 1);
  client.say("step");
  std::int64_t step = 1;
  for (int k = 0; k < 200 && step == 1; ++k) step = client.next_frame();
  EXPECT_EQ(step, 2) << "single step adds one step";
  for (int k = 0; k < 3; ++k) EXPECT_EQ(client.next_frame(), 2) << "and holds again";
  client.say("resume");
  std::int64_t later = 2;
  for (int k = 0; k < 200 && later < 1000; ++k) {
    const std::int64_t now = client.next_frame();
    EXPECT_GE(now, later) << "frames come in step order";
    later = now;
  }
  EXPECT_GE(later, 1000) << "resumed";
  client.say("pause");
  // The pause takes effect within a frame or two; then the step holds.
  std::int64_t held = client.next_frame();
  for (int k = 0; k < 5; ++k) held = client.next_frame();
  EXPECT_EQ(client.next_frame(), held);
  EXPECT_EQ(client.next_frame(), held);
  client.close();  // the last client gone, the run resumes; the interrupt stops it
}

TEST(LiveView, AnUnwatchedRunKeepsItsChunks) {
  LiveView view(WatchedRun::options(false), {0, -9.81}, nullptr);
  Scene s = test::jostling_pile(4, 3);
  s.simulation.backend = Backend::Cpu;
  auto solver = make_solver(s, {});
  EXPECT_EQ(view.steps_before_look(500, 1e-4), 1) << "the first look after one step";
  solver->advance(1);
  view.after_advance(*solver, nullptr);
  EXPECT_EQ(view.steps_before_look(500, 1e-4), 500) << "nobody watching: the loop's chunk";
  FrameClient client(view.port());
  EXPECT_EQ(client.next_frame(), 1);  // it has the first frame: connected and served
  const std::int64_t watched = view.steps_before_look(500, 1e-4);
  EXPECT_GE(watched, 1);
  EXPECT_LE(watched, static_cast<std::int64_t>(kPollSeconds / 1e-4) + 1)
      << "a client connected: a look within kPollSeconds";
  client.close();
}

// The run's set-up prepares the view (run_starting): its first look is not taken out of the
// stepping, whose first chunk is then the loop's own; frames still come after steps.
TEST(LiveView, PreparesBeforeTheFirstStep) {
  LiveView view(WatchedRun::options(false), {0, -9.81}, nullptr);
  Scene s = test::jostling_pile(4, 3);
  s.simulation.backend = Backend::Cpu;
  auto solver = make_solver(s, {});
  view.run_starting(*solver);
  EXPECT_EQ(view.steps_before_look(500, 1e-4), 500) << "prepared: the loop's chunk";
  FrameClient client(view.port());
  client.say("next");
  solver->advance(1);
  // The request reaches the server's thread in its own time, slowly under the sanitizers on
  // a busy machine: wait until it has (a look before would take no frame, and the client
  // would wait for one forever), and fail, not hang, if it never does.
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
  while (!view.frame_wanted() && std::chrono::steady_clock::now() < deadline)
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  ASSERT_TRUE(view.frame_wanted()) << "the client's request never reached the server";
  view.after_advance(*solver, nullptr);
  EXPECT_EQ(client.next_frame(), 1) << "the first frame, after the first step";
  client.close();
}

TEST(LiveView, StopsItsServerBeforeItGoes) {
  // The last frame of a run is converted and delivered on the server's thread, maybe while
  // the view is being destroyed: the server must still be there for it (the server's
  // pointer was nulled before its thread stopped, and tridem run --live crashed at exit
  // about one time in three at 10^4 triangles).
  Scene s = test::jostling_pile(4, 3);
  s.simulation.backend = Backend::Cpu;
  auto solver = make_solver(s, {});
  for (int k = 0; k < 5; ++k) {
    auto view = std::make_unique<LiveView>(WatchedRun::options(false), Vec2d{0, -9.81}, nullptr);
    solver->advance(1);
    view->after_advance(*solver, nullptr);
    FrameClient client(view->port());
    EXPECT_EQ(client.next_frame(), solver->step());
    client.say("next");  // wanted: the end's frame will be delivered to it
    view->run_ended(*solver);
    view.reset();
  }
}

}  // namespace TRIDEM_TEST_FILE
}  // namespace
}  // namespace tridem::live
