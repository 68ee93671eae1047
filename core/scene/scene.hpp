#pragma once
#include <array>
#include <cstdint>
#include <limits>
#include <map>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include <glm/mat3x2.hpp>
#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include "core/scene/camera.hpp"
#include "core/scene/mesh.hpp"
#include "core/scene/sky_params.hpp"

namespace pbr {

// The renderer works in float: framing a model, placing the default lights and culling lights square distances,
// which overflow past about 1e19. Coordinates and light radii, after every transform, stay within this, far beyond
// any real scene; the loaders refuse what is further out by the field that put it there.
constexpr double kMaxCoordinate = 1e12;

// A decoded image for a material, with its glTF sampler state (GL enums).
struct TextureData {
  std::string name;  // file or glTF image name, for messages
  int width = 0, height = 0;
  std::vector<uint8_t> rgba;  // 4 bytes per pixel, rows from the top
  bool srgb = false;          // base colour and emissive images are sRGB-encoded
  int wrapS = 0x2901, wrapT = 0x2901;  // GL_REPEAT
  int minFilter = 0x2703, magFilter = 0x2601;  // GL_LINEAR_MIPMAP_LINEAR, GL_LINEAR
};

// OPAQUE ignores alpha; MASK keeps what reaches alphaCutoff; BLEND composites the lit colour over what lies behind
// by its alpha (Porter-Duff "over").
enum class AlphaMode { Opaque, Mask, Blend };

// A BLEND material casts a shadow where its alpha is at least this, and none elsewhere: a cut-out at one half, so
// that a faint pane casts nothing and the solid part of a fading decal casts its shape.
constexpr float kBlendShadowCutoff = 0.5f;

// A map of a material extension (KHR_materials_*): its Scene::textures index (-1: none), its KHR_texture_transform
// (identity without one) and its UV set (glTF texCoord: 0 TEXCOORD_0, 1 TEXCOORD_1).
struct MaterialMap {
  int texture = -1;
  glm::mat3x2 uvTransform{1.0f};
  int texCoord = 0;
};

// The glTF metal-rough material; Blinn-Phong parameters are derived from it at shading time. Texture fields
// index Scene::textures (-1: none); factors multiply the texture values as in glTF.
struct Material {
  glm::vec3 baseColor{0.8f};  // linear
  float roughness = 0.5f;     // perceptual roughness in [0,1]
  float metalness = 0.0f;
  glm::vec3 emissive{0.0f};   // linear emitted radiance
  float alpha = 1.0f;         // base colour alpha factor
  AlphaMode alphaMode = AlphaMode::Opaque;
  float alphaCutoff = 0.5f;
  int baseColorTexture = -1;
  int metallicRoughnessTexture = -1;  // G = roughness, B = metalness
  int normalTexture = -1;
  float normalScale = 1.0f;
  int occlusionTexture = -1;  // R = ambient occlusion
  float occlusionStrength = 1.0f;
  int emissiveTexture = -1;
  // Each map's KHR_texture_transform: its UVs become M (u, v, 1) before it is sampled; identity without one.
  glm::mat3x2 baseColorUvTransform{1.0f};
  glm::mat3x2 metallicRoughnessUvTransform{1.0f};
  glm::mat3x2 normalUvTransform{1.0f};
  glm::mat3x2 occlusionUvTransform{1.0f};
  glm::mat3x2 emissiveUvTransform{1.0f};
  // Each map's UV set (glTF texCoord): 0 TEXCOORD_0, 1 TEXCOORD_1 (MeshData::uv1).
  int baseColorTexCoord = 0;
  int metallicRoughnessTexCoord = 0;
  int normalTexCoord = 0;
  int occlusionTexCoord = 0;
  int emissiveTexCoord = 0;
  bool doubleSided = false;  // drawn without back-face culling, the normal flipped on back faces
  // KHR_materials_unlit: the base colour (with its alpha) is the surface's radiance, and no light is reflected.
  bool unlit = false;
  // KHR_materials_ior and KHR_materials_specular: the dielectric part's index of refraction (1 or more, or 0 for
  // F0 1), specular strength (specularFactor) and F0 colour (specularColorFactor, linear, may exceed 1).
  float ior = 1.5f;
  float specular = 1.0f;
  glm::vec3 specularColor{1.0f};
  // KHR_materials_clearcoat: a GGX layer of F0 0.04 over everything else, of this strength (0: none) and
  // perceptual roughness, on the interpolated normal (no normal map).
  float clearcoat = 0.0f;
  float clearcoatRoughness = 0.0f;
  // KHR_materials_sheen: the colour (linear, 0: no sheen) and roughness of a "Charlie" fibre lobe over the base.
  glm::vec3 sheenColor{0.0f};
  float sheenRoughness = 0.0f;
  // KHR_materials_transmission: the share of the light entering the dielectric (not reflected) that passes through
  // it rather than being diffused, tinted by the base colour (0: none).
  float transmission = 0.0f;
  // KHR_materials_volume: the thickness of the volume under the surface, in the object's space (0: thin-walled, no
  // refraction), and the colour white light keeps after attenuationDistance inside it (Beer-Lambert; infinite: no
  // absorption).
  float thickness = 0.0f;
  glm::vec3 attenuationColor{1.0f};
  float attenuationDistance = std::numeric_limits<float>::infinity();
  // The extensions' maps, each multiplying its factor as the specification says: clearcoatTexture (R) and
  // clearcoatRoughnessTexture (G); the coat's own normal map (clearcoatNormalTexture, tangent space, its scale);
  // sheenColorTexture (RGB, sRGB) and sheenRoughnessTexture (A); specularTexture (A) and specularColorTexture (RGB,
  // sRGB); transmissionTexture (R); thicknessTexture (G).
  MaterialMap clearcoatMap{}, clearcoatRoughnessMap{}, clearcoatNormalMap{};
  float clearcoatNormalScale = 1.0f;
  MaterialMap sheenColorMap{}, sheenRoughnessMap{};
  MaterialMap specularMap{}, specularColorMap{};
  MaterialMap transmissionMap{}, thicknessMap{};
};

// A transmissive material lets light through its surface (KHR_materials_transmission), so it is drawn over the
// opaque frame behind it rather than into the G-buffer; an unlit one reflects and transmits nothing.
bool isTransmissive(const Material& material);
// A transmissive material casts a shadow where at most this share of the light entering it passes through, and
// none above: a clear pane casts nothing, a frosted lamp shade with a little transmission its full shadow.
constexpr float kTransmissionShadowCutoff = 0.5f;
// Whether a transmissive material lets shadow rays through, and is left out of the shadow maps: more than
// kTransmissionShadowCutoff of its light passes.
bool passesShadowRays(const Material& material);
// Whether a surface of this material is shaded by the forward pass over the opaque frame rather than through the
// G-buffer: alphaMode BLEND or transmissive.
bool isForwardShaded(const Material& material);

// The dielectric part's F0 colour (rgb) and F90 (a) of KHR_materials_specular: min(((ior - 1) / (ior + 1))^2
// specularColor, 1) specular and specular; the core material's 0.04 and 1 (exactly: ior 1.5 gives 0.25 / 6.25).
glm::vec4 dielectricSpecular(const Material& material);
// Whether a material's dielectric reflects other than the core material's F0 0.04 and F90 1.
bool hasDielectricSpecular(const Material& material);
// Whether a material has a clear coat (KHR_materials_clearcoat, a strength above 0) and a sheen (KHR_materials_sheen,
// a colour other than black): the G-buffer's channels and the lighting permutations are made for those alone.
bool hasClearcoat(const Material& material);
bool hasSheen(const Material& material);

// Analytic shapes keep their identity so that reference renderers can ray-cast them exactly.
enum class Shape { Plane, Sphere, Box, Mesh };

struct SceneObject {
  Shape shape = Shape::Mesh;
  int mesh = -1;  // index into Scene::meshes
  glm::mat4 transform{1.0f};
  Material material;
};

// A spot light's cone (KHR_lights_punctual): full intensity within `innerAngle` of its axis, fading smoothly to
// nothing at `outerAngle` (radians; 0 <= inner <= outer <= pi/2).
struct SpotCone {
  glm::vec3 direction{0.0f, 0.0f, -1.0f};  // the axis, the way the light shines; unit length
  float innerAngle = 0.0f;
  float outerAngle = 0.785398163f;  // pi/4, glTF's default
};

// A point light, or with `spot` a spot light: the same source masked by a cone, its intensity along the axis that
// of the point light (I = P / (4 pi) still; the cone does not concentrate the power).
struct PointLight {
  glm::vec3 position{0.0f};
  float radius = 1.0f;  // influence radius R of the windowed attenuation
  glm::vec3 color{1.0f};
  float luminousPower = 100.0f;  // P in lumens; intensity I = P / (4 pi)
  std::optional<SpotCone> spot = std::nullopt;
  // Whether it casts shadows where the frame shadows as the scene says (ShadowMode::Auto): the loaders set it,
  // true for spot lights and every glTF light, false for JSON point lights and random lights, unless the file says.
  bool castsShadows = false;
};

// glTF's smooth angular falloff of a spot light as a scale and offset of cos(angle to the axis):
// clamp(cos s + o, 0, 1)^2, s = 1 / max(1e-3, cos inner - cos outer), o = -cos(outer) s (KHR_lights_punctual).
struct SpotFalloff {
  float scale, offset;
};
SpotFalloff spotFalloff(const SpotCone& cone);

// A light infinitely far away (the sun): parallel rays of illuminance E on a surface facing it, Lo = f E n.l.
struct DirectionalLight {
  glm::vec3 direction{0.0f, -1.0f, 0.0f};  // the way the light travels, unit length
  glm::vec3 color{1.0f};
  float illuminance = 1.0f;  // E in lux
  bool castsShadows = true;  // as PointLight::castsShadows; a sun casts unless the file says not
};

// Which lights a frame shadows: none, every light, or those whose castsShadows is set (the scene's say).
enum class ShadowMode { None, On, Auto };
// "none", "on", "auto"; throws std::invalid_argument naming the choices otherwise.
ShadowMode parseShadowMode(const std::string& name);
const char* toString(ShadowMode mode);
inline bool castsShadows(bool sceneSays, ShadowMode mode) {
  return mode == ShadowMode::On || (mode == ShadowMode::Auto && sceneSays);
}

// Directional lights are shaded for every pixel from one small uniform block (lighting/light_buffer.hpp).
constexpr size_t kMaxDirectionalLights = 16;

// What lights the scene from afar (image-based lighting, PBR only) and shows behind it: a Radiance .hdr panorama,
// or the procedural sky when `file` is empty. Loading and precomputation belong to the renderer (ibl/).
struct EnvironmentDesc {
  std::string file;  // absolute, or relative to the working directory
  SkyParams sky;
  float intensity = 1.0f;    // multiplies the radiance
  float rotationDeg = 0.0f;  // about +Y, right-handed
};

// What the loaders give glTF models whose scene names no environment. Their metals show little but reflections, so
// the commands that show frames light them by the procedural sky; the measurements keep them without one, to stay
// comparable with earlier runs and with the reference renderer, which has no image-based lighting.
enum class DefaultEnvironment { Sky, None };

// What appendGltf added to a scene for one file, by the file's own indices: a file placed N times then costs one
// conversion of each mesh and one decode (and GPU upload) of each image, not N. The indices are valid while the
// scene's meshes and textures only grow.
struct LoadedGltf {
  std::map<std::pair<int, int>, int> meshes;     // (mesh, primitive) -> Scene::meshes; -1: not drawn
  std::map<int, Material> materials;             // material (-1: glTF's default) -> as converted
  std::map<std::pair<int, bool>, int> textures;  // (texture, sRGB) -> Scene::textures
};

struct GltfPlayback;  // core/scene/gltf_loader.hpp

struct Scene {
  std::string name;
  Camera camera;
  float exposure = 1.0f;        // a plain multiplier of the HDR image before tone mapping
  std::optional<float> ev100;   // the camera's exposure value at ISO 100; with it, exposure multiplies 1 / Lmax
  bool ev100Metered = false;    // ev100 is what the loader's light meter read (model_scene.hpp), not a camera's

