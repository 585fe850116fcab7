// SPDX-License-Identifier: MIT
// The materials' base color textures and what a pipeline's materials need, shared by the
// camera passes (material.glsl) and the shadow passes' cut-outs (shadow_cut_out.glsl).
#ifndef SG_MATERIAL_TEXTURES_GLSL
#define SG_MATERIAL_TEXTURES_GLSL

#include "bindings.glsl"

// Every material texture of the scene, one per layer (systems/gpu/gpu_textures.h).
layout(set = 0, binding = material_textures_binding) uniform sampler2DArray base_color_textures;
// What a pipeline's materials need (material_pass_constants, systems/gpu/gpu_textures.h), a bit
// each; constant_id 0 and 1 are the including shaders' own. Bit 0, textures: clear for a scene
// without images, as a CPU driver samples the texture for every fragment whatever the branch
// says (it runs both sides of every branch). Bit 1, a mask's cut-out: only pipelines that draw
// masked materials discard, since a shader that may discard loses the early depth test.
layout(constant_id = 2) const uint MATERIAL_FEATURES = 1u;
const bool MATERIAL_TEXTURES = (MATERIAL_FEATURES & 1u) != 0u;
const bool ALPHA_TEST = (MATERIAL_FEATURES & 2u) != 0u;

#endif
