#pragma once
#include <functional>
#include <string>
#include <vector>

#include "core/gl/program_cache.hpp"
#include "core/scene/binding_table.hpp"

namespace pbr {

// The program one draw of a BLEND object is made with, by the module that draws the objects for its own purpose
// (the forward lighting and the clusters' occupancy, lighting/), from what the geometry pass's draws need: its
// vertex shader, the object's material permutation (gbuffer/gbuffer_pass.hpp) and the geometry pass's binding points
// (object block, material maps). `repeat` counts the object's draws in a row (BlendedSurfaces::draw).
using BlendedProgram = std::function<const Program&(int repeat, const std::string& vertexShader,
                                                    const ShaderDefines& material,
                                                    const std::vector<BindingPoint>& bindings)>;

// The order of the draws: any (each object once, both faces of a double-sided one together), or back to front for
// compositing: by the view depth of the objects' bounds' centres, farthest first, a double-sided object's back
// faces before its front faces.
enum class BlendOrder { Any, BackToFront };

// Which of the forward-shaded surfaces a draw takes: every one (the clusters' occupancy), the transmissive ones
// (KHR_materials_transmission: drawn first, over the opaque frame they see through, writing depth as the opaque
// surfaces they stand for do), or the BLEND ones that do not transmit (composited after them).
enum class BlendedSet { All, Transmissive, Blend };

// The scene's forward-shaded surfaces (alphaMode BLEND, or transmissive), which the G-buffer leaves out. The
// contract between the pass that owns their geometry and materials (gbuffer/) and the passes that shade and cull
// them (lighting/), neither of which knows the other.
struct BlendedSurfaces {
  // Draws every object of `set` `repeats` times in a row, in `order`, each through the program `program` returns
  // for the repeat, into the frame's radiance target (colour attachment 0) over the G-buffer's depth, which tests
  // the draws (reversed Z: only what lies in front of the opaque surfaces is drawn) and which only the
  // transmissive set writes.
  std::function<void(const BlendedProgram& program, BlendOrder order, int repeats, BlendedSet set)> draw;
};

}  // namespace pbr
