#pragma once
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec4.hpp>

#include "core/scene/binding_table.hpp"
#include "core/scene/scene.hpp"

namespace pbr {

// Shadow maps as shaders sample them (shaders/shadows/shadow_sample.glsl), with no GL: the layouts of the views
// and of the entries the shaders look them up by, where the lighting pass binds them, and the settings they are
// made with. The maps themselves are handles (core/gl/shadow_maps.hpp).

// std430 mirror of `CascadeView` in shaders/shadows/shadow_sample.glsl: one cascade of a directional light, an
// orthographic view (cube faces and spot views need no record: see packShadowSquare).
struct GpuCascadeView {
  glm::vec4 rows[3];  // world -> the light's clip space x, y and reversed-Z depth (w is 1)
  glm::vec4 rect;     // atlas UV of the square: offset xy, size zw; size 0: not rendered, everything lit
  glm::vec4 params;   // x: world size of a texel
};
static_assert(sizeof(GpuCascadeView) == 80, "GpuCascadeView must match its std430 layout");

// std430 mirror of the header of `ShadowViews` in shaders/shadows/shadow_sample.glsl.
struct GpuShadowHeader {
  glm::uvec4 directional[kMaxDirectionalLights];  // per directional light: x first cascade + 1 (0: none), y cascades
  glm::vec4 cascadeEnds;                          // view depth where each cascade ends
  glm::vec4 atlas;                                // x size in texels, y its inverse
};
static_assert(sizeof(GpuShadowHeader) == 16 * kMaxDirectionalLights + 32, "GpuShadowHeader: std430");

// One square of the atlas to render casters into: the light's view-projection and the square, in texels.
struct ShadowCasterView {
  glm::mat4 viewProjection;
  glm::ivec4 viewport;  // x, y, width, height
  // A point or spot light's sphere (centre, radius; w 0 for a cascade): what it lights lies inside, so only a caster
  // meeting it can stand between the light and a lit point.
  glm::vec4 reach{0.0f};
  // A texel's world size per unit of the view's w (the distance along a perspective view's axis; an orthographic
  // view's w is 1): how coarse a caster's tessellation may be in this view.
  float texelWorld = 0.0f;
  // The shadowed light it belongs to (ShadowViewPlan::light): a light's views are drawn together.
  uint32_t light = 0;
  // Bit i: the caster of plane i (CasterPlane, in the geometry's order) is left out, hiding no visible point from
  // this light.
  uint32_t skipPlanes = 0;
};

// What drawing the casters into views did: the draw calls made (and how many were one-sided), and per view the
// atlas texels its casters may have written (coveredRect of each caster drawn, joined; width 0 where none was drawn).
struct ShadowCasterDraws {
  size_t draws = 0;
  size_t oneSided = 0;  // of them, closed casters drawn from their faces toward the light alone
  std::vector<glm::ivec4> rects;
};

// A point or spot light's entry in `lightViews`: 0 without shadows; else its first view + 1 in bits 0-25, log2 of
// its views' side in bits 26-29, kCubeShadow set when it owns six cube faces (+X, -X, +Y, -Y, +Z, -Z) rather than
// one perspective view, and for a spot view kShadowFrameX set when its frame was built around the x axis rather
// than y (frameAround's choice, which the shader cannot remake exactly from a rounded axis).
constexpr uint32_t kCubeShadow = 0x80000000u;
constexpr uint32_t kShadowFrameX = 0x40000000u;
enum class LightShadowKind { Spot, SpotFrameX, Cube };
uint32_t lightShadowEntry(uint32_t firstView, int size, LightShadowKind kind);

// A view's entry in `squares`: its atlas origin x | y << 14 | log2(side) << 28 in texels; 0 when not rendered. Cube
// faces and spot views are looked up from it alone: the view's frame, field of view and near plane follow from the
// light's position, radius and cone (shaders/shadows/shadow_sample.glsl), which saves reading its 96-byte view per
// light-pixel pair.
uint32_t packShadowSquare(glm::ivec2 origin, int size);

// A perspective view's border around its field of view, in texels: filter taps near an edge read rendered depth,
// not the neighbouring square or a clamp. Its near plane: this share of the light's radius (at least 1e-4). Casters
// nearer the light are clipped away, so it is small: a glTF light without a range gets its radius from its
// intensity, a kilometre and more for the README's Blender export, where a share of 1e-3 put the near plane 1-2 m
// from its point lights, inside the objects beside them. The reversed float depth n / w (far plane at infinity) keeps
// a relative precision that does not depend on n.
constexpr int kShadowBorderTexels = 3;
constexpr float kShadowNearScale = 1e-6f;
// The near plane of the views of a point or spot light of that radius.
inline float shadowNearPlane(float radius) { return std::max(radius * kShadowNearScale, 1e-4f); }

// Where the lighting pass reads them (part of lightingBindingDefines): clear of the lighting module's, the frame
// block's and the IBL maps' points.
constexpr BindingPoint kShadowAtlasUnit{"SHADOW_ATLAS_UNIT", BindingKind::TextureUnit, 11};
constexpr BindingPoint kShadowViewSsbo{"SHADOW_VIEW_SSBO", BindingKind::StorageBuffer, 15};
constexpr BindingPoint kLightShadowSsbo{"LIGHT_SHADOW_SSBO", BindingKind::StorageBuffer, 16};
constexpr BindingPoint kShadowSquareSsbo{"SHADOW_SQUARE_SSBO", BindingKind::StorageBuffer, 17};

// How a shadow map is sampled (the lighting pass's SHADOW_FILTER_* permutations): one comparison at the nearest
// texel; a 3x3 grid of bilinear comparisons one texel apart (a tent over 4x4 texels); 16 bilinear comparisons on a
// Poisson disc of radius 1.5 texels.
enum class ShadowFilter { Hard, Pcf3x3, Poisson16 };
// "hard", "pcf3x3", "poisson16"; throws std::invalid_argument naming the choices otherwise.
ShadowFilter parseShadowFilter(const std::string& name);
const char* toString(ShadowFilter filter);
// The define that selects it: SHADOW_FILTER_HARD, SHADOW_FILTER_PCF3X3 or SHADOW_FILTER_POISSON16.
const char* shadowFilterDefine(ShadowFilter filter);

// What a frame's shadows are made with: which lights cast, how the maps are sampled, and the atlas's side (a power
// of two; 4096 holds 64 MiB).
constexpr int kDefaultShadowAtlas = 4096;
constexpr int kMinShadowAtlas = 256;
constexpr int kMaxShadowAtlas = 16384;
// How the casters' draws are issued (the same depths either way): `PerView`, a draw per caster and view;
// `PerLight`, a draw per caster and run of a light's views seeing it, each instance choosing its view's viewport
// in the vertex shader (GL_ARB_shader_viewport_layer_array), fewer draws for the CPU to record; `Auto`, PerLight
// on a GPU with the extension, PerView on a CPU rasterizer, which rasterizes per-vertex viewports the slower.
enum class ShadowDraws { Auto, PerView, PerLight };
ShadowDraws parseShadowDraws(const std::string& name);  // "auto", "per-view", "per-light"
const char* toString(ShadowDraws draws);

struct ShadowSettings {
  ShadowMode mode = ShadowMode::Auto;
  ShadowFilter filter = ShadowFilter::Pcf3x3;
  int atlasSize = kDefaultShadowAtlas;
  ShadowDraws draws = ShadowDraws::Auto;
  // Keep the last frame's maps where nothing they depend on changed (ShadowFrameKey): a still scene seen from a
  // still camera draws its maps once. Off redraws them every frame, what a moving scene pays.
  bool cache = true;
};

// The constants above as defines for shadow_sample.glsl.
ShaderDefines shadowViewDefines();

}  // namespace pbr
