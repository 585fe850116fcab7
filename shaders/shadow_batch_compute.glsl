// What the shadow batch's compute passes share (shadow_cull.comp, shadow_draws.comp,
// shadow_scatter.comp): their push constants, the casters, and the per-draw counts.
#ifndef SG_SHADOW_BATCH_COMPUTE_GLSL
#define SG_SHADOW_BATCH_COMPUTE_GLSL

#include "shadow_views.glsl"

layout(push_constant) uniform BatchConstants {
  uint caster_count;
  uint group_count;  // caster groups (meshes); each has one draw per view kind
  uint capacity;     // culled pairs the pair buffers hold
  uint view_base;    // the first view of this dispatch (shadow_cull.comp)
} pc;

layout(std430, set = 0, binding = shadow_casters_binding) readonly buffer Casters { ShadowCaster casters[]; };

// Zeroed before culling.
layout(std430, set = 0, binding = draw_counts_binding) buffer Counts {
  uint total;  // pairs kept, stored or not
  uint unused[3];
  uint counts[];  // [0, draws): pairs per draw; [draws, 2 draws): the scatter's cursors
};

uint draw_count() { return VIEW_KINDS * pc.group_count; }

#endif
