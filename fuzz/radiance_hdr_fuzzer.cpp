// Environment pictures (ibl/openexr_image.*, ibl/radiance_hdr.*): OpenEXR through tinyexr, behind the header and
// size checks, and Radiance's header reader and checked run-length decoder, chosen by the magic number.
// Rejections throw std::runtime_error; any other exception escapes and is reported as a crash.
#include <cstddef>
#include <cstdint>
#include <stdexcept>

#include "fuzz/temp_input.hpp"
#include "ibl/openexr_image.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string path = pbr::fuzz::writeTempInput("environment.hdr", data, size);
  try {
    pbr::readEnvironmentImage(path);
  } catch (const std::runtime_error&) {
  }
  return 0;
}
