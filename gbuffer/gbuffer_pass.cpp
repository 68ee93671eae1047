#include "gbuffer/gbuffer_pass.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <map>
#include <memory>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>

#include <glm/mat2x3.hpp>
#include <glm/matrix.hpp>

#include "gbuffer/gbuffer_bindings.hpp"
#include "gbuffer/object_block.hpp"

namespace pbr {

namespace {

// `bytes` rounded up to the driver's uniform-buffer offset alignment: the stride of blocks bound by range.
GLsizeiptr alignedStride(size_t bytes) {
  GLint align = 256;
  glGetIntegerv(GL_UNIFORM_BUFFER_OFFSET_ALIGNMENT, &align);
  const GLsizeiptr a = align > 0 ? align : 256;
  return (static_cast<GLsizeiptr>(bytes) + a - 1) / a * a;
}

bool mirrors(const glm::mat4& transform) { return glm::determinant(glm::mat3(transform)) < 0.0f; }

// Whether every point of a caster within `box` lies outside the solid a closed mesh bounds as a shadow view of
// `light`'s sees it: always for a cascade, whose depth range spans every caster; for a point or spot light's view,
// when the box keeps clear of the light by 8 near planes, since the frustum's tip before the near plane is then
// empty: it lies within sqrt(1 + 2 t^2) near planes of the eye, t the tangent of the half field of view with the
// border, at most 2.8 (a 60-degree spot cone in a 16-texel square, shadows/shadow_plan.cpp), so within 4.1.
bool eyeOutside(const ShadowCasterView& light, const WorldBounds& box) {
  return light.reach.w == 0.0f ||
         !overlapsSphere(box, glm::vec3(light.reach), 8.0f * shadowNearPlane(light.reach.w));
}

// An affine UV map as the shader's std140 mat2x3: its two rows, each padded to a vec4.
glm::mat2x4 std140Rows(const glm::mat3x2& uvTransform) {
  const glm::mat2x3 rows = glm::transpose(uvTransform);
  return {glm::vec4(rows[0], 0.0f), glm::vec4(rows[1], 0.0f)};
}

std::vector<unsigned char> packObjectBlocks(const Scene& scene, GLsizeiptr stride) {
  std::vector<unsigned char> bytes(static_cast<size_t>(stride) * scene.objects.size());
  for (size_t i = 0; i < scene.objects.size(); ++i) {
    const SceneObject& o = scene.objects[i];
    const Material& m = o.material;
    ObjectBlock b{};
    b.model = o.transform;
    // A transform scaled to nothing (a hidden node of a playing glTF animation) draws no fragment: its normal
    // matrix is never read, and left 0 rather than the inverse's infinities.
    if (glm::determinant(glm::mat3(o.transform)) != 0.0f) b.normalMatrix = glm::transpose(glm::inverse(o.transform));
    b.baseColor = glm::vec4(m.baseColor, m.alpha);
    b.material = glm::vec4(m.roughness, m.metalness, m.normalScale, m.occlusionStrength);
    // A BLEND material casts a cut-out shadow at kBlendShadowCutoff (the depth permutation's ALPHA_MASK).
    b.emissive = glm::vec4(m.emissive, m.alphaMode == AlphaMode::Blend ? kBlendShadowCutoff : m.alphaCutoff);
    using namespace gbuffer_binding;
    // The maps that read TEXCOORD_1, a bit per texture unit (read by the UV1 permutation only).
    const std::pair<size_t, bool> secondSet[] = {
        {kBaseColorMapUnit.index, m.baseColorTexCoord == 1},
        {kMetallicRoughnessMapUnit.index, m.metallicRoughnessTexCoord == 1},
        {kNormalMapUnit.index, m.normalTexCoord == 1},
        {kOcclusionMapUnit.index, m.occlusionTexCoord == 1},
        {kEmissiveMapUnit.index, m.emissiveTexCoord == 1}};
    unsigned uv1Maps = 0;
    for (const auto& [unit, second] : secondSet) uv1Maps |= second ? 1u << unit : 0u;
    const std::array<const MaterialMap*, kExtensionMapCount> extensions = extensionMaps(m);
    unsigned uv1Extensions = 0;
    for (size_t e = 0; e < kExtensionMapCount; ++e) {
      uv1Extensions |= extensions[e]->texCoord == 1 ? 1u << e : 0u;
      b.extensionUvTransform[e] = std140Rows(extensions[e]->uvTransform);
    }
    b.orientation = glm::vec4(mirrors(o.transform) ? -1.0f : 1.0f, static_cast<float>(uv1Maps),
                              static_cast<float>(uv1Extensions), 0.0f);
    b.dielectric = dielectricSpecular(m);
    b.layers = glm::vec4(m.clearcoat, m.clearcoatRoughness, m.sheenRoughness, m.clearcoatNormalScale);
    b.sheenColor = glm::vec4(m.sheenColor, 0.0f);
    const bool absorbs = std::isfinite(m.attenuationDistance);
    b.transmission = glm::vec4(m.transmission, m.thickness, absorbs ? m.attenuationDistance : 0.0f, m.ior);
    b.attenuationColor = glm::vec4(m.attenuationColor, 0.0f);
    const double f0 = (double(m.ior) - 1.0) * (double(m.ior) - 1.0) / ((double(m.ior) + 1.0) * (double(m.ior) + 1.0));
    b.specularFactors = glm::vec4(m.specularColor, float(f0));
    b.uvTransform[kBaseColorMapUnit.index] = std140Rows(m.baseColorUvTransform);
    b.uvTransform[kMetallicRoughnessMapUnit.index] = std140Rows(m.metallicRoughnessUvTransform);
    b.uvTransform[kNormalMapUnit.index] = std140Rows(m.normalUvTransform);
    b.uvTransform[kOcclusionMapUnit.index] = std140Rows(m.occlusionUvTransform);
    b.uvTransform[kEmissiveMapUnit.index] = std140Rows(m.emissiveUvTransform);
    std::memcpy(&bytes[i * static_cast<size_t>(stride)], &b, sizeof b);
  }
  return bytes;
}

// The shadow casters' coarser spheres: segments around (half as many rings), coarsest first.
constexpr std::array<int, 3> kSphereLodSegments = {8, 16, 32};

// The defines of the depth permutation a caster draws with (shaders/gbuffer/shadow_depth.*): ALPHA_MASK for an
// alpha-masked material, BASE_COLOR_MAP where its alpha comes from a texture (read through TEXCOORD_1 with UV1),
// VERTEX_COLORS where the vertex colours' alpha multiplies it.
ShaderDefines depthPermutation(bool masked, bool maskTexture, bool vertexColors, bool uv1,
                               bool viewportFromVertex) {
  auto flag = [](bool b) { return std::string(b ? "1" : "0"); };
  return concat({{"ALPHA_MASK", flag(masked)},
                 {"BASE_COLOR_MAP", flag(maskTexture)},
                 {"VERTEX_COLORS", flag(vertexColors)},
                 {"UV1", flag(uv1)},
                 {"VIEWPORT_FROM_VERTEX", flag(viewportFromVertex)}},
                gbufferBindingDefines());
}

}  // namespace

std::array<int, GBufferPass::kMapCount> GBufferPass::materialMaps(const Material& m) {
  using namespace gbuffer_binding;
  static_assert(kBaseColorMapUnit.index < kMapCount && kMetallicRoughnessMapUnit.index < kMapCount &&
                    kNormalMapUnit.index < kMapCount && kOcclusionMapUnit.index < kMapCount &&
                    kEmissiveMapUnit.index < kMapCount,
                "material maps are bound to units 0 .. kMapCount - 1");
  static_assert(std::extent_v<decltype(ObjectBlock::uvTransform)> == kMapCount, "one UV transform per map unit");
  std::array<int, kMapCount> maps{};
  maps[kBaseColorMapUnit.index] = m.baseColorTexture;
  maps[kMetallicRoughnessMapUnit.index] = m.metallicRoughnessTexture;
  maps[kNormalMapUnit.index] = m.normalTexture;
  maps[kOcclusionMapUnit.index] = m.occlusionTexture;
  maps[kEmissiveMapUnit.index] = m.emissiveTexture;
  return maps;
}

ShaderDefines GBufferPass::streamPermutation(const MeshData& mesh) {
  auto flag = [](bool b) { return std::string(b ? "1" : "0"); };
  return {{"VERTEX_COLORS", flag(!mesh.colors.empty())}, {"UV1", flag(!mesh.uv1.empty())}};
}

ShaderDefines GBufferPass::permutation(const Material& m) {
  auto flag = [](bool b) { return std::string(b ? "1" : "0"); };
  ShaderDefines defines = {{"BASE_COLOR_MAP", flag(m.baseColorTexture >= 0)},
                           {"METALLIC_ROUGHNESS_MAP", flag(m.metallicRoughnessTexture >= 0)},
                           {"NORMAL_MAP", flag(m.normalTexture >= 0)},
                           {"OCCLUSION_MAP", flag(m.occlusionTexture >= 0)},
                           {"EMISSIVE_MAP", flag(m.emissiveTexture >= 0)},
                           {"ALPHA_MASK", flag(m.alphaMode == AlphaMode::Mask)},
                           {"UNLIT", flag(m.unlit)}};
  // Named only where used, so that the other permutations keep their define lists (an undefined name is 0 in #if).
  if (isTransmissive(m)) defines.push_back({"MATERIAL_TRANSMISSION", "1"});
  const char* const mapDefines[kExtensionMapCount] = {
      "CLEARCOAT_MAP",   "CLEARCOAT_ROUGHNESS_MAP", "CLEARCOAT_NORMAL_MAP", "SHEEN_COLOR_MAP", "SHEEN_ROUGHNESS_MAP",
      "SPECULAR_MAP",    "SPECULAR_COLOR_MAP",      "TRANSMISSION_MAP",     "THICKNESS_MAP"};
  const std::array<const MaterialMap*, kExtensionMapCount> maps = extensionMaps(m);
  for (size_t i = 0; i < kExtensionMapCount; ++i) {
    if (maps[i]->texture >= 0) defines.push_back({mapDefines[i], "1"});
  }
  return defines;
}

GBufferPass::GBufferPass(ProgramCache& programs, const Scene& scene)
    : cache_(programs),
      blockStride_(alignedStride(sizeof(ObjectBlock))),
      shadowViewStride_(alignedStride(kViewsPerDraw * sizeof(glm::mat4))),
      objectBlocks_("gbuffer.objectBlocks", static_cast<size_t>(blockStride_) * scene.objects.size(),
                    packObjectBlocks(scene, blockStride_).data()) {
  meshes_.reserve(scene.meshes.size());
  for (const MeshData& m : scene.meshes) meshes_.emplace_back(m, "mesh " + std::to_string(meshes_.size()));
  textures_.reserve(scene.textures.size());
  for (const TextureData& t : scene.textures) textures_.emplace_back(t);

  // Every G-buffer draw writes the channels the scene's layout has.
  layout_ = gbufferLayout(scene);
  blendedExtensions_ = materialExtensions(scene, true);
  const ShaderDefines layoutDefines = {{"MATERIAL_SPECULAR", layout_.specular ? "1" : "0"},
                                       {"MATERIAL_CLEARCOAT", layout_.clearcoat ? "1" : "0"},
                                       {"MATERIAL_SHEEN", layout_.sheen ? "1" : "0"}};
  std::map<std::string, size_t> programIndex, blendedIndex;  // by the permutation's define list
  for (size_t i = 0; i < scene.objects.size(); ++i) {
    const SceneObject& o = scene.objects[i];
    const MeshData& mesh = scene.meshes.at(static_cast<size_t>(o.mesh));
    const ShaderDefines defines = concat(permutation(o.material), streamPermutation(mesh));
    std::string key;
    for (const ShaderDefine& d : defines) key += d.value;
    Draw d{};
    d.blended = isForwardShaded(o.material);
    d.transmissive = isTransmissive(o.material);
    d.castsShadow = !passesShadowRays(o.material);
    if (d.blended) {
      // Drawn by other passes' programs (drawBlended): no G-buffer program.
      auto it = blendedIndex.find(key);
      if (it == blendedIndex.end()) {
        blendedPermutations_.push_back(defines);
        it = blendedIndex.emplace(key, blendedPermutations_.size() - 1).first;
      }
      d.program = it->second;
    } else {
      auto it = programIndex.find(key);
      if (it == programIndex.end()) {
        programs_.push_back(&programs.graphics("gbuffer/gbuffer.vert", "gbuffer/gbuffer.frag",
                                               concat(concat(defines, layoutDefines), gbufferBindingDefines())));
        it = programIndex.emplace(key, programs_.size() - 1).first;
      }
      d.program = it->second;
    }
    d.mesh = o.mesh;
    d.blockOffset = static_cast<GLintptr>(i) * blockStride_;
    d.doubleSided = o.material.doubleSided;
    d.mirrored = mirrors(o.transform);
    d.bounds = meshBounds(scene.meshes.at(static_cast<size_t>(o.mesh)), o.transform);
    d.castsCutOut = o.material.alphaMode == AlphaMode::Mask || o.material.alphaMode == AlphaMode::Blend;
    d.cutOutTexture = d.castsCutOut && o.material.baseColorTexture >= 0;
    d.cutOutColors = d.castsCutOut && !mesh.colors.empty();
    d.cutOutUv1 = d.cutOutTexture && !mesh.uv1.empty();
    d.triangles = scene.meshes.at(static_cast<size_t>(o.mesh)).indices.size() / 3;
    if (o.shape == Shape::Sphere) {
      const glm::mat3 m(o.transform);
      d.sphereCentre = glm::vec3(o.transform[3]);
      d.sphereRadius = 0.5f * std::max({glm::length(m[0]), glm::length(m[1]), glm::length(m[2])});
      if (sphereLods_.empty()) {
        for (size_t k = 0; k < kSphereLodSegments.size(); ++k) {
          const int segments = kSphereLodSegments[k];
          const MeshData lod = makeSphereMesh(segments, segments / 2);
          const MeshClosure closure = meshClosure(lod);
          sphereLodClosure_ = k == 0 || closure == sphereLodClosure_ ? closure : MeshClosure::Open;
          sphereLods_.emplace_back(lod, "shadow sphere " + std::to_string(segments));
        }
      }
    }
    bounds_.add(d.bounds);
    const std::array<const MaterialMap*, kExtensionMapCount> extensions = extensionMaps(o.material);
    for (size_t e = 0; e < kExtensionMapCount; ++e) {
      if (extensions[e]->texture < 0) continue;
      const GpuTexture& t = textures_.at(static_cast<size_t>(extensions[e]->texture));
      d.extensionTextures[e] = t.texture().id();
      d.extensionSamplers[e] = t.sampler().id();
      d.extensionTextured = true;
    }
    const std::array<int, kMapCount> maps = materialMaps(o.material);
    for (size_t unit = 0; unit < kMapCount; ++unit) {
      if (maps[unit] < 0) continue;
      const GpuTexture& t = textures_.at(static_cast<size_t>(maps[unit]));
      d.textures[unit] = t.texture().id();
      d.samplers[unit] = t.sampler().id();
      d.textured = true;
    }
    draws_.push_back(d);
  }
  // Fewer program switches; the depth test makes the order of opaque draws otherwise irrelevant.
  std::stable_sort(draws_.begin(), draws_.end(), [](const Draw& a, const Draw& b) {
    return a.blended != b.blended ? b.blended : a.program < b.program;
  });
  unlit_ = hasUnlitSurface(scene);
  opaqueDraws_ = size_t(std::count_if(draws_.begin(), draws_.end(), [](const Draw& d) { return !d.blended; }));
  transmissive_ = std::any_of(draws_.begin(), draws_.end(), [](const Draw& d) { return d.transmissive; });
}

const std::vector<CasterPlane>& GBufferPass::casterPlanes(const Scene& scene) {
  if (!planesFound_) findCasterPlanes(scene);
  return casterPlanes_;
}

void GBufferPass::findCasterPlanes(const Scene& scene) {
  if (meshPlanar_.empty()) {
    for (const MeshData& mesh : scene.meshes) meshPlanar_.push_back(casterPlane(mesh, glm::mat4(1.0f)).has_value());
  }
  struct Found {
    size_t draw;
    CasterPlane plane;
    float area;
  };
  std::vector<Found> found;
  for (size_t i = 0; i < draws_.size(); ++i) {
    Draw& d = draws_[i];
    d.planeSlot = -1;
    if (!d.castsShadow || !meshPlanar_[static_cast<size_t>(d.mesh)]) continue;
    const SceneObject& o = scene.objects.at(static_cast<size_t>(d.blockOffset / blockStride_));
    if (const std::optional<CasterPlane> plane = casterPlane(scene.meshes.at(size_t(d.mesh)), o.transform)) {
      const glm::vec3 e = d.bounds.max - d.bounds.min;
      found.push_back({i, *plane, e.x * e.y + e.y * e.z + e.z * e.x});
    }
  }
  std::stable_sort(found.begin(), found.end(), [](const Found& a, const Found& b) { return a.area > b.area; });
  casterPlanes_.clear();
  for (size_t k = 0; k < found.size() && k < kMaxCasterPlanes; ++k) {
    draws_[found[k].draw].planeSlot = int(k);
    casterPlanes_.push_back(found[k].plane);
  }
  planesFound_ = true;
}

void GBufferPass::findClosures(const Scene& scene) {
  std::vector<std::optional<MeshClosure>> perMesh(scene.meshes.size());
  for (Draw& d : draws_) {
    if (!d.castsShadow || d.castsCutOut) continue;
    std::optional<MeshClosure>& closure = perMesh.at(static_cast<size_t>(d.mesh));
    if (!closure) closure = meshClosure(scene.meshes[static_cast<size_t>(d.mesh)]);
    d.closure = d.sphereRadius > 0.0f && *closure != sphereLodClosure_ ? MeshClosure::Open : *closure;
  }
  closuresFound_ = true;
}

void GBufferPass::updatePose(const Scene& scene, const std::vector<int>& changedMeshes) {
  if (!scene.objects.empty()) {
    objectBlocks_.upload(packObjectBlocks(scene, blockStride_).data(), objectBlocks_.size());
  }
  for (const int m : changedMeshes) {
    meshes_.at(static_cast<size_t>(m)) = GpuMesh(scene.meshes.at(static_cast<size_t>(m)), "mesh " + std::to_string(m));
  }
  bounds_ = WorldBounds{};
  for (Draw& d : draws_) {
    const SceneObject& o = scene.objects.at(static_cast<size_t>(d.blockOffset / blockStride_));
    d.mirrored = mirrors(o.transform);
    d.bounds = meshBounds(scene.meshes.at(static_cast<size_t>(o.mesh)), o.transform);
    bounds_.add(d.bounds);
  }
  if (!meshPlanar_.empty()) {
    for (const int m : changedMeshes) {
      meshPlanar_.at(size_t(m)) = casterPlane(scene.meshes.at(size_t(m)), glm::mat4(1.0f)).has_value();
    }
  }
  planesFound_ = false;
}

void GBufferPass::render(const GBuffer& target, const UniformBuffer<FrameBlock>& frame) const {
  if (!(target.layout == layout_)) throw std::logic_error("G-buffer pass: the target's layout is not the scene's");
  glBindFramebuffer(GL_FRAMEBUFFER, target.framebuffer.id());
  glViewport(0, 0, target.width, target.height);
  glClipControl(GL_LOWER_LEFT, GL_ZERO_TO_ONE);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_GREATER);
  glDepthMask(GL_TRUE);
  glCullFace(GL_BACK);
  glEnable(GL_FRAMEBUFFER_SRGB);
  const float zeros[4] = {0, 0, 0, 0}, background[4] = {0, 0, 0, 1};
  const float farDepth = 0.0f;
  // The specular channel is read only where depth says a surface was drawn: it needs no clearing. The radiance
  // target (attachment 3) starts as the background without an environment (above).
  for (int i = 0; i < 4; ++i) {
    glClearNamedFramebufferfv(target.framebuffer.id(), GL_COLOR, i, i == 3 ? background : zeros);
  }
  glClearNamedFramebufferfv(target.framebuffer.id(), GL_DEPTH, 0, &farDepth);

