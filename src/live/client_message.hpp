#pragma once
// What a browser may say to the live view over its WebSocket: one short text command per
// message. Anything else (binary, too long, unknown, a bad number) is refused with the
// reason, which the server logs before dropping the message.
#include <cstddef>
#include <string>
#include <string_view>

namespace tridem::live {

/// The longest command accepted; a longer message is dropped unread.
inline constexpr std::size_t kMaxCommandBytes = 64;

struct ClientMessage {
  enum class Kind {
    Invalid,  ///< refused: `error` says why
    Next,     ///< "next": the client drew its last frame and wants another
    Pause,    ///< "pause"
    Resume,   ///< "resume"
    Step,     ///< "step": one step, then paused again
    Fps,      ///< "fps N": the frame-rate limit, 1 to 120 frames per second
    Seek,     ///< "seek N": a replay's frame N (tridem view)
  } kind = Kind::Invalid;
  long long value = 0;  ///< Fps: frames per second; Seek: the frame's index
  std::string error;    ///< Invalid: why
};

inline constexpr long long kMinFps = 1;
inline constexpr long long kMaxFps = 120;

ClientMessage parse_client_message(std::string_view text);

}  // namespace tridem::live
