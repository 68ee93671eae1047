#pragma once
#include <functional>
#include <string>
#include <vector>

namespace pbr {

// What the frame's passes read and write. The first four are inputs of the frame (the scene's uploaded geometry
// and materials, its lights, its image-based lighting maps, the camera's frame block); the others are targets a
// pass must write before another may read them.
enum class FrameResource {
  Geometry, Lights, Environment, Camera, GBuffer, ShadowMaps, Radiance, ClusterLists, PairCounts, ShadowLight, Exposure,
  Display, Capture
};
const char* toString(FrameResource resource);

// One entry of the frame's pass list: a name (its profiler scope), what it reads and writes, and the work.
struct FramePass {
  std::string name;
  std::vector<FrameResource> reads, writes;
  std::function<void()> run;
};

// An ordered list of passes, in the shape of a frame graph without resource aliasing: the order is declared, and
// checked rather than derived.
using PassList = std::vector<FramePass>;

// Throws std::logic_error naming the pass and the resource when a pass reads a target no earlier pass wrote.
void checkPassList(const PassList& passes);

// "gbuffer (reads geometry, camera; writes gbuffer, radiance) -> ..." for logs and documentation.
std::string describePassList(const PassList& passes);

}  // namespace pbr
