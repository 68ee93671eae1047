#pragma once
#include <cstdint>

namespace pbr {

// PCG32 (O'Neill 2014): the same seed gives the same stream on every platform and standard library,
// which std::uniform_real_distribution does not promise.
class Pcg32 {
 public:
  explicit Pcg32(uint64_t seed, uint64_t stream = 54u) : inc_((stream << 1u) | 1u) {
    next();
    state_ += seed;
    next();
  }
  uint32_t next() {
    const uint64_t old = state_;
    state_ = old * 6364136223846793005ULL + inc_;
    const uint32_t xorshifted = static_cast<uint32_t>(((old >> 18u) ^ old) >> 27u);
    const uint32_t rot = static_cast<uint32_t>(old >> 59u);
    return (xorshifted >> rot) | (xorshifted << ((32u - rot) & 31u));
  }
  // Uniform in [0, 1) with 24 bits.
  float uniform() { return static_cast<float>(next() >> 8) * (1.0f / 16777216.0f); }
  float uniform(float lo, float hi) { return lo + (hi - lo) * uniform(); }

 private:
  uint64_t state_ = 0;
  uint64_t inc_;
};

}  // namespace pbr
