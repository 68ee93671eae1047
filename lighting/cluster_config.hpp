#pragma once
#include <cstdint>
#include <string>

namespace pbr {

// How an assignment pass spreads its work over the GPU's invocations. `Invocation`: an invocation takes four lights
// (the light pass) or one slot's list (the fill), the shape for llvmpipe, whose few wide threads pay to start each
// invocation. `Workgroup`: a workgroup takes each light, sharing its tiles, and each slot, sharing its mask words,
// the shape a GPU needs where few invocations would otherwise run long loops alone (few large lights, long lists).
// `Cluster` (the light pass only; its fill is the workgroup one): an invocation per cluster holding a surface,
// testing batches of lights its workgroup prepared in shared memory, the shape of most GPU clustered renderers,
// for few lights over few clusters. `Automatic`: measured, by AssignShapeTrials.
enum class AssignShape { Automatic, Invocation, Workgroup, Cluster };
constexpr AssignShape kAssignShapes[] = {AssignShape::Automatic, AssignShape::Invocation, AssignShape::Workgroup,
                                         AssignShape::Cluster};

// "auto", "invocation", "workgroup", "cluster"; parseAssignShape throws std::invalid_argument on anything else.
const char* toString(AssignShape shape);
AssignShape parseAssignShape(const std::string& text);

// How the cluster grid is laid out and assigned, with no GL (LightClusters builds it on the GPU).
struct ClusterConfig {
  int tileSize = 64;  // pixels per screen tile side (LightClusters::setTileSize changes it per frame)
  // Exponential depth slices between the near and far planes. Thin slices raise culling efficiency, and only
  // slices holding a surface cost assignment work: with 192 slices (and the side-plane test) the stress scene's
  // efficiency rose from 0.256 to 0.532 at 1,024 lights and the frame shortened at 4,096
  // (docs/performance-history.md).
  int slices = 192;
  // Most memory the light index list may take; past it, the clusters that do not fit are shaded by brute force.
  uint64_t maxIndexBytes = 512ull << 20;
  // Most memory the clusters' light masks may take (a bit per light for each cluster holding a surface); past
  // it, or past twice the driver's largest storage block, lights are assigned in windows, each costing another
  // light pass.
  uint64_t maxMaskBytes = 256ull << 20;
  // Whether the renderer times a grid of half the tile side against it and keeps the faster (TileTrials); the
  // commands' `--tile auto`.
  bool tileTrial = false;
  // The assignment passes' shapes: measured per machine (AssignShapeTrials) unless forced.
  AssignShape lightPass = AssignShape::Automatic;
  AssignShape fill = AssignShape::Automatic;
};

}  // namespace pbr
