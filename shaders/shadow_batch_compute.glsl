// SPDX-License-Identifier: MIT
// What the shadow batch's compute passes share (shadow_cull.comp, shadow_draws.comp,
// shadow_scatter.comp, shadow_raster.comp): their push constants, the casters, and the per-draw
// counts. Pairs come in two lists: list 0 (`total`), and list 1 (`moving_total`), the moving
// casters' pairs, drawn after the static layers are saved (systems/shadow_maps/shadow_view_batch.h).
#ifndef SG_SHADOW_BATCH_COMPUTE_GLSL
#define SG_SHADOW_BATCH_COMPUTE_GLSL

#include "shadow_views.glsl"

layout(push_constant) uniform BatchConstants {
  uint caster_count;
  uint group_count;  // caster groups (meshes); each has one draw per view kind
  uint capacity;     // culled pairs the list's pair buffer holds
  uint view_base;    // the first view of this dispatch (shadow_cull.comp)
  uint caster_base;  // the first caster record of this dispatch (shadow_cull.comp)
  uint list;         // 0 or 1: the pair list this dispatch writes or reads
  uint skip_moving;  // shadow_cull.comp: not 0: moving casters are left to list 1
  uint moving_capacity;  // shadow_draws.comp: list 1's capacity
  uint block_base;       // shadow_cull.comp: the first block record of this dispatch's casters
} pc;

layout(std430, set = 0, binding = shadow_casters_binding) readonly buffer Casters { ShadowCaster casters[]; };

// Zeroed before culling.
layout(std430, set = 0, binding = draw_counts_binding) buffer Counts {
  uint total;         // list 0's pairs kept, stored or not
  uint moving_total;  // list 1's
  uint unused[2];
  uint counts[];  // [0, draws): pairs per draw; [draws, 2 draws): the scatter's cursors
};

uint draw_count() { return VIEW_KINDS * pc.group_count; }

#endif
