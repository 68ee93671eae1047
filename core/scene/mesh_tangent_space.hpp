#pragma once
#include "core/scene/mesh.hpp"

namespace pbr {

// Gives every triangle its own three vertices carrying the face normal: glTF's rule for meshes without normals.
void makeFlatNormals(MeshData& mesh);

// Replaces zero-length or non-finite normals by the area-weighted normal of the triangles around the vertex.
void repairNormals(MeshData& mesh);

// Per-vertex tangents from the UV layout: per-triangle dP/du and bitangents accumulated at the vertices, then
// Gram-Schmidt against the normal. Handedness as MikkTSpace: w = sign(dot(cross(n, t), b)). Normals must be
// usable (see repairNormals).
void generateTangents(MeshData& mesh);

}  // namespace pbr
