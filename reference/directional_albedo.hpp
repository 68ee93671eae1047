#pragma once
#include <vector>

#include <glm/vec3.hpp>

#include "reference/reference_brdf.hpp"

namespace pbr::reference {

// The directional albedo of the reference BRDF, integral of f(l, v) n.l over the hemisphere, by deterministic
// stratified importance sampling: GGX visible normals for the specular lobe (Heitz 2018), cosine-weighted
// directions for the diffuse lobe. `samples` per axis of the stratified grid.
dvec3 directionalAlbedo(const ReferenceMaterial& m, double NoV, const BrdfForms& forms = {}, int samples = 64);

// The directional albedo at the centres of `bins` (at least 2) equal intervals of n.v, linear between them and
// held beyond the outermost: the exact response to uniform ambient light, which per pixel would cost milliseconds.
class AlbedoTable {
 public:
  AlbedoTable() = default;  // empty: for materials that no ambient light reaches
  AlbedoTable(const ReferenceMaterial& m, const BrdfForms& forms, int bins, int samples);
  bool empty() const { return values_.empty(); }
  dvec3 operator()(double NoV) const;

 private:
  std::vector<dvec3> values_;
};

}  // namespace pbr::reference
