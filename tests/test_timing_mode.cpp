// The profiler's timing-mode selection and names: which mode a driver gets, and how each is described.
#include <doctest/doctest.h>

#include <stdexcept>
#include <string>

#include "core/io/frame_timing.hpp"

using pbr::TimingMode;

TEST_CASE("profiler: chooseTimingMode serializes on software rasterizers unless told otherwise") {
  CHECK(pbr::chooseTimingMode("auto", "llvmpipe (LLVM 15.0.6, 256 bits)") == TimingMode::Serializing);
  CHECK(pbr::chooseTimingMode("auto", "NVIDIA H100/PCIe/SSE2") == TimingMode::GpuQueries);
  CHECK(pbr::chooseTimingMode("gpu", "llvmpipe (LLVM 15.0.6, 256 bits)") == TimingMode::GpuQueries);
  CHECK(pbr::chooseTimingMode("serial", "NVIDIA H100/PCIe/SSE2") == TimingMode::Serializing);
  CHECK_THROWS_AS(pbr::chooseTimingMode("fast", "NVIDIA H100/PCIe/SSE2"), std::invalid_argument);
  CHECK_THROWS_AS(pbr::chooseTimingMode("", "llvmpipe"), std::invalid_argument);
  CHECK_THROWS_AS(pbr::chooseTimingMode("Auto", "llvmpipe"), std::invalid_argument);
}

TEST_CASE("profiler: describe names the two timing modes differently") {
  const std::string gpu = pbr::describe(TimingMode::GpuQueries);
  const std::string serial = pbr::describe(TimingMode::Serializing);
  CHECK_FALSE(gpu.empty());
  CHECK_FALSE(serial.empty());
  CHECK(gpu != serial);
}