  glm::vec3 ambient{0.0f};  // uniform ambient radiance for the PBR model; an environment replaces it
  std::optional<EnvironmentDesc> environment;
  std::vector<MeshData> meshes;
  std::vector<TextureData> textures;
  std::vector<SceneObject> objects;
  std::vector<PointLight> lights;
  std::vector<DirectionalLight> directionalLights;
  std::vector<Camera> cameras;          // the glTF files' perspective cameras, in node order (`--camera N`)
  std::optional<Camera> framedCamera;   // a model given alone: the camera that frames its bounds (`--camera auto`)
  bool gltfPlacedLights = false;        // a glTF file placed lights (KHR_lights_punctual) in the scene
  std::vector<std::string> notes;       // what a loader put in where the file was silent, for the commands to say
  std::map<std::string, LoadedGltf> gltfFiles;  // by canonical path
  // The glTF loads asked to be playable (GltfSelection::playable), which posePlayback poses at other times.
  std::vector<std::shared_ptr<const GltfPlayback>> gltfPlayback;

  // What the post pass multiplies radiance by: `exposure`, times exposureFromEv100(*ev100) when given.
  float displayExposure() const;

  // Adds the mesh of an analytic shape once and an object that uses it.
  SceneObject& addShape(Shape shape, const glm::mat4& transform, const Material& material);
};

// Whether any object's material has alphaMode BLEND (drawn by the transparency pass).
bool hasBlendMaterial(const Scene& scene);
// Whether any object's material is transmissive (isTransmissive).
bool hasTransmissiveMaterial(const Scene& scene);
// Whether an opaque or MASK object's material is unlit: the deferred pass then reads the G-buffer's unlit flag.
bool hasUnlitSurface(const Scene& scene);
// Whether a map of `material` reads the second UV set (TEXCOORD_1).
bool readsTexCoord1(const Material& material);
// The extensions' maps of a material, in the order of Material's fields (and of the geometry pass's texture units).
constexpr size_t kExtensionMapCount = 9;
std::array<const MaterialMap*, kExtensionMapCount> extensionMaps(const Material& material);

class SceneError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Rejects what must never be rendered (NaN/Inf, negative radius or power, roughness outside [0,1]) with one
// line naming `source` and the field, e.g. "scene.json: lights[3].radius: must be finite and >= 0 (got -1)".
void validateScene(const Scene& scene, const std::string& source);

}  // namespace pbr
