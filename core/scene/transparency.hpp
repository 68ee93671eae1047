#pragma once
#include <string>

namespace pbr {

// How BLEND surfaces are composited (docs/transparency.md): sorted, back to front by their bounds with Porter-Duff
// "over" (exact where that order is the depth order at every pixel); oit, weighted blended order-independent
// transparency (McGuire & Bavoil 2013), one pass in any order whose weights approximate the depth order; or exact,
// every fragment kept in a list per pixel and composited in depth order (up to a stated memory bound).
enum class Transparency { Sorted, Oit, Exact };
// "sorted", "oit", "exact"; throws std::invalid_argument naming the choices otherwise.
Transparency parseTransparency(const std::string& name);
const char* toString(Transparency transparency);

}  // namespace pbr
