#pragma once
#include <cstdint>
#include <vector>

#include <glm/mat4x4.hpp>
#include <glm/vec4.hpp>

#include "core/scene/bounds.hpp"

namespace pbr {

// Where the frame's visible surfaces are, from the cluster occupancy (the boxes of the surface points each cluster
// holds, lighting/light_clusters.hpp): what a shadow view must contain to be worth rendering (Olsson et al. 2014,
// "Efficient Virtual Shadow Maps for Many Lights": views without a visible receiver are not rendered) and the depth
// range cascades are fitted to.
class ShadowReceivers {
 public:
  // `boxes`: the occupied clusters' view-space boxes with their screen tile; `inverseView` takes them to world
  // space. Each world box is widened by 1e-4 of its largest coordinate magnitude, as the clusters' own tests are.
  ShadowReceivers(const std::vector<ViewSpaceBox>& boxes, const glm::mat4& inverseView);

  bool empty() const { return tiles_.empty(); }
  // The view depths (distance along the camera's axis) the occupied clusters span; only when not empty().
  float nearDepth() const { return nearDepth_; }
  float farDepth() const { return farDepth_; }

  // Whether an occupied cluster's box meets the sphere (centre xyz, radius w) and is not wholly outside `planes`.
  bool meets(const glm::vec4& sphere, const FrustumPlanes& planes) const;
  // meets for several views of one sphere (at most 32), in one pass over the clusters: bit i for views[i].
  uint32_t meetsViews(const glm::vec4& sphere, const std::vector<FrustumPlanes>& views) const;
  // Whether an occupied cluster's view depths overlap [begin, end].
  bool holdsDepth(float begin, float end) const;

 private:
  struct Cluster {
    WorldBounds box;
    float nearDepth, farDepth;
  };
  struct Tile {
    WorldBounds box;  // of its clusters: most lights miss a whole tile
    std::vector<Cluster> clusters;
  };
  std::vector<Tile> tiles_;
  float nearDepth_ = 0.0f, farDepth_ = 0.0f;
};

}  // namespace pbr
