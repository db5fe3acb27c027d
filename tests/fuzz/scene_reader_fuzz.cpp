// libFuzzer target: any text handed to the scene reader must end in a Scene or a
// tridem::Error, never a crash, a hang, undefined behaviour or another exception.
#include "tridem/error.hpp"
#include "tridem/scene_io.hpp"

#include <cstddef>
#include <cstdint>
#include <string_view>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  try {
    tridem::parse_scene(std::string_view(reinterpret_cast<const char*>(data), size), "fuzz.toml");
  } catch (const tridem::Error&) {
    // a refusal with a message is the expected outcome for most inputs
  }
  return 0;
}
