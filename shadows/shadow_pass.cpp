#include "shadows/shadow_pass.hpp"

#include <algorithm>
#include <chrono>
#include <cstring>
#include <map>
#include <string>
#include <tuple>
#include <utility>

#include <glm/matrix.hpp>

namespace pbr {

namespace {

// Whether two views draw the same depths into their squares: the same square, matrix, reach, texel size and planes
// left out (the caster culling and tessellation read no more), bit for bit.
bool sameDepths(const ShadowCasterView& a, const ShadowCasterView& b) {
  return a.viewport == b.viewport && a.reach == b.reach && a.texelWorld == b.texelWorld &&
         a.skipPlanes == b.skipPlanes &&
         std::memcmp(&a.viewProjection, &b.viewProjection, sizeof(glm::mat4)) == 0;
}

// A buffer of at least `bytes` (never empty: a bound storage buffer must exist), reallocated only to grow.
void ensureBuffer(std::unique_ptr<Buffer>& buffer, const char* label, size_t bytes) {
  bytes = std::max<size_t>(bytes, 16);
  if (!buffer || buffer->size() < bytes) buffer = std::make_unique<Buffer>(label, bytes);
}

}  // namespace

bool operator==(const ShadowFrameKey& a, const ShadowFrameKey& b) {
  // FrameBlock is std140 floats without padding (its static_assert), so equal bytes are equal matrices.
  return std::memcmp(&a.frame, &b.frame, sizeof(FrameBlock)) == 0 && a.lightsVersion == b.lightsVersion &&
         a.poseVersion == b.poseVersion &&
         a.mode == b.mode && a.atlasSize == b.atlasSize && a.drawsPerLight == b.drawsPerLight &&
         a.clustered == b.clustered && a.tileSize == b.tileSize && a.slices == b.slices;
}

ShadowPass::ShadowPass() : sampler_("shadows.atlasSampler", GL_CLAMP_TO_EDGE, GL_CLAMP_TO_EDGE, GL_LINEAR, GL_LINEAR) {
  // Reversed Z: a receiver is lit where its depth is at least the nearest caster's.
  glSamplerParameteri(sampler_.id(), GL_TEXTURE_COMPARE_MODE, GL_COMPARE_REF_TO_TEXTURE);
  glSamplerParameteri(sampler_.id(), GL_TEXTURE_COMPARE_FUNC, GL_GEQUAL);
}

bool ShadowPass::reuse(const ShadowFrameKey& key) {
  if (!holds(key)) return false;
  stats_.reused = true;
  stats_.viewsKept = stats_.viewsRendered;
  stats_.readBackMs = stats_.planMs = stats_.recordMs = 0.0;
  stats_.draws = stats_.oneSidedDraws = 0;
  return true;
}

void ShadowPass::render(const ShadowInputs& inputs, const DrawShadowCasters& drawCasters,
                        const ShadowFrameKey& key, bool keepViews) {
  const auto start = std::chrono::steady_clock::now();
  ShadowPlan plan = planShadows(inputs);
  const auto planned = std::chrono::steady_clock::now();
  stats_ = plan.stats;
  stats_.planMs = std::chrono::duration<double, std::milli>(planned - start).count();
  ownersCurrent_ = false;
  if (!atlas_ || atlas_->width() != inputs.atlasSize) {
    framebuffer_.reset();
    atlas_.reset();
    atlas_ = std::make_unique<Texture>("shadows.atlas", GL_DEPTH_COMPONENT32F, inputs.atlasSize, inputs.atlasSize);
    framebuffer_ = std::make_unique<Framebuffer>("shadows.framebuffer");
    atlasViews_.clear();
    framebuffer_->attach(GL_DEPTH_ATTACHMENT, *atlas_);
    glNamedFramebufferDrawBuffer(framebuffer_->id(), GL_NONE);
    framebuffer_->checkComplete();
    const float far = 0.0f;
    glClearNamedFramebufferfv(framebuffer_->id(), GL_DEPTH, 0, &far);
    dirty_.clear();
  }

  // The header, its directional entries pointing at the cascades' records, which follow it.
  GpuShadowHeader header = plan.header;
  const float scale = 1.0f / float(inputs.atlasSize);
  std::vector<GpuCascadeView> cascades;
  for (glm::uvec4& entry : header.directional) {
    if (entry.x == 0u) continue;
    const uint32_t first = entry.x - 1u;
    entry.x = uint32_t(cascades.size()) + 1u;
    for (uint32_t c = 0; c < entry.y; ++c) {
      const ShadowViewPlan& v = plan.views[first + c];
      const glm::mat4 rows = glm::transpose(v.viewProjection);
      cascades.push_back({{rows[0], rows[1], rows[2]},
                          glm::vec4(glm::vec2(v.origin) * scale, glm::vec2(float(v.size) * scale)),
                          glm::vec4(v.texelWorld, 0.0f, 0.0f, 0.0f)});
    }
  }
  std::vector<unsigned char> bytes(sizeof header + cascades.size() * sizeof(GpuCascadeView));
  std::memcpy(bytes.data(), &header, sizeof header);
  if (!cascades.empty()) {
    std::memcpy(bytes.data() + sizeof header, cascades.data(), cascades.size() * sizeof(GpuCascadeView));
  }
  std::vector<ShadowCasterView> casterViews;
  std::vector<uint32_t> squares(plan.views.size());
  for (size_t i = 0; i < plan.views.size(); ++i) {
    const ShadowViewPlan& v = plan.views[i];
    squares[i] = packShadowSquare(v.origin, v.size);
    if (v.size > 0) {
      casterViews.push_back(
          {v.viewProjection, glm::ivec4(v.origin, v.size, v.size), v.reach, v.texelWorld, v.light, v.skipPlanes});
    }
  }
  ensureBuffer(views_, "shadows.views", bytes.size());
  views_->upload(bytes.data(), bytes.size());
  ensureBuffer(squares_, "shadows.squares", squares.size() * sizeof(uint32_t));
  if (!squares.empty()) squares_->upload(squares.data(), squares.size() * sizeof(uint32_t));
  ensureBuffer(lightViews_, "shadows.lightViews", plan.lightViews.size() * sizeof(uint32_t));
  if (!plan.lightViews.empty()) lightViews_->upload(plan.lightViews.data(), plan.lightViews.size() * sizeof(uint32_t));

  // Views the atlas already holds, unchanged, keep their depths: what a view draws depends on its matrix, square,
  // reach, texel size and planes left out and on the objects (GBufferPass::renderDepth).
  std::vector<ShadowCasterView> toDraw;
  const bool objectsStill = renderedFor_ && renderedFor_->poseVersion == key.poseVersion;
  std::map<std::tuple<int, int, int>, const ShadowCasterView*> held;
  if (keepViews && objectsStill) {
    for (const ShadowCasterView& v : atlasViews_) held[{v.viewport.x, v.viewport.y, v.viewport.z}] = &v;
  }
  for (const ShadowCasterView& v : casterViews) {
    const auto found = held.find({v.viewport.x, v.viewport.y, v.viewport.z});
    if (found != held.end() && sameDepths(*found->second, v)) {
      ++stats_.viewsKept;
    } else {
      toDraw.push_back(v);
    }
  }
  clearSquares(toDraw, stats_.viewsKept > 0);
  if (!toDraw.empty()) {
    const ShadowCasterDraws drawn = drawCasters(framebuffer_->id(), toDraw);
    stats_.draws = uint32_t(drawn.draws);
    stats_.oneSidedDraws = uint32_t(drawn.oneSided);
    for (const glm::ivec4& r : drawn.rects) {
      if (!emptyRect(r)) dirty_.push_back(r);
    }
  }
  stats_.recordMs = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - planned).count();
  lastViews_ = std::move(plan.views);  // kept for ownerMap, not copied
  atlasViews_ = std::move(casterViews);
  renderedFor_ = key;
}

