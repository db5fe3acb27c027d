// The GPU is the caller's choice (SolverConfig::device, `tridem run --device`): an index
// this machine does not have is refused with the way out, and the solver runs on the one
// it is given.
#include "backends/cuda/cuda_backend.hpp"
#include "support/gpu.hpp"
#include "support/scene_builder.hpp"
#include "tridem/error.hpp"

#include <gtest/gtest.h>

#include <string>

namespace tridem {
namespace {
namespace TRIDEM_TEST_FILE {  // one per source in a unity batch (tests/CMakeLists.txt)

Scene two_grains(Backend backend) {
  Scene s = test::empty_scene();
  s.simulation.backend = backend;
  s.triangles.push_back(test::triangle({0, 0}, {1, 0}, {0, 1}));
  s.triangles.push_back(test::triangle({2, 0}, {3, 0}, {2, 1}));
  return s;
}

/// The RunError make_solver gives for `device`, or "" when it accepts it.
std::string refusal(const Scene& s, int device) {
  SolverConfig config;
  config.device = device;
  try {
    make_solver(s, config);
  } catch (const RunError& e) {
    return e.what();
  }
  return {};
}

TEST(DeviceChoice, CpuBackendsRefuseAGpuIndex) {
  for (Backend b : {Backend::Cpu, Backend::OpenMP}) {
    const std::string why = refusal(two_grains(b), 1);
    EXPECT_NE(why.find("--device 1"), std::string::npos) << why;
    EXPECT_NE(why.find("--backend cuda"), std::string::npos) << why;
    EXPECT_EQ(refusal(two_grains(b), 0), "") << "device 0 is the default, on every backend";
  }
}

TEST(DeviceChoice, CudaWithoutAGpuSaysSo) {
  if (cuda_device_count() > 0) GTEST_SKIP() << "a GPU is usable here";
  EXPECT_NE(refusal(two_grains(Backend::Cuda), 0).find("not available"), std::string::npos);
}

TEST(GpuDeviceChoice, IndexPastTheLastGpuIsRefused) {
  TRIDEM_SKIP_WITHOUT_GPU();
  const int count = cuda_device_count();
  ASSERT_GT(count, 0);
  const std::string why = refusal(two_grains(Backend::Cuda), count);
  EXPECT_NE(why.find("--device " + std::to_string(count) + " is not a GPU of this machine"),
            std::string::npos)
      << why;
  EXPECT_NE(refusal(two_grains(Backend::Cuda), -1).find("is not a GPU"), std::string::npos);
}

TEST(GpuDeviceChoice, SolverRunsOnTheGpuItIsGiven) {
  TRIDEM_SKIP_WITHOUT_GPU();
  for (int device = 0; device < cuda_device_count(); ++device) {
    SolverConfig config;
    config.device = device;
    auto solver = make_solver(two_grains(Backend::Cuda), config);
    solver->advance(3);
    // The description names the device's own model ("NVIDIA H200 (sm_90, ...)" starts
    // with the name the solver reports).
    const std::string name = cuda_device_description(device);
    const std::string model = name.substr(0, name.find(" (sm_"));
    EXPECT_NE(solver->description().find("cuda (" + model + ")"), std::string::npos)
        << solver->description() << " vs " << name;
  }
}

}  // namespace TRIDEM_TEST_FILE
}  // namespace
}  // namespace tridem
