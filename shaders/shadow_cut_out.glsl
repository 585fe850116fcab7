// SPDX-License-Identifier: MIT
// Shadow casters with a cut-out (systems/gpu/gpu_scene.h's draw_masked and draw_blended classes)
// leave no depth where their surface is not. A mask cuts at its cutoff (glTF's alphaCutoff), as
// the camera passes do. A transparent surface (a negative cutoff in its instance's material)
// covers a share of the shadow texels equal to its alpha, each texel cut against a threshold of
// its own, so that a filtered lookup darkens by its alpha (stochastic transparency): a pane of
// alpha 0.4 casts a shadow of about 40%, PCF and PCSS smooth it, hard shadows show the dither.
#ifndef SG_SHADOW_CUT_OUT_GLSL
#define SG_SHADOW_CUT_OUT_GLSL

#include "material_textures.glsl"

// The alpha under which a caster's surface at `texel` of the atlas casts nothing: `cutoff`, or
// for a transparent surface a threshold in (0, 1] from interleaved gradient noise (Jimenez 2014),
// whose neighbouring values spread evenly, so that a 3x3 kernel sees close to the alpha.
float shadow_alpha_threshold(float cutoff, uvec2 texel) {
  if (cutoff >= 0.0) return cutoff;
  return 1.0 - fract(52.9829189 * fract(dot(vec2(texel), vec2(0.06711056, 0.00583715))));
}

// Whether a caster with `material` (scene_instances.glsl's Instance::material: y its texture
// layer or -1, z its base color alpha, w its cutoff) is cut out at `uv`, at `texel` of the
// atlas. The texture array has one level, so level 0 is what texture() would sample, and compute
// shaders may call this too.
bool shadow_cut_out(vec4 material, vec2 uv, uvec2 texel) {
  float alpha = material.z;
  int layer = int(material.y);
  if (MATERIAL_TEXTURES && layer >= 0) alpha *= textureLod(base_color_textures, vec3(uv, float(layer)), 0.0).a;
  return alpha < shadow_alpha_threshold(material.w, texel);
}

#endif
