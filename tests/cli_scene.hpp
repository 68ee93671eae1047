#pragma once
// The scene file the command-line tests give `pbr render --scene`: a plane, a sphere, one listed light and eight
// random ones.
namespace pbr::test {

inline constexpr const char* kCliScene = R"({
  "camera": {"position": [0, 2, 5], "target": [0, 0.5, 0], "fov_y_deg": 45, "near": 0.5, "far": 20},
  "ambient": 0.05,
  "objects": [{"shape": "plane", "transform": {"scale": 8}}, {"shape": "sphere", "transform": {"translate": [0, 0.5, 0]}}],
  "lights": [{"position": [1, 2, 2], "luminous_power": 200, "radius": 8}],
  "random_lights": {"count": 8, "bounds": [[-2, 0.2, -2], [2, 1.5, 2]], "radius": [1, 2], "luminous_power": [5, 10]}
})";

}  // namespace pbr::test