  frame.bind(kFrameUbo.index);
  size_t bound = std::numeric_limits<size_t>::max();
  for (size_t i = 0; i < opaqueDraws_; ++i) {
    const Draw& d = draws_[i];
    if (d.program != bound) programs_[d.program]->use();
    bound = d.program;
    if (d.doubleSided) {
      glDisable(GL_CULL_FACE);
    } else {
      glEnable(GL_CULL_FACE);
    }
    glFrontFace(d.mirrored ? GL_CW : GL_CCW);
    if (d.textured) {
      glBindTextures(0, static_cast<GLsizei>(kMapCount), d.textures.data());
      glBindSamplers(0, static_cast<GLsizei>(kMapCount), d.samplers.data());
    }
    if (d.extensionTextured) {
      glBindTextures(gbuffer_binding::kFirstExtensionMapUnit, GLsizei(kExtensionMapCount), d.extensionTextures.data());
      glBindSamplers(gbuffer_binding::kFirstExtensionMapUnit, GLsizei(kExtensionMapCount), d.extensionSamplers.data());
    }
    glBindBufferRange(GL_UNIFORM_BUFFER, gbuffer_binding::kObjectUbo.index, objectBlocks_.id(), d.blockOffset,
                      sizeof(ObjectBlock));
    meshes_[static_cast<size_t>(d.mesh)].draw();
  }
  // Later passes fetch from these units with their own (mipmap-less) textures: a sampler left bound would make
  // them incomplete.
  glBindSamplers(0, static_cast<GLsizei>(kMapCount), nullptr);
  glBindSamplers(gbuffer_binding::kFirstExtensionMapUnit, GLsizei(kExtensionMapCount), nullptr);
  glFrontFace(GL_CCW);
  glDisable(GL_FRAMEBUFFER_SRGB);
  glDisable(GL_CULL_FACE);
  glDisable(GL_DEPTH_TEST);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

const GpuMesh& GBufferPass::casterMesh(const Draw& d, const ShadowCasterView& v, const glm::vec4& wRow) const {
  const GpuMesh& own = meshes_[static_cast<size_t>(d.mesh)];
  if (!(d.sphereRadius > 0.0f)) return own;
  // The smallest w on the sphere's part in the view, where its texels are smallest: at least its smallest w, and in
  // a perspective view (half-angle tangent t) at least its distance from the apex over sqrt(1 + 2 t^2), the most a
  // point's distance exceeds its w inside the frustum.
  float w = glm::dot(glm::vec3(wRow), d.sphereCentre) + wRow.w - d.sphereRadius * glm::length(glm::vec3(wRow));
  if (v.reach.w > 0.0f) {
    const float t = 0.5f * v.texelWorld * float(v.viewport.z);
    const float nearest = glm::distance(d.sphereCentre, glm::vec3(v.reach)) - d.sphereRadius;
    w = std::max(w, nearest / std::sqrt(1.0f + 2.0f * t * t));
  }
  if (!(w > 0.0f)) return own;
  const float texel = v.texelWorld * w;
  for (size_t i = 0; i < kSphereLodSegments.size(); ++i) {
    const int segments = kSphereLodSegments[i];
    const size_t triangles = size_t(segments) * size_t(segments);  // segments x segments / 2 quads
    if (triangles < d.triangles && sphereTessellationDepth(d.sphereRadius, segments) <= 0.5f * texel) {
      return sphereLods_[i];
    }
  }
  return own;
}

void GBufferPass::drawBlended(GLuint framebuffer, const Camera& camera, const BlendedProgram& program,
                              BlendOrder order, int repeats, BlendedSet set) const {
  std::vector<const Draw*> blended;
  for (size_t i = opaqueDraws_; i < draws_.size(); ++i) {
    const bool transmissive = draws_[i].transmissive;
    if (set == BlendedSet::All || transmissive == (set == BlendedSet::Transmissive)) blended.push_back(&draws_[i]);
  }
  if (order == BlendOrder::BackToFront) {
    // By the distance of the bounds' centres, which orders them as their view depths do for objects ahead of the
    // camera and keeps the order when the camera turns on the spot (glTF-Sample-Viewer sorts by the centre's depth);
    // along parallel rays by the centres' depth itself, the distance from the camera's plane.
    const glm::vec3 forward = glm::normalize(camera.target - camera.position);
    auto farness = [&](const Draw* d) {
      const glm::vec3 c = 0.5f * (d->bounds.min + d->bounds.max) - camera.position;
      return camera.orthographic ? glm::dot(c, forward) : glm::dot(c, c);
    };
    std::stable_sort(blended.begin(), blended.end(),
                     [&](const Draw* a, const Draw* b) { return farness(a) > farness(b); });
  }
  glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_GREATER);
  glDepthMask(set == BlendedSet::Transmissive ? GL_TRUE : GL_FALSE);
  std::vector<BindingPoint> bindings = {gbuffer_binding::kObjectUbo};
  const std::vector<BindingPoint> maps = materialMapBindings();
  bindings.insert(bindings.end(), maps.begin(), maps.end());
  for (const Draw* d : blended) {
    glFrontFace(d->mirrored ? GL_CW : GL_CCW);
    if (d->textured) {
      glBindTextures(0, static_cast<GLsizei>(kMapCount), d->textures.data());
      glBindSamplers(0, static_cast<GLsizei>(kMapCount), d->samplers.data());
    }
    if (d->extensionTextured) {
      glBindTextures(gbuffer_binding::kFirstExtensionMapUnit, GLsizei(kExtensionMapCount),
                     d->extensionTextures.data());
      glBindSamplers(gbuffer_binding::kFirstExtensionMapUnit, GLsizei(kExtensionMapCount),
                     d->extensionSamplers.data());
    }
    glBindBufferRange(GL_UNIFORM_BUFFER, gbuffer_binding::kObjectUbo.index, objectBlocks_.id(), d->blockOffset,
                      sizeof(ObjectBlock));
    // The faces each round draws: the front ones; both at once (GL_NONE); or for a double-sided object composited
    // in order its back faces, then its front faces over them.
    std::vector<GLenum> culled = {GL_BACK};
    if (d->doubleSided) culled = order == BlendOrder::BackToFront ? std::vector<GLenum>{GL_FRONT, GL_BACK}
                                                                  : std::vector<GLenum>{GL_NONE};
    for (const GLenum cull : culled) {
      if (cull == GL_NONE) {
        glDisable(GL_CULL_FACE);
      } else {
        glEnable(GL_CULL_FACE);
        glCullFace(cull);
      }
      for (int r = 0; r < repeats; ++r) {
        program(r, "gbuffer/gbuffer.vert", blendedPermutations_[d->program], bindings).use();
        meshes_[static_cast<size_t>(d->mesh)].draw();
      }
    }
  }
  glBindSamplers(0, static_cast<GLsizei>(kMapCount), nullptr);
  glBindSamplers(gbuffer_binding::kFirstExtensionMapUnit, GLsizei(kExtensionMapCount), nullptr);
  glCullFace(GL_BACK);
  glDisable(GL_CULL_FACE);
  glFrontFace(GL_CCW);
  glDepthMask(GL_TRUE);
  glDisable(GL_DEPTH_TEST);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

ShadowCasterDraws GBufferPass::renderDepth(const Scene& scene, GLuint framebuffer,
                                           const std::vector<ShadowCasterView>& views, bool viewportFromVertex) {
  if (!closuresFound_) findClosures(scene);
  if (!planesFound_) findCasterPlanes(scene);
  glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
  glClipControl(GL_LOWER_LEFT, GL_ZERO_TO_ONE);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_GREATER);
  glDepthMask(GL_TRUE);
  glCullFace(GL_BACK);
  // Each draw's depth program for this way of drawing, looked up once.
  std::vector<const Program*>& depthPrograms = depthPrograms_[viewportFromVertex ? 1 : 0];
  if (depthPrograms.empty()) {
    for (const Draw& d : draws_) {
      depthPrograms.push_back(&cache_.graphics("gbuffer/shadow_depth.vert", "gbuffer/shadow_depth.frag",
                                               depthPermutation(d.castsCutOut, d.cutOutTexture, d.cutOutColors,
                                                                d.cutOutUv1, viewportFromVertex)));
    }
  }
  // The views in groups of one light's consecutive views, at most kViewsPerDraw, each group's view-projections in a
  // block of its own within one buffer, at the driver's offset alignment.
  std::vector<std::pair<size_t, size_t>> groups;  // first view, views
  for (size_t v = 0; v < views.size(); ++v) {
    if (groups.empty() || views[v].light != views[groups.back().first].light ||
        groups.back().second == kViewsPerDraw) {
      groups.push_back({v, 0});
    }
    ++groups.back().second;
  }
  const size_t blockBytes = kViewsPerDraw * sizeof(glm::mat4);
  const size_t stride = static_cast<size_t>(shadowViewStride_);
  std::vector<unsigned char> blocks(groups.size() * stride);
  for (size_t g = 0; g < groups.size(); ++g) {
    for (size_t i = 0; i < groups[g].second; ++i) {
      std::memcpy(&blocks[g * stride + i * sizeof(glm::mat4)], &views[groups[g].first + i].viewProjection[0][0],
                  sizeof(glm::mat4));
    }
  }
  if (!blocks.empty()) {
    if (!shadowViews_ || shadowViews_->size() < blocks.size()) {
      shadowViews_ = std::make_unique<Buffer>("gbuffer.shadowViews", blocks.size(), nullptr, GL_DYNAMIC_STORAGE_BIT);
    }
    glNamedBufferSubData(shadowViews_->id(), 0, GLsizeiptr(blocks.size()), blocks.data());
  }

