#pragma once
#include "core/scene/gltf_file.hpp"

namespace pbr {

// EXT_meshopt_compression: decodes every buffer view that carries the extension with Debian's libmeshoptimizer
// (ATTRIBUTES with the NONE, OCTAHEDRAL, QUATERNION or EXPONENTIAL filter, TRIANGLES, INDICES) into a buffer of
// its own, and points the view at it, so that accessors read the decoded bytes. Every parameter the decoder
// relies on is checked first (the library asserts them only in debug builds); throws SceneError naming the view's
// extension field.
void decodeMeshoptViews(GltfFile& file);

}  // namespace pbr
