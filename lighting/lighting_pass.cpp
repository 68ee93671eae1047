#include "lighting/lighting_pass.hpp"

#include <algorithm>
#include <cstddef>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/gl/hdr_format.hpp"
#include "lighting/blended_programs.hpp"
#include "lighting/lighting_bindings.hpp"

namespace pbr {

uint32_t lightWindowLights() {
  GLint64 maxBlock = 0;
  glGetInteger64v(GL_MAX_UNIFORM_BLOCK_SIZE, &maxBlock);
  uint32_t window = kLightWindowMax;
  while (window > 1 && uint64_t(window) * sizeof(GpuLight) > uint64_t(maxBlock)) window /= 2;
  return window;
}

const Program& LightingPass::program(const LightingOptions& o, bool clustered, unsigned radianceFormat, bool chunked,
                                     LightKinds kinds) {
  const ShaderDefines permutation =
      lightingPermutation(o, clustered, hdrFormatOf(radianceFormat), chunked, kinds, lightWindow_);
  return programs_.compute("lighting/deferred.comp", concat(permutation, lightingBindingDefines()));
}

void LightingPass::bindShading(const LightBuffer& lights, const LightingOptions& options,
                               const UniformBuffer<FrameBlock>& frame, const LightClusters* clusters) {
  // Made (on first use) before anything is bound for this pass: making a table dispatches a pass of its own.
  const bool ibl = options.ibl();
  const Texture* ambient = options.model == ShadingModel::Pbr && !ibl
                               ? &ambientAlbedo_.table(shaderDefines(options.variant))
                               : nullptr;
  const Texture* sheen =
      options.model == ShadingModel::Pbr && options.sheenMaterials ? &sheenAlbedo_.table() : nullptr;
  block_.update({glm::vec4(options.ambient, 0.0f), glm::uvec4(lights.count(), 0, 0, 0)});
  frame.bind(kFrameUbo.index);
  block_.bind(lighting_binding::kLightingUbo.index);
  lights.bind();
  lights.bindDirectional();
  if (clusters) clusters->bindForLighting();
  if (ibl) bindEnvironmentMaps(*options.environment);
  if (options.shadows) bindShadowMaps(*options.shadows);
  if (ambient) {
    glBindTextureUnit(lighting_binding::kAmbientAlbedoUnit.index, ambient->id());
    glBindSampler(lighting_binding::kAmbientAlbedoUnit.index, ambientSampler_.id());
  }
  if (sheen) {
    glBindTextureUnit(lighting_binding::kSheenAlbedoUnit.index, sheen->id());
    glBindSampler(lighting_binding::kSheenAlbedoUnit.index, ambientSampler_.id());
  }
}

void LightingPass::render(const SurfaceTextures& surface, const LightBuffer& lights, const LightingOptions& options,
                          const UniformBuffer<FrameBlock>& frame, const Texture& radiance,
                          const LightClusters* clusters, const Texture* partialRadiance) {
  const GLuint groupsX = static_cast<GLuint>((radiance.width() + 7) / 8);
  const GLuint groupsY = static_cast<GLuint>((radiance.height() + 7) / 8);
  const bool clustered = clusters != nullptr;
  const uint32_t perDispatch = lightsPerDispatch(clustered);
  const uint32_t chunks = std::max(1u, (lights.count() + perDispatch - 1) / perDispatch);
  const bool chunked = needsLightChunks(lights.count(), clustered);
  if (chunked && (!partialRadiance || partialRadiance->format() != GL_RGBA32F ||
                  partialRadiance->width() != radiance.width() || partialRadiance->height() != radiance.height())) {
    throw std::logic_error("the lighting pass needs an RGBA32F running-sum image of the frame's size over " +
                           std::to_string(perDispatch) + " lights");
  }
  const Program& shader = program(options, clustered, radiance.format(), chunked, lights.kinds());
  bindShading(lights, options, frame, clusters);
  if (options.stats) {
    pairGroups_ = static_cast<size_t>(groupsX) * groupsY;
    if (!pairStats_ || pairStats_->size() < pairGroups_ * 8) {
      pairStats_ = std::make_unique<Buffer>("lighting.pairStats", pairGroups_ * 8, nullptr, 0);
    }
    const uint32_t zero = 0;
    glClearNamedBufferData(pairStats_->id(), GL_R32UI, GL_RED_INTEGER, GL_UNSIGNED_INT, &zero);
    pairStats_->bindBase(GL_SHADER_STORAGE_BUFFER, lighting_binding::kLightingStatsSsbo.index);
  }
  glBindTextureUnit(lighting_binding::kBaseColorUnit.index, surface.baseColor.id());
  glBindTextureUnit(lighting_binding::kNormalUnit.index, surface.normal.id());
  glBindTextureUnit(lighting_binding::kMaterialUnit.index, surface.material.id());
  glBindTextureUnit(lighting_binding::kDepthUnit.index, surface.depth.id());
  if ((options.specularMaterials && !surface.specular) || (options.clearcoatMaterials && !surface.clearcoat) ||
      (options.sheenMaterials && !surface.sheen)) {
    throw std::logic_error("lighting pass: material extensions without their G-buffer channels");
  }
  if (surface.specular) glBindTextureUnit(lighting_binding::kSpecularUnit.index, surface.specular->id());
  if (surface.clearcoat) glBindTextureUnit(lighting_binding::kClearcoatUnit.index, surface.clearcoat->id());
  if (surface.sheen) glBindTextureUnit(lighting_binding::kSheenUnit.index, surface.sheen->id());
  glBindImageTexture(lighting_binding::kRadianceImage.index, radiance.id(), 0, GL_FALSE, 0, GL_READ_WRITE,
                     radiance.format());
  glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_STORAGE_BARRIER_BIT);
  if (options.pairCounts) {
    glBindImageTexture(lighting_binding::kPairCountImage.index, options.pairCounts->id(), 0, GL_FALSE, 0,
                       GL_READ_WRITE, GL_RG32UI);
  }
  if (options.shadows && options.shadowLight) {
    glBindImageTexture(lighting_binding::kShadowLightImage.index, options.shadowLight->id(), 0, GL_FALSE, 0,
                       GL_READ_WRITE, GL_RG32F);
  }
  if (chunked) {
    glBindImageTexture(lighting_binding::kPartialRadianceImage.index, partialRadiance->id(), 0, GL_FALSE, 0,
                       GL_READ_WRITE, GL_RGBA32F);
  }
  // The tiles holding a surface are shaded, the others given their background by a build of the pass that does
  // nothing else: each an indirect dispatch over its list, so that no workgroup runs the shading for a tile of sky.
  sortTiles(groupsX, groupsY);
  shader.use();
  for (uint32_t c = 0; c < chunks; ++c) {
    if (!clustered) lights.bindWindow(c * perDispatch, perDispatch);
    if (chunked) {
      glProgramUniform4ui(shader.id(), 0, c * perDispatch, (c + 1) * perDispatch, c == 0 ? 1u : 0u,
                          c + 1 == chunks ? 1u : 0u);
    }
    glDispatchComputeIndirect(offsetof(SurfaceTilesHeader, surfaceDispatch));
    if (chunked) glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
  }
  // The tiles of background keep what `radiance` holds there, the background without an environment, unless the
  // environment is seen through them or the statistics images want their zeros: on llvmpipe a store costs about
  // 11 ns a pixel (9 ms for helmet-grid's sky at 1280x720).
  if (options.ibl() || options.pairCounts || (options.shadows && options.shadowLight)) {
    ShaderDefines background = lightingPermutation(options, clustered, hdrFormatOf(radiance.format()), false,
                                                   lights.kinds(), lightWindow_);
    background.push_back({"BACKGROUND_TILES", "1"});
    programs_.compute("lighting/deferred.comp", concat(background, lightingBindingDefines())).use();
    glDispatchComputeIndirect(offsetof(SurfaceTilesHeader, backgroundDispatch));
  }
  glBindBuffer(GL_DISPATCH_INDIRECT_BUFFER, 0);
  glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT | GL_TEXTURE_UPDATE_BARRIER_BIT |
                  GL_BUFFER_UPDATE_BARRIER_BIT);
}

