#pragma once
#include <array>
#include <memory>
#include <vector>

#include "core/gl/blended_surfaces.hpp"
#include "core/scene/bounds.hpp"
#include "core/scene/caster_plane.hpp"
#include "core/scene/closed_mesh.hpp"
#include "core/scene/frame_block.hpp"
#include "core/gl/gpu_mesh.hpp"
#include "core/gl/gpu_texture.hpp"
#include "core/scene/scene.hpp"
#include "core/gl/program_cache.hpp"
#include "core/scene/shadow_settings.hpp"
#include "core/gl/uniform_buffer.hpp"
#include "gbuffer/gbuffer.hpp"

namespace pbr {

// Rasterizes a scene's objects into the G-buffer and their emitted radiance (alpha 0) into the frame's radiance
// target, which is black with alpha 1 where no surface is drawn: the background of a frame without an environment,
// as the lighting pass would write it, so that it need not write it again.
// Meshes, textures (with mipmaps) and per-object blocks are uploaded once per scene. Each material selects a
// shader permutation (the maps it samples, alpha masking), compiled once for all the draws that use it.
class GBufferPass {
 public:
  GBufferPass(ProgramCache& programs, const Scene& scene);
  void render(const GBuffer& target, const UniformBuffer<FrameBlock>& frame) const;
  // The scene's objects moved and the meshes `changedMeshes` rewritten in place (a glTF animation posed again,
  // core/scene/gltf_loader.hpp posePlayback): their blocks, bounds and vertex buffers uploaded again. Built-in shapes
  // (whose spheres the shadow views draw coarser) do not move.
  void updatePose(const Scene& scene, const std::vector<int>& changedMeshes);

  // Shadow casters: every object's depth into `framebuffer`'s depth attachment (reversed Z), into each view's square,
  // objects outside the view's frustum left out. An open mesh (a plane, a shell with holes) draws both faces; a
  // closed one (meshClosure) only those turned toward the light, unless the light may lie inside its box or a view's
  // near plane may cut it; `scene` is the one the pass was made from, whose meshes the first call finds closed or not
  // (and planar, where casterPlanes has not found them since the last pose: the views' skipPlanes name its slots).
  // A light's consecutive views are drawn together, up to kViewsPerDraw, their matrices in one block; with
  // `viewportFromVertex` (GL_ARB_shader_viewport_layer_array, ShadowDraws::PerLight) a caster takes one instanced
  // draw per run of them that sees it with one tessellation, each instance choosing its view's viewport in the
  // vertex shader; without it, a draw per view. The depth programs are compiled on first use. Returns the draws
  // made and the texels each view's casters may have written.
  ShadowCasterDraws renderDepth(const Scene& scene, GLuint framebuffer, const std::vector<ShadowCasterView>& views,
                                bool viewportFromVertex);
  // Views one shadow draw may cover: GL's least number of viewports (shaders/gbuffer/shadow_depth.vert).
  static constexpr size_t kViewsPerDraw = 16;
  // Whether the scene has forward-shaded objects (BLEND or transmissive), which the G-buffer leaves out and
  // drawBlended draws.
  bool hasBlended() const { return opaqueDraws_ < draws_.size(); }
  // Whether the G-buffer holds unlit surfaces (hasUnlitSurface), whose pixels the lighting pass leaves unlit.
  bool hasUnlit() const { return unlit_; }
  // The channels the scene's materials need (gbufferLayout), which every G-buffer program writes: the target
  // render() draws into must have them.
  const GBufferLayout& layout() const { return layout_; }
  // The extensions the forward-shaded materials use (materialExtensions), which drawBlended's programs shade.
  const GBufferLayout& blendedExtensions() const { return blendedExtensions_; }
  // The forward-shaded objects of `set` into `framebuffer` (BlendedSurfaces::draw): depth-tested, depth written by
  // the transmissive set alone, each through the program `program` makes from this pass's vertex shader and the
  // object's permutation; BackToFront orders them as seen by `camera`.
  void drawBlended(GLuint framebuffer, const Camera& camera, const BlendedProgram& program, BlendOrder order,
                   int repeats, BlendedSet set) const;
  // Whether the scene has transmissive objects (BlendedSet::Transmissive).
  bool hasTransmissive() const { return transmissive_; }
  // Every object's world box together.
  const WorldBounds& bounds() const { return bounds_; }
  // The planes of the planar casters (casterPlane), the kMaxCasterPlanes largest by their boxes' area: a view whose
  // ShadowCasterView::skipPlanes has bit i set leaves plane i's caster out. Found on the first call after the scene
  // is made or posed (a pass over every mesh's vertices), so that a frame without shadows does not pay for them.
  const std::vector<CasterPlane>& casterPlanes(const Scene& scene);