void ShadowPass::clearSquares(const std::vector<ShadowCasterView>& toDraw, bool viewsKept) {
  if (dirty_.empty() || toDraw.empty()) return;  // every square to draw holds the far depth already
  // Which square to draw each kMinShadowView-texel cell of the atlas lies in (+ 1, 0 none): squares are powers of
  // two of at least that side on a grid of their own size.
  const int atlas = atlas_->width(), cells = atlas / kMinShadowView;
  std::vector<uint32_t> cellView(size_t(cells) * size_t(cells), 0u);
  for (size_t i = 0; i < toDraw.size(); ++i) {
    const glm::ivec4& r = toDraw[i].viewport;
    for (int y = r.y / kMinShadowView; y < (r.y + r.w) / kMinShadowView; ++y) {
      for (int x = r.x / kMinShadowView; x < (r.x + r.z) / kMinShadowView; ++x) {
        cellView[size_t(y) * size_t(cells) + size_t(x)] = uint32_t(i) + 1u;
      }
    }
  }
  // The dirty texels inside those squares; a dirty rectangle wholly inside one is clean after the clear.
  std::vector<glm::ivec4> clears, stillDirty;
  uint64_t texels = 0;
  for (const glm::ivec4& d : dirty_) {
    bool cleared = false;
    std::vector<uint32_t> met;  // the squares this rectangle reaches, a few at most
    for (int y = d.y / kMinShadowView; y <= (d.y + d.w - 1) / kMinShadowView; ++y) {
      for (int x = d.x / kMinShadowView; x <= (d.x + d.z - 1) / kMinShadowView; ++x) {
        const uint32_t view = cellView[size_t(y) * size_t(cells) + size_t(x)];
        if (view == 0u || std::find(met.begin(), met.end(), view) != met.end()) continue;
        met.push_back(view);
        const glm::ivec4 c = intersectRects(d, toDraw[view - 1u].viewport);
        if (emptyRect(c)) continue;
        clears.push_back(c);
        texels += uint64_t(c.z) * uint64_t(c.w);
        cleared = cleared || c == d;
      }
    }
    if (!cleared) stillDirty.push_back(d);
  }
  // Each rectangle is cleared as a part of the texture, which llvmpipe fills in memory (a scissored framebuffer clear
  // it draws as a quad, about 1.1 ns a texel: the Blender export's shadow pass took 12.8 instead of 11.1 ms). When
  // they are a quarter of the atlas or more, or more than kMaxPartClears calls, the whole atlas is cleared at once
  // (about 0.3 ns a texel on llvmpipe, one call a GPU clears fastest), unless a view kept from the frame before would
  // lose its depths. On llvmpipe the whole clear cost `stress` with 1,024 casting lights 1.5-2.5 ms more than its
  // 1,576 part clears; on a GPU each call is the driver's work on the CPU for a clear that takes the GPU nothing.
  constexpr size_t kMaxPartClears = 64;
  const float far = 0.0f;
  if (!viewsKept && (4 * texels >= uint64_t(atlas) * uint64_t(atlas) || clears.size() > kMaxPartClears)) {
    glClearNamedFramebufferfv(framebuffer_->id(), GL_DEPTH, 0, &far);
    dirty_.clear();
    return;
  }
  for (const glm::ivec4& c : clears) {
    glClearTexSubImage(atlas_->id(), 0, c.x, c.y, 0, c.z, c.w, 1, GL_DEPTH_COMPONENT, GL_FLOAT, &far);
  }
  dirty_ = std::move(stillDirty);
}