  ShadowCasterDraws drawn;
  drawn.rects.resize(views.size());
  for (size_t v = 0; v < views.size(); ++v) drawn.rects[v] = glm::ivec4(views[v].viewport.x, views[v].viewport.y, 0, 0);
  std::vector<const GpuMesh*> meshes(kViewsPerDraw);
  std::vector<FrustumPlanes> planes(kViewsPerDraw);
  std::vector<glm::vec4> wRows(kViewsPerDraw);
  for (size_t g = 0; g < groups.size(); ++g) {
    const auto [first, count] = groups[g];
    glBindBufferRange(GL_UNIFORM_BUFFER, gbuffer_binding::kShadowViewsUbo.index, shadowViews_->id(),
                      GLintptr(g * stride), GLsizeiptr(blockBytes));
    for (size_t i = 0; i < count; ++i) {
      const ShadowCasterView& v = views[first + i];
      if (viewportFromVertex) {
        glViewportIndexedf(GLuint(i), float(v.viewport.x), float(v.viewport.y), float(v.viewport.z),
                           float(v.viewport.w));
      }
      planes[i] = frustumPlanes(v.viewProjection);
      const glm::mat4& m = v.viewProjection;
      wRows[i] = glm::vec4(m[0][3], m[1][3], m[2][3], m[3][3]);
    }
    const Program* bound = nullptr;
    for (size_t d = 0; d < draws_.size(); ++d) {
      const Draw& draw = draws_[d];
      if (!draw.castsShadow) continue;
      // The tessellation each view draws the caster with; none where the view cannot see it.
      bool any = false;
      for (size_t i = 0; i < count; ++i) {
        const ShadowCasterView& v = views[first + i];
        const bool seen = !(draw.planeSlot >= 0 && (v.skipPlanes >> draw.planeSlot & 1u) != 0u) &&
                          !outsideFrustum(planes[i], draw.bounds) &&
                          !(v.reach.w > 0.0f && !overlapsSphere(draw.bounds, glm::vec3(v.reach), v.reach.w));
        meshes[i] = seen ? &casterMesh(draw, v, wRows[i]) : nullptr;
        any = any || seen;
        if (seen) drawn.rects[first + i] = joinRects(drawn.rects[first + i],
                                                     coveredRect(draw.bounds, v.viewProjection, v.viewport));
      }
      if (!any) continue;
      if (depthPrograms[d] != bound) depthPrograms[d]->use();
      bound = depthPrograms[d];
      if (draw.cutOutTexture) {
        const GLuint unit = gbuffer_binding::kBaseColorMapUnit.index;
        glBindTextureUnit(unit, draw.textures[unit]);
        glBindSampler(unit, draw.samplers[unit]);
      }
      glBindBufferRange(GL_UNIFORM_BUFFER, gbuffer_binding::kObjectUbo.index, objectBlocks_.id(), draw.blockOffset,
                        sizeof(ObjectBlock));
      const bool oneSided = draw.closure != MeshClosure::Open && eyeOutside(views[first], draw.bounds);
      if (oneSided) {
        glEnable(GL_CULL_FACE);
        glFrontFace((draw.closure == MeshClosure::Inward) != draw.mirrored ? GL_CW : GL_CCW);
      } else {
        glDisable(GL_CULL_FACE);
      }
      // Runs of consecutive views drawing the same tessellation: one instanced draw each, or without the viewport
      // from the vertex shader one draw per view.
      for (size_t i = 0; i < count;) {
        size_t end = i + 1;
        if (viewportFromVertex) {
          while (end < count && meshes[end] == meshes[i]) ++end;
        }
        if (meshes[i]) {
          if (!viewportFromVertex) {
            const glm::ivec4& r = views[first + i].viewport;
            glViewport(r.x, r.y, r.z, r.w);
          }
          glProgramUniform1ui(bound->id(), 0, GLuint(i));
          meshes[i]->drawInstanced(int(end - i));
          ++drawn.draws;
          drawn.oneSided += oneSided ? 1 : 0;
        }
        i = end;
      }
    }
  }
  glBindSampler(gbuffer_binding::kBaseColorMapUnit.index, 0);
  glDisable(GL_CULL_FACE);
  glFrontFace(GL_CCW);
  glDisable(GL_DEPTH_TEST);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  return drawn;
}

}  // namespace pbr
