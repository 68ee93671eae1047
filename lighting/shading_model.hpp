#pragma once
#include <string>

namespace pbr {

enum class ShadingModel { Pbr, BlinnPhong };
// The Smith visibility term of the PBR model: exact height-correlated, or Hammon's fast approximation.
enum class Visibility { HeightCorrelated, Hammon };

// Which lights the lighting pass visits per pixel: all of them (the reference path) or its cluster's.
enum class Culling { None, Clustered };

ShadingModel parseShadingModel(const std::string& name);  // "pbr" | "blinn-phong"
const char* toString(ShadingModel model);
Visibility parseVisibility(const std::string& name);  // "exact" | "hammon"
const char* toString(Visibility visibility);
Culling parseCulling(const std::string& name);  // "none" | "clustered"
const char* toString(Culling culling);

}  // namespace pbr