void LightingPass::renderBlended(const BlendedSurfaces& surfaces, const TransmissionTargets& transmission,
                                 const LightBuffer& lights, const LightingOptions& options,
                                 const UniformBuffer<FrameBlock>& frame, const Texture& radiance,
                                 const LightClusters* clusters, const OitTargets& oit) {
  // The counts and pictures of the debug views are the deferred pass's.
  LightingOptions forward = options;
  forward.stats = false;
  forward.pairCounts = nullptr;
  forward.shadowLight = nullptr;
  const bool clustered = clusters != nullptr;
  const bool weighted = oit.accumulation != nullptr, exact = oit.layerLists != nullptr;
  const bool orderIndependent = weighted || exact;
  const uint32_t perDispatch = lightsPerDispatch(clustered);
  const uint32_t chunks = std::max(1u, (lights.count() + perDispatch - 1) / perDispatch);
  const bool chunked = chunks > 1;
  const ShaderDefines lighting =
      lightingPermutation(forward, clustered, hdrFormatOf(radiance.format()), chunked, lights.kinds(), lightWindow_);
  bindShading(lights, forward, frame, clusters);
  glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_STORAGE_BARRIER_BIT | GL_UNIFORM_BARRIER_BIT |
                  GL_FRAMEBUFFER_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
  // Each object's later light chunks write alpha 0 (and no weight, no revealage): they add to what its first one
  // composited.
  const auto draw = [&](const BlendedSurfaces& set, BlendedSet which, bool weightedSums, bool lists) {
    const ShaderDefines defines =
        concat(lighting, {{"OIT_WEIGHTED", weightedSums ? "1" : "0"}, {"OIT_EXACT", lists ? "1" : "0"}});
    BlendedPrograms programs(programs_, "lighting/forward.frag", [&](const std::vector<BindingPoint>& bindings) {
      return concat(defines, forwardBindingDefines(bindings));
    });
    set.draw(
        [&](int repeat, const std::string& vertexShader, const ShaderDefines& material,
            const std::vector<BindingPoint>& bindings) -> const Program& {
          const Program& p = programs.get(vertexShader, material, bindings);
          const uint32_t first = uint32_t(repeat) * perDispatch;
          if (!clustered) lights.bindWindow(first, perDispatch);
          if (chunked) {
            glProgramUniform4ui(p.id(), 0, first, first + perDispatch, repeat == 0 ? 1u : 0u,
                                uint32_t(repeat) + 1 == chunks ? 1u : 0u);
          }
          return p;
        },
        weightedSums || lists ? BlendOrder::Any : BlendOrder::BackToFront, int(chunks), which);
  };
  if (transmission.surfaces) {
    // What lies behind the transmissive surfaces: the opaque frame, blurred by roughness through its mip chain.
    const Texture& background = *transmission.background;
    glMemoryBarrier(GL_TEXTURE_UPDATE_BARRIER_BIT | GL_FRAMEBUFFER_BARRIER_BIT);
    glCopyImageSubData(radiance.id(), GL_TEXTURE_2D, 0, 0, 0, 0, background.id(), GL_TEXTURE_2D, 0, 0, 0, 0,
                       radiance.width(), radiance.height(), 1);
    glGenerateTextureMipmap(background.id());
    glBindTextureUnit(lighting_binding::kTransmissionBackgroundUnit.index, background.id());
    glBindSampler(lighting_binding::kTransmissionBackgroundUnit.index, backgroundSampler_.id());
    glEnable(GL_BLEND);
    glBlendFunc(GL_ONE, GL_ONE_MINUS_SRC_ALPHA);  // premultiplied "over", as for sorted BLEND surfaces
    draw(*transmission.surfaces, BlendedSet::Transmissive, false, false);
    glDisable(GL_BLEND);
    glBindSampler(lighting_binding::kTransmissionBackgroundUnit.index, 0);
    glMemoryBarrier(GL_FRAMEBUFFER_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT);
  }
  if (exact) {
    // Empty lists; the fragments write nodes, no colour.
    const size_t pixels = size_t(radiance.width()) * size_t(radiance.height());
    const size_t nodeBytes = oit.layerLists->size() - sizeof(LayerListHeader) - pixels * 4;
    const LayerListHeader header{0, uint32_t(nodeBytes / 16), 0, uint32_t(pixels)};
    glNamedBufferSubData(oit.layerLists->id(), 0, sizeof header, &header);
    const uint32_t zero = 0;
    glClearNamedBufferSubData(oit.layerLists->id(), GL_R32UI, sizeof header, pixels * 4, GL_RED_INTEGER,
                              GL_UNSIGNED_INT, &zero);
    oit.layerLists->bindBase(GL_SHADER_STORAGE_BUFFER, lighting_binding::kLayerNodeSsbo.index);
    glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
  } else {
    glEnable(GL_BLEND);
  }
  if (weighted) {
    // Sums of weighted premultiplied colour and weight, and the product of the layers' 1 - a (dst (1 - src)).
    const float zeros[4] = {0.0f, 0.0f, 0.0f, 0.0f}, ones[4] = {1.0f, 1.0f, 1.0f, 1.0f};
    glClearTexImage(oit.accumulation->id(), 0, GL_RGBA, GL_FLOAT, zeros);
    glClearTexImage(oit.revealage->id(), 0, GL_RGBA, GL_FLOAT, ones);
    glBlendFunci(0, GL_ONE, GL_ONE);
    glBlendFunci(1, GL_ZERO, GL_ONE_MINUS_SRC_COLOR);
  } else if (!exact) {
    // Premultiplied "over" (forward.frag writes the lit colour times alpha, and alpha).
    glBlendFunc(GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
  }
  draw(surfaces, BlendedSet::Blend, weighted, exact);
  glDisable(GL_BLEND);
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  if (!orderIndependent) return;
  const auto [qualifier, maximum] = radianceImageFormat(hdrFormatOf(radiance.format()));
  const ShaderDefines format = {{"HDR_IMAGE_FORMAT", qualifier}, {"HDR_MAX", maximum}};
  if (exact) {
    programs_.compute("lighting/layer_resolve.comp",
                      concat(concat(format, {{"MAX_LAYERS", std::to_string(kMaxLayersPerPixel) + "u"}}),
                             lightingBindingDefines()))
        .use();
    glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_SHADER_STORAGE_BARRIER_BIT);
  } else {
    programs_.compute("lighting/oit_composite.comp", concat(format, lightingBindingDefines())).use();
    glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_FRAMEBUFFER_BARRIER_BIT);
    glBindTextureUnit(lighting_binding::kOitAccumulationUnit.index, oit.accumulation->id());
    glBindTextureUnit(lighting_binding::kOitRevealageUnit.index, oit.revealage->id());
  }
  glBindImageTexture(lighting_binding::kRadianceImage.index, radiance.id(), 0, GL_FALSE, 0, GL_READ_WRITE,
                     radiance.format());
  glDispatchCompute(static_cast<GLuint>((radiance.width() + 7) / 8), static_cast<GLuint>((radiance.height() + 7) / 8),
                    1);
  glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT | GL_TEXTURE_UPDATE_BARRIER_BIT);
}

