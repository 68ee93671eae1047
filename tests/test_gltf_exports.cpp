// Every real export of ../shared/assets/exports/ (its README says what each was chosen for) loads with the warning
// lines it should give and no others, and renders a frame in which the model shows (against the same frame without
// its objects); a file requiring an extension the renderer lacks would be refused naming it. A folder the table
// does not know must at least load or be refused in one line.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "core/scene/assets.hpp"
#include "core/scene/scene_json.hpp"
#include "tests/cli_util.hpp"
#include "tests/gl_test_context.hpp"
#include "tests/render_util.hpp"

namespace fs = std::filesystem;

namespace {

struct Expected {
  std::vector<std::string> warnings;  // a part of each warning line, one per line, in order
  std::string refusal;                // the error's part where the file is refused
  bool geometry = true;               // false: nothing to draw (a flat frame is right)
};

const std::map<std::string, Expected> kExports = {
    {"assetgen-Mesh_PrimitiveMode_00", {{"meshes[0].primitives[0]: mode 0 (points or lines) is not drawn"}, "", false}},
    {"assimp-Cameras", {{}, "", true}},
    {"assimp-ClearCoatTest", {{}, "", true}},  // its coat maps drawn
    {"babylon-max-AnimatedSpotlights",
     {{"lights[0].range: 3.40282e+38 is beyond the coordinate limit", "lights[1].range", "lights[2].range",
       "lights[3].range"},
      "",
      true}},
    {"blender-01_color_attribute", {{}, "", true}},
    {"blender-01_morphed_cube", {{}, "", true}},
    {"blender-01_unlit", {{}, "", true}},
    {"blender-03_skinned_cylinder", {{}, "", true}},
    {"blender-04_lights", {{}, "", true}},
    {"blender-15_transmission", {{}, "", true}},
    {"blender-24_gpu_instancing", {{}, "", true}},
    {"gltftransform-BoxMeshopt", {{}, "", true}},
    {"jl-Astronaut_obj2gltfconverter",
     {{"bufferViews[0].byteStride: 0 read as tightly packed", "accessors[4].count: 0 read as an empty accessor"},
      "",
      true}},
    {"jl-BrainStem", {{}, "", true}},  // KHR_materials_pbrSpecularGlossiness, converted
    {"jl-DamagedHelmet_gltfpack014", {{}, "", true}},
    {"playcanvas-glass-table_sketchfab", {{}, "", true}},
    {"playcanvas-heart_draco_fbx2gltf", {{}, "", true}},
    {"sdk-SimpleSparseAccessor", {{}, "", true}},
    {"trimesh-AlphaBlendModeTest", {{}, "", true}},
    {"webp-CesiumBoxWebp-LocalTexture", {{}, "", true}},
};

std::vector<std::string> lines(const std::string& text) {
  std::vector<std::string> out;
  size_t start = 0;
  for (size_t end = text.find('\n'); end != std::string::npos; end = text.find('\n', start)) {
    out.push_back(text.substr(start, end - start));
    start = end + 1;
  }
  return out;
}

// The share of pixels whose colour differs by more than 8 of 255 in some channel between two frames.
double changedShare(const pbr::ImageRgba8& a, const pbr::ImageRgba8& b) {
  size_t changed = 0;
  const size_t n = a.pixels.size() / 4;
  for (size_t i = 0; i < n; ++i) {
    bool differs = false;
    for (size_t c = 0; c < 3; ++c) {
      differs = differs || std::abs(int(a.pixels[4 * i + c]) - int(b.pixels[4 * i + c])) > 8;
    }
    changed += differs ? 1 : 0;
  }
  return double(changed) / double(n);
}

}  // namespace

TEST_CASE("gltf exports: every real export loads with the warnings it should and renders a frame it shows in") {
  PBR_REQUIRE_GL();
  const fs::path folder = fs::path(pbr::assetDir()) / "exports";
  if (!fs::is_directory(folder)) {
    MESSAGE("shared exports not found at " << folder << ": skipped");
    return;
  }
  std::vector<fs::path> models;
  for (const fs::directory_entry& dir : fs::directory_iterator(folder)) {
    if (!dir.is_directory()) continue;
    for (const fs::directory_entry& file : fs::directory_iterator(dir.path())) {
      const std::string ext = file.path().extension().string();
      if (ext == ".gltf" || ext == ".glb") models.push_back(file.path());
    }
  }
  std::sort(models.begin(), models.end());
  CHECK(models.size() >= kExports.size());
  for (const fs::path& model : models) {
    const std::string name = model.parent_path().filename().string();
    CAPTURE(name);
    const auto known = kExports.find(name);
    pbr::test::CapturedStderr err;
    std::string refusal;
    pbr::Scene scene;
    try {
      scene = pbr::loadSceneFile(model.string());
    } catch (const pbr::SceneError& e) {
      refusal = e.what();
    }
    const std::vector<std::string> warned = lines(err.text());
    CAPTURE(err.text());
    CAPTURE(refusal);
    if (known == kExports.end()) {
      // Not in the table: loaded, or refused in one line naming the file.
      CHECK((refusal.empty() || (refusal.find('\n') == std::string::npos && refusal.find(model.string()) == 0)));
      continue;
    }
    const Expected& e = known->second;
    if (!e.refusal.empty()) {
      CHECK(refusal.find(e.refusal) != std::string::npos);
      continue;
    }
    REQUIRE(refusal.empty());
    REQUIRE(warned.size() == e.warnings.size());
    for (size_t i = 0; i < warned.size(); ++i) CHECK(warned[i].find(e.warnings[i]) != std::string::npos);
    CHECK(scene.objects.empty() == !e.geometry);
    pbr::FrameOptions options;
    options.exposure = scene.displayExposure();  // as `pbr render` shows it: metered for files with lights
    const pbr::test::RenderedFrame frame = pbr::test::renderScene(scene, {64, 36}, options, 1);
    // Against the same frame without the model's objects (the sky and the lights alone): the model shows.
    pbr::Scene empty = scene;
    empty.objects.clear();
    const pbr::test::RenderedFrame background = pbr::test::renderScene(empty, {64, 36}, options, 1);
    const double shown = changedShare(frame.ldr, background.ldr);
    MESSAGE(name << ": " << scene.objects.size() << " objects, " << shown * 100.0 << " % of the pixels");
    CHECK((e.geometry ? shown > 0.005 : shown == 0.0));
  }
}
