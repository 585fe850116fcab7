// SPDX-License-Identifier: MIT
// What a pixel of the G-buffer's normal target holds (rgba16f), written by gbuffer.glsl and read
// by tiled_lighting.glsl: xy the unit normal, octahedral; z the Blinn shininess, negated where the
// surface receives no shadow; w its light layers (MeshInstance::light_layers), 0 to 255, which a
// half float holds exactly. The octahedral pair keeps the normal within a half float's step, as
// the three components did, and frees w for the layers at no extra bytes a pixel.
#ifndef SG_GBUFFER_LAYOUT_GLSL
#define SG_GBUFFER_LAYOUT_GLSL

// The octahedron's net of unit vector n: its upper half folded onto the square's centre, the
// lower half onto its corners.
vec2 octahedral_encode(vec3 n) {
  vec2 p = n.xy / (abs(n.x) + abs(n.y) + abs(n.z));
  if (n.z >= 0.0) return p;
  return (1.0 - abs(p.yx)) * vec2(p.x >= 0.0 ? 1.0 : -1.0, p.y >= 0.0 ? 1.0 : -1.0);
}

vec3 octahedral_decode(vec2 e) {
  vec3 n = vec3(e, 1.0 - abs(e.x) - abs(e.y));
  float fold = max(-n.z, 0.0);
  n.x += n.x >= 0.0 ? -fold : fold;
  n.y += n.y >= 0.0 ? -fold : fold;
  return normalize(n);
}

vec4 gbuffer_normal_texel(vec3 normal, float shininess, bool receives_shadow, uint light_layers) {
  return vec4(octahedral_encode(normal), receives_shadow ? shininess : -shininess, float(light_layers));
}

#endif