  // The defines of the permutation a material draws with: BASE_COLOR_MAP, METALLIC_ROUGHNESS_MAP, NORMAL_MAP,
  // OCCLUSION_MAP, EMISSIVE_MAP, ALPHA_MASK and UNLIT, each 0 or 1.
  static ShaderDefines permutation(const Material& material);
  // The defines of the optional vertex streams a mesh has (MeshData::colors, uv1): VERTEX_COLORS and UV1, each 0
  // or 1, added to its objects' permutations.
  static ShaderDefines streamPermutation(const MeshData& mesh);

 private:
  static constexpr size_t kMapCount = 5;
  struct Draw {
    int mesh;
    bool blended;    // forward-shaded (isForwardShaded): not in the G-buffer
    bool transmissive;  // KHR_materials_transmission (isTransmissive)
    bool castsShadow;   // drawn into the shadow maps (all but passesShadowRays)
    size_t program;  // programs_ index, or for a blended draw blendedPermutations_ index
    GLintptr blockOffset;
    bool doubleSided;
    bool mirrored;  // det(model) < 0: front faces wind clockwise
    bool textured;
    std::array<GLuint, kMapCount> textures;  // by texture unit; 0 where the draw samples nothing
    std::array<GLuint, kMapCount> samplers;
    // The extensions' maps (units from gbuffer_binding::kFirstExtensionMapUnit, extensionMaps' order).
    bool extensionTextured;
    std::array<GLuint, kExtensionMapCount> extensionTextures;
    std::array<GLuint, kExtensionMapCount> extensionSamplers;
    WorldBounds bounds;
    bool castsCutOut;    // alpha-masked: discards below its cut-off in the shadow maps too
    bool cutOutTexture;  // its alpha comes from the base colour map
    bool cutOutColors;   // and from its vertex colours
    bool cutOutUv1;      // the base colour map's UVs may be the second set
    // An analytic sphere (Shape::Sphere): its centre and world radius (its largest axis), from which the shadow
    // views pick a coarser tessellation; radius 0 for every other shape.
    glm::vec3 sphereCentre;
    float sphereRadius;
    size_t triangles;
    int planeSlot = -1;  // its casterPlanes_ index, -1 for none
    // Its mesh's closure (and its coarser spheres'), Open for a cut-out, whose holes show the faces behind, and
    // until the first shadow views are drawn.
    MeshClosure closure = MeshClosure::Open;
  };
  // The planar casters' planes and slots, from the objects' poses, and meshPlanar_ where it is not known yet.
  void findCasterPlanes(const Scene& scene);
  // The casters' closures, found when shadows are first drawn: a frame without shadows does not pay for them (about
  // 0.3 s per million triangles). A mesh posed again since keeps its first pose's: a pose moves coincident positions
  // together.
  void findClosures(const Scene& scene);
  // The tessellation a caster is drawn with in view `v`, whose w row (the distance along a perspective view's axis,
  // 1 in an orthographic one) is `wRow`: its own mesh, or for a sphere the coarsest of sphereLods_ that stays within
  // half a texel of the sphere (the rasterizer's own rounding of a silhouette; the facets lie inside the sphere, so
  // the sphere never shadows itself more).
  const GpuMesh& casterMesh(const Draw& d, const ShadowCasterView& v, const glm::vec4& wRow) const;
  // The material's Scene::textures index per texture unit, -1 for none.
  static std::array<int, kMapCount> materialMaps(const Material& material);

  ProgramCache& cache_;
  std::vector<const Program*> programs_;  // one per permutation the scene uses, owned by the cache
  // Per draw, once shadows are first drawn: [0] a draw per view, [1] the viewport from the vertex shader.
  std::array<std::vector<const Program*>, 2> depthPrograms_;
  std::unique_ptr<Buffer> shadowViews_;  // renderDepth's blocks of view-projections
  std::vector<GpuMesh> meshes_;
  // Per mesh: all its vertices in one plane (planarity survives any pose's affine map); empty until casterPlanes.
  std::vector<bool> meshPlanar_;
  std::vector<CasterPlane> casterPlanes_;
  bool planesFound_ = false;  // casterPlanes_ and the draws' planeSlot are the current poses'
  std::vector<GpuMesh> sphereLods_;  // spheres of kSphereLodSegments segments, made when the scene has a sphere
  MeshClosure sphereLodClosure_ = MeshClosure::Open;  // theirs, when all have the same
  bool closuresFound_ = false;
  std::vector<GpuTexture> textures_;
  std::vector<Draw> draws_;  // the opaque and masked first, then the blended
  size_t opaqueDraws_ = 0;
  bool unlit_ = false;
  bool transmissive_ = false;
  GBufferLayout layout_;
  GBufferLayout blendedExtensions_;
  std::vector<ShaderDefines> blendedPermutations_;
  GLsizeiptr blockStride_;
  GLsizeiptr shadowViewStride_;  // renderDepth's blocks of view-projections, at the offset alignment
  Buffer objectBlocks_;
  WorldBounds bounds_;
};

}  // namespace pbr
