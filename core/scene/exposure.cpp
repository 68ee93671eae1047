#include "core/scene/exposure.hpp"

#include <cmath>

namespace pbr {

double ev100FromCamera(double aperture, double shutterSeconds, double iso) {
  return std::log2(aperture * aperture / shutterSeconds * 100.0 / iso);
}

double exposureFromEv100(double ev100) { return 1.0 / (1.2 * std::exp2(ev100)); }

double ev100FromExposure(double exposure) { return std::log2(1.0 / (1.2 * exposure)); }

}  // namespace pbr
