// The live view's parser of what a browser sends: every command it knows, and the
// refusals (with a reason for the log) of everything else.
#include "live/client_message.hpp"

#include <gtest/gtest.h>
#include <string>

namespace tridem::live {
namespace {
namespace TRIDEM_TEST_FILE {  // one per source in a unity batch (tests/CMakeLists.txt)

using K = ClientMessage::Kind;

TEST(LiveClientMessage, KnowsItsCommands) {
  EXPECT_EQ(parse_client_message("next").kind, K::Next);
  EXPECT_EQ(parse_client_message("pause").kind, K::Pause);
  EXPECT_EQ(parse_client_message("resume").kind, K::Resume);
  EXPECT_EQ(parse_client_message("step").kind, K::Step);
  const ClientMessage fps = parse_client_message("fps 45");
  EXPECT_EQ(fps.kind, K::Fps);
  EXPECT_EQ(fps.value, 45);
  EXPECT_EQ(parse_client_message("fps 1").value, 1);
  EXPECT_EQ(parse_client_message("fps 120").value, 120);
  const ClientMessage seek = parse_client_message("seek 12");
  EXPECT_EQ(seek.kind, K::Seek);
  EXPECT_EQ(seek.value, 12);
}

TEST(LiveClientMessage, RefusesBadNumbersWithAReason) {
  for (const char* bad : {"fps 0", "fps 121", "fps -3", "fps 30x", "fps ", "fps", "fps  30",
                          "fps 3.5", "fps 99999999999999999999", "seek -1", "seek x", "seek"}) {
    const ClientMessage m = parse_client_message(bad);
    EXPECT_EQ(m.kind, K::Invalid) << bad;
    EXPECT_FALSE(m.error.empty()) << bad;
  }
  EXPECT_NE(parse_client_message("fps 0").error.find("1 to 120"), std::string::npos);
}

TEST(LiveClientMessage, RefusesUnknownEmptyAndGarbage) {
  for (const std::string& bad :
       {std::string(), std::string("PAUSE"), std::string("pause now"), std::string(" next"),
        std::string("next\n"), std::string("{\"cmd\":1}"), std::string("\0\xff\x01garbage", 10)}) {
    const ClientMessage m = parse_client_message(bad);
    EXPECT_EQ(m.kind, K::Invalid) << bad;
    // The log line quotes it in printable characters only.
    for (char c : m.error) EXPECT_TRUE(c >= 0x20 && c < 0x7f) << static_cast<int>(c);
  }
}

TEST(LiveClientMessage, DropsOversizedMessagesUnread) {
  const std::string big(kMaxCommandBytes + 1, 'a');
  const ClientMessage m = parse_client_message(big);
  EXPECT_EQ(m.kind, K::Invalid);
  EXPECT_NE(m.error.find("65 bytes"), std::string::npos) << m.error;
  std::string longest = "seek " + std::string(kMaxCommandBytes - 5, '1');
  EXPECT_EQ(parse_client_message(longest).kind, K::Invalid);  // too many digits, but read
}

}  // namespace TRIDEM_TEST_FILE
}  // namespace
}  // namespace tridem::live