ShadowMaps ShadowPass::maps() const {
  return {atlas_ ? atlas_->id() : 0, sampler_.id(), views_ ? views_->id() : 0, lightViews_ ? lightViews_->id() : 0,
          squares_ ? squares_->id() : 0};
}

const Texture& ShadowPass::ownerMap() {
  const int atlas = atlas_ ? atlas_->width() : kMinShadowView;
  const int cells = atlas / kMinShadowView;
  if (!owners_ || owners_->width() != cells) {
    owners_ = std::make_unique<Texture>("shadows.owners", GL_RG32UI, cells, cells);
    ownersCurrent_ = false;
  }
  if (!ownersCurrent_) {
    // Squares are powers of two of at least kMinShadowView texels on a grid of their own size: whole cells.
    std::vector<glm::uvec2> owners(size_t(cells) * size_t(cells), glm::uvec2(0u));
    for (size_t i = 0; i < lastViews_.size(); ++i) {
      const ShadowViewPlan& v = lastViews_[i];
      const glm::ivec2 first = v.origin / kMinShadowView;
      for (int y = first.y; y < first.y + v.size / kMinShadowView; ++y) {
        for (int x = first.x; x < first.x + v.size / kMinShadowView; ++x) {
          owners[size_t(y) * size_t(cells) + size_t(x)] = glm::uvec2(uint32_t(i) + 1u, v.light + 1u);
        }
      }
    }
    glTextureSubImage2D(owners_->id(), 0, 0, 0, cells, cells, GL_RG_INTEGER, GL_UNSIGNED_INT, owners.data());
    ownersCurrent_ = true;
  }
  return *owners_;
}

size_t ShadowPass::bytes() const {
  return (atlas_ ? shadowAtlasBytes(atlas_->width()) : 0) + (views_ ? views_->size() : 0) +
         (lightViews_ ? lightViews_->size() : 0) + (squares_ ? squares_->size() : 0);
}

}  // namespace pbr
