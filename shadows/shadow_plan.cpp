#include "shadows/shadow_plan.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include <glm/geometric.hpp>
#include <glm/gtc/constants.hpp>
#include <glm/trigonometric.hpp>

#include "shadows/atlas_packing.hpp"
#include "shadows/shadow_views.hpp"

namespace pbr {

namespace {

// A spot light wider than this (half angle) takes a cube, as one perspective view would stretch its texels.
constexpr float kMaxSpotViewHalfAngle = 1.0471976f;  // 60 degrees

// A casting light's request: its views' directions, its size and how much it matters.
struct Request {
  enum Kind { Cube, Spot, Directional } kind;
  uint32_t index;    // light-buffer index, or directional light
  float importance;  // pixels on screen; directional lights come first
  int size;          // texels per view side
  uint32_t firstView = 0;
  std::vector<bool> visible;  // per view: meets a receiver in view
};

int ceilPow2(float x, int lo, int hi) {
  int s = lo;
  while (s < hi && float(s) < x) s *= 2;
  return s;
}

// The light's sphere's radius on screen in pixels; the whole frame's height when a perspective camera is inside it.
float screenRadius(const Camera& camera, int frameHeight, const glm::vec3& centre, float R) {
  if (camera.orthographic) return std::min(R / camera.orthoHalfHeight, 2.0f) * float(frameHeight) * 0.5f;
  const float d = glm::distance(camera.position, centre);
  if (d <= R * 1.001f) return float(frameHeight);
  const float tanAngle = R / std::sqrt(d * d - R * R);
  return tanAngle / std::tan(glm::radians(camera.fovYDeg) * 0.5f) * float(frameHeight) * 0.5f;
}

constexpr std::array<glm::vec3, 6> kFaceAxes = {glm::vec3(1, 0, 0), glm::vec3(-1, 0, 0), glm::vec3(0, 1, 0),
                                                glm::vec3(0, -1, 0), glm::vec3(0, 0, 1), glm::vec3(0, 0, -1)};

}  // namespace

bool anyShadowCaster(const std::vector<PointLight>& lights, const std::vector<DirectionalLight>& directional,
                     ShadowMode mode) {
  if (mode == ShadowMode::None) return false;
  if (mode == ShadowMode::On) return !lights.empty() || !directional.empty();
  return std::any_of(lights.begin(), lights.end(), [](const PointLight& l) { return l.castsShadows; }) ||
         std::any_of(directional.begin(), directional.end(), [](const DirectionalLight& l) { return l.castsShadows; });
}

ShadowPlan planShadows(const ShadowInputs& in) {
  ShadowPlan plan;
  plan.lightViews.assign(in.bufferOrder.size(), 0u);
  plan.header.atlas = glm::vec4(float(in.atlasSize), 1.0f / float(in.atlasSize), 0.0f, 0.0f);
  const int maxView = std::min(kMaxShadowView, in.atlasSize / 4);
  const CascadeSplits splits =
      in.receivers.empty() ? CascadeSplits{}
                           : cascadeSplits(in.camera, in.receivers.nearDepth(), in.receivers.farDepth(), kCascades);
  // Whether a perspective view from the light may hold a visible receiver; the widest border the view can have, at
  // the least size, is conservative for every size.
  const auto widestPlanes = [&](const PointLight& l, const glm::vec3& axis, float tanHalf) {
    return frustumPlanes(
        perspectiveView(l.position, axis, tanHalf, l.radius, kMinShadowView, kShadowBorderTexels).viewProjection);
  };

  std::vector<Request> requests;
  for (size_t d = 0; d < in.directional.size(); ++d) {
    if (!castsShadows(in.directional[d].castsShadows, in.mode) || splits.count == 0) continue;
    Request r{Request::Directional, uint32_t(d), std::numeric_limits<float>::max(), in.atlasSize / 4, 0, {}};
    for (int c = 0; c < kCascades; ++c) {
      const float begin = c == 0 ? splits.begin : splits.ends[size_t(c - 1)];
      r.visible.push_back(c < splits.count && in.receivers.holdsDepth(begin, splits.ends[size_t(c)]));
    }
    requests.push_back(r);
  }
  for (size_t i = 0; i < in.bufferOrder.size(); ++i) {
    const PointLight& l = in.lights[in.bufferOrder[i]];
    if (!castsShadows(l.castsShadows, in.mode) || !(l.radius > 0.0f)) continue;
    const float importance = screenRadius(in.camera, in.frameHeight, l.position, l.radius);
    const bool spotView = l.spot && l.spot->outerAngle <= kMaxSpotViewHalfAngle;
    Request r{spotView ? Request::Spot : Request::Cube, uint32_t(i), importance,
              ceilPow2(importance * (spotView ? 2.0f : 1.0f), kMinShadowView, maxView), 0, {}};
    const glm::vec4 sphere(l.position, l.radius);
    if (spotView) {
      r.visible.push_back(in.receivers.meets(sphere, widestPlanes(l, l.spot->direction, std::tan(l.spot->outerAngle))));
    } else {
      // A wide spot light's faces outside its cone (beyond the face's corner angle, atan(sqrt 2)) see nothing lit.
      std::vector<FrustumPlanes> faces;
      std::vector<size_t> faceOf;
      for (size_t f = 0; f < kFaceAxes.size(); ++f) {
        const glm::vec3& axis = kFaceAxes[f];
        if (!l.spot ||
            std::acos(std::clamp(glm::dot(axis, l.spot->direction), -1.0f, 1.0f)) < l.spot->outerAngle + 0.9553166f) {
          faces.push_back(widestPlanes(l, axis, 1.0f));
          faceOf.push_back(f);
        }
      }
      const uint32_t met = in.receivers.meetsViews(sphere, faces);
      r.visible.assign(kFaceAxes.size(), false);
      for (size_t k = 0; k < faces.size(); ++k) r.visible[faceOf[k]] = (met >> k & 1u) != 0u;
    }
    requests.push_back(r);
  }

  // Sizes that fit: halve the least important lights first, a step each per round, down to the least size; then
  // leave out the least important lights altogether.
  std::vector<size_t> byImportance(requests.size());
  for (size_t i = 0; i < requests.size(); ++i) byImportance[i] = i;
  std::stable_sort(byImportance.begin(), byImportance.end(),
                   [&](size_t a, size_t b) { return requests[a].importance < requests[b].importance; });
  auto area = [](const Request& r) {
    return uint64_t(std::count(r.visible.begin(), r.visible.end(), true)) * uint64_t(r.size) * uint64_t(r.size);
  };
  const uint64_t capacity = uint64_t(in.atlasSize) * uint64_t(in.atlasSize);
  uint64_t total = 0;
  for (const Request& r : requests) total += area(r);
  std::vector<bool> shrunk(requests.size(), false), dropped(requests.size(), false);
  for (bool halved = true; total > capacity && halved;) {
    halved = false;
    for (size_t k = 0; k < byImportance.size() && total > capacity; ++k) {
      Request& r = requests[byImportance[k]];
      if (r.size <= kMinShadowView) continue;
      total -= area(r);
      r.size /= 2;
      total += area(r);
      shrunk[byImportance[k]] = halved = true;
    }
  }
  for (size_t k = 0; k < byImportance.size() && total > capacity; ++k) {
    total -= area(requests[byImportance[k]]);
    dropped[byImportance[k]] = true;
  }

  // Views in request order; squares placed largest first.
  std::vector<AtlasSquare> squares;
  for (size_t q = 0; q < requests.size(); ++q) {
    Request& r = requests[q];
    if (dropped[q]) {
      ++plan.stats.unshadowedLights;
      continue;
    }
    const uint32_t light = plan.stats.shadowedLights++;
    plan.stats.shrunkLights += shrunk[q] ? 1u : 0u;
    r.firstView = uint32_t(plan.views.size());
    for (size_t v = 0; v < r.visible.size(); ++v) {
      if (r.visible[v]) squares.push_back({r.size, plan.views.size()});
      plan.views.emplace_back().light = light;
    }
  }
  packSquares(squares);

  for (size_t q = 0; q < requests.size(); ++q) {
    if (dropped[q]) continue;
    const Request& r = requests[q];
    const glm::vec4 from = r.kind == Request::Directional
                               ? glm::vec4(in.directional[r.index].direction, 0.0f)
                               : glm::vec4(in.lights[in.bufferOrder[r.index]].position, 1.0f);
    uint32_t skipPlanes = 0;
    for (size_t p = 0; p < in.casterPlanes.size(); ++p) {
      if (!planeMayShadow(in.casterPlanes[p], in.planeSides, p, from)) skipPlanes |= 1u << p;
    }
    for (size_t v = 0; v < r.visible.size(); ++v) {
      ShadowViewPlan& view = plan.views[r.firstView + v];
      const uint32_t light = view.light;
      if (!r.visible[v]) {
        ++plan.stats.viewsSkipped;
        continue;
      }
      if (r.kind == Request::Directional) {
        const DirectionalLight& l = in.directional[r.index];
        view = cascadeView(in.camera, in.aspect, splits, int(v), l.direction, in.scene, r.size);
        ShadowStats& s = plan.stats;
        s.cascadeTexelMin = s.cascadeTexelMin > 0.0f ? std::min(s.cascadeTexelMin, view.texelWorld) : view.texelWorld;
        s.cascadeTexelMax = std::max(s.cascadeTexelMax, view.texelWorld);
      } else {
        const PointLight& l = in.lights[in.bufferOrder[r.index]];
        const glm::vec3 axis = r.kind == Request::Spot ? l.spot->direction : kFaceAxes[v];
        const float tanHalf90 = r.kind == Request::Spot ? std::tan(l.spot->outerAngle) : 1.0f;
        view = perspectiveView(l.position, axis, tanHalf90, l.radius, r.size, kShadowBorderTexels);
        view.reach = glm::vec4(l.position, l.radius);
      }
      view.light = light;
      view.skipPlanes = skipPlanes;
      plan.stats.planesLeftOut += uint32_t(__builtin_popcount(skipPlanes));
      ++plan.stats.viewsRendered;
      plan.stats.texelsUsed += uint64_t(r.size) * uint64_t(r.size);
    }
    if (r.kind == Request::Directional) {
      plan.header.directional[r.index] = glm::uvec4(r.firstView + 1u, uint32_t(splits.count), 0u, 0u);
    } else {
      const PointLight& l = in.lights[in.bufferOrder[r.index]];
      const LightShadowKind kind = r.kind == Request::Cube              ? LightShadowKind::Cube
                                   : frameAroundX(l.spot->direction) ? LightShadowKind::SpotFrameX
                                                                     : LightShadowKind::Spot;
      plan.lightViews[r.index] = lightShadowEntry(r.firstView, r.size, kind);
    }
  }
  for (const AtlasSquare& s : squares) {
    plan.views[s.view].origin = s.origin;
    plan.views[s.view].size = s.size;
  }
  for (int c = 0; c < 4; ++c) plan.header.cascadeEnds[c] = c < splits.count ? splits.ends[size_t(c)] : 1e30f;
  return plan;
}

}  // namespace pbr