size_t layerListBytes(size_t pixels, uint64_t maxBlockBytes) {
  const uint64_t least = sizeof(LayerListHeader) + uint64_t(pixels) * (4 + 16);
  if (least > maxBlockBytes) {
    throw std::runtime_error("--transparency exact: a frame of " + std::to_string(pixels) + " pixels needs " +
                             std::to_string(least >> 20) + " MiB of lists at the least, over the driver's largest "
                             "storage block (" + std::to_string(maxBlockBytes >> 20) + " MiB): use oit or sorted, or "
                             "a smaller frame");
  }
  const uint64_t wanted = sizeof(LayerListHeader) + uint64_t(pixels) * (4 + 16 * uint64_t(kLayerNodesPerPixel));
  return size_t(std::min(wanted, maxBlockBytes / 16 * 16));
}

uint32_t readDroppedLayers(const Buffer& lists) {
  LayerListHeader header{};
  glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
  glGetNamedBufferSubData(lists.id(), 0, sizeof header, &header);
  return header.droppedNodes;
}

void LightingPass::sortTiles(GLuint groupsX, GLuint groupsY) {
  const uint32_t tiles = groupsX * groupsY;
  const size_t bytes = sizeof(SurfaceTilesHeader) + 2 * size_t(tiles) * sizeof(uint32_t);
  if (!surfaceTiles_ || surfaceTiles_->size() < bytes) {
    surfaceTiles_ = std::make_unique<Buffer>("lighting.surfaceTiles", bytes);
  }
  SurfaceTilesHeader header;
  header.tileGrid = glm::uvec4(groupsX, tiles, 0u, 0u);
  surfaceTiles_->upload(&header, sizeof header);
  surfaceTiles_->bindBase(GL_SHADER_STORAGE_BUFFER, lighting_binding::kSurfaceTilesSsbo.index);
  programs_.compute("lighting/surface_tiles.comp", lightingBindingDefines()).use();
  glDispatchCompute((tiles + 63) / 64, 1, 1);
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_COMMAND_BARRIER_BIT);
  glBindBuffer(GL_DISPATCH_INDIRECT_BUFFER, surfaceTiles_->id());
}

PairCounts LightingPass::readPairCounts() const {
  PairCounts counts;
  if (surfaceTiles_) {
    SurfaceTilesHeader header;
    glGetNamedBufferSubData(surfaceTiles_->id(), 0, sizeof header, &header);
    counts.surfaceTiles = header.surfaceDispatch.w;
    counts.surfaceGroups = glm::uvec2(header.surfaceDispatch);
    counts.tiles = header.tileGrid.y;
  }
  if (!pairStats_) return counts;
  std::vector<uint32_t> pairs(pairGroups_ * 2);
  glGetNamedBufferSubData(pairStats_->id(), 0, static_cast<GLsizeiptr>(pairs.size() * 4), pairs.data());
  for (size_t g = 0; g < pairGroups_; ++g) {
    counts.evaluated += pairs[2 * g];
    counts.contributing += pairs[2 * g + 1];
  }
  return counts;
}

}  // namespace pbr
