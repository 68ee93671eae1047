// What a transmissive surface (KHR_materials_transmission) sees through itself: the opaque frame behind it
// (TransmissionTargets: the radiance target copied, with its mip chain), in glTF-Sample-Viewer's screen-space
// form. Thin-walled (thickness 0) along the view ray; with KHR_materials_volume, at the point where the view ray,
// refracted by the index of refraction, leaves a slab of the thickness under the surface (the thickness is in the
// object's space), attenuated over that path by Beer-Lambert's law, attenuationColor^(d / attenuationDistance)
// (the volume extension's sigma = -ln(attenuationColor) / attenuationDistance). Roughness blurs it: the mip level is
// log2(width) roughness, scaled by clamp(2 ior - 2, 0, 1) as glTF-Sample-Viewer does (ior 1 does not blur).
layout(binding = TRANSMISSION_BACKGROUND_UNIT) uniform sampler2D transmissionBackground;

vec3 transmittedRadiance(Surface s, float thickness) {
  float ior = object.transmission.w;
  vec3 path = vec3(0.0);
  if (thickness > 0.0 && ior >= 1.0) {
    // The thickness across the surface in world space: an object-space distance t along the object's normal
    // spans t |M^T n| between the planes it separates (M the model matrix, n the world normal); the volume taken
    // as a slab that thick, the refracted ray crosses it in that over its cosine to the normal.
    vec3 refracted = refract(-s.V, s.normal, 1.0 / ior);
    float across = thickness * length(s.normal * mat3(object.model));
    path = refracted * (across / max(dot(-s.normal, refracted), 0.1));
  }
  vec4 clip = frame.viewProjection * vec4(s.position + path, 1.0);
  vec2 uv = clip.w > 0.0 ? clip.xy / clip.w * 0.5 + 0.5 : gl_FragCoord.xy * frame.viewport.zw;
  float lod = log2(max(frame.viewport.x, frame.viewport.y)) * s.roughness * clamp(2.0 * ior - 2.0, 0.0, 1.0);
  vec3 behind = textureLod(transmissionBackground, uv, lod).rgb;
  float attenuationDistance = object.transmission.z;  // 0: no absorption
  // A thin wall absorbs nothing (and pow(0, 0) is undefined): only a volume's path does.
  if (attenuationDistance > 0.0 && thickness > 0.0) {
    behind *= pow(object.attenuationColor.rgb, vec3(length(path) / attenuationDistance));
  }
  return behind;
}
