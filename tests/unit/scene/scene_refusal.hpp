#pragma once
// Helpers for tests of refused scenes: every refusal must say where (file, line or
// particle) and what (key), so the tests check the message, not just the exception type.
#include "tridem/error.hpp"
#include "tridem/scene_io.hpp"

#include <gtest/gtest.h>

#include <initializer_list>
#include <string>
#include <string_view>

namespace tridem::test {

/// Lines 1-6 of every small test scene; a block appended after it starts on line 7.
inline constexpr std::string_view kSceneHead =
    "[simulation]\n"
    "steps = 5\n"
    "[[material]]\n"
    "name = \"m\"\n"
    "density = 1000\n"
    "penalty = 1e6\n";

/// kSceneHead followed by one [[triangle]] header (line 7) and `body` (from line 8).
inline std::string with_triangle(std::string_view body) {
  return std::string(kSceneHead) + "[[triangle]]\n" + std::string(body);
}

inline constexpr std::string_view kGoodTriangle =
    "[[triangle]]\nmaterial = \"m\"\nvertices = [[0, 0], [1, 0], [0, 1]]\n";

/// Parses `text` as "bad.toml", expects a SceneError whose message contains every one of
/// `parts`, and returns the message.
inline std::string expect_refused(const std::string& text,
                                  std::initializer_list<std::string_view> parts) {
  std::string message;
  try {
    parse_scene(text, "bad.toml");
    ADD_FAILURE() << "scene was accepted:\n" << text;
    return message;
  } catch (const SceneError& e) {
    message = e.what();
  }
  for (std::string_view part : parts)
    EXPECT_NE(message.find(part), std::string::npos)
        << "message lacks \"" << part << "\":\n  " << message;
  return message;
}

}  // namespace tridem::test
