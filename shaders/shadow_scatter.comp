// SPDX-License-Identifier: MIT
#version 460
#extension GL_GOOGLE_include_directive : require
// Moves each stored (caster, view) pair into its draw's instance range (shadow_draws.comp's
// cursors) as (instance, view), the order shadow_batch.vert reads them by gl_InstanceIndex.
// Dispatched indirectly, a thread per stored pair (each thread takes several past 65,535
// workgroups, the smallest limit devices may have).
#include "shadow_batch_compute.glsl"

layout(local_size_x = 64) in;

layout(std430, set = 0, binding = culled_pairs_binding) readonly buffer Pairs { uvec2 pairs[]; };
layout(std430, set = 0, binding = view_instances_binding) writeonly buffer Sorted { uvec2 sorted_pairs[]; };

void main() {
  uint stored = min(total, pc.capacity);
  uint stride = gl_NumWorkGroups.x * gl_WorkGroupSize.x;
  for (uint i = gl_GlobalInvocationID.x; i < stored; i += stride) {
    uvec2 pair = pairs[i];
    uint group = caster_group(casters[pair.x]);
    uint draw = views[pair.y].info.y * pc.group_count + group;
    uint slot = atomicAdd(counts[draw_count() + draw], 1u);
    sorted_pairs[slot] = uvec2(caster_instance(casters[pair.x]), pair.y);
  }
}
