// Radiance .hdr environments (ibl/radiance_hdr.*): the header reader and the checked run-length decoder.
// Rejections throw std::runtime_error; any other exception escapes and is reported as a crash.
#include <cstddef>
#include <cstdint>
#include <stdexcept>

#include "fuzz/temp_input.hpp"
#include "ibl/radiance_hdr.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string path = pbr::fuzz::writeTempInput("environment.hdr", data, size);
  try {
    pbr::readRadianceHdr(path);
  } catch (const std::runtime_error&) {
  }
  return 0;
}
