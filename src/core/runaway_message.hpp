#pragma once
// The one message of a runaway step, whichever backend detects it.
#include <cstdint>
#include <string>

namespace tridem {

std::string runaway_message(std::int64_t step, std::int64_t particle, double x, double y,
                            double speed, double dt);

}  // namespace tridem
