#pragma once
#include "core/scene/mesh.hpp"

namespace pbr {

// Whether a mesh bounds a solid, and which way its faces look. A closed mesh (along every edge between two
// positions, as many triangles run one way as the other) is the boundary of a solid: a ray from a point outside
// the solid first meets a face turned toward that point, so a shadow view whose eye lies outside it draws the same
// nearest depths without the faces turned away. An open mesh (a plane, a shell with holes) may be seen first from
// either side.
enum class MeshClosure {
  Open,
  Outward,  // closed, counter-clockwise faces looking out of the solid (positive signed volume)
  Inward,   // closed, counter-clockwise faces looking in (negative signed volume)
};

// Edges are matched by vertex position, not index: a glTF mesh splits a position where its normals or UVs do, and
// positions a millionth of the mesh's size apart count as one (weldPositions). A triangle with two corners at one
// position (a UV sphere's pole) adds two opposite edges, which cancel. A closed mesh whose signed volume is within
// 1e-6 of its box's (a card drawn from both sides) counts as open: neither side can be called its outside.
MeshClosure meshClosure(const MeshData& mesh);

}  // namespace pbr
