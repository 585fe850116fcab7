// SPDX-License-Identifier: MIT
#version 460
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_control_flow_attributes : require
// Keeps every (caster, view) pair whose caster shares a layer with the view's light's caster mask
// and whose world bounds meet the view's frustum, but for a transparent caster whose bounds hold
// the view's light (a light inside a glass bulb or a marker is not shut in by it;
// ShadowCasterLists::add_view does the same per light): one thread per caster (records
// caster_base on), one workgroup row per view. Pairs go to culled_pairs in any order (at most
// `capacity`; the list's total counts every kept pair, so the CPU learns when to grow); each list
// 0 pair counts towards its draw (view kind, caster group). Counts start at zero.
#include "shadow_batch_compute.glsl"

layout(local_size_x = 64) in;

layout(std430, set = 0, binding = culled_pairs_binding) writeonly buffer Pairs { uvec2 pairs[]; };

void main() {
  if (gl_GlobalInvocationID.x >= pc.caster_count) return;
  uint caster = pc.caster_base + gl_GlobalInvocationID.x;
  uint view = pc.view_base + gl_WorkGroupID.y;
  if (pc.skip_moving != 0u && caster_moving(casters[caster])) return;
  if (!caster_in_view(casters[caster], views[view])) return;
  vec3 lo = casters[caster].lo;
  vec3 hi = casters[caster].hi;
  if (caster_blended(casters[caster])) {
    vec4 light = views[view].position_far;
    if (light.w >= 0.0 && all(greaterThanEqual(light.xyz, lo)) && all(lessThanEqual(light.xyz, hi))) return;
  }
  // The frustum's planes from the matrix's rows (as shadows::frustum_planes: dot(plane.xyz, p) +
  // plane.w >= 0 inside, Vulkan depth 0..1), here rather than in the record: 96 bytes less a view
  // for the CPU to fill and upload each frame.
  mat4 m = views[view].view_projection;
  vec4 row0 = vec4(m[0][0], m[1][0], m[2][0], m[3][0]);
  vec4 row1 = vec4(m[0][1], m[1][1], m[2][1], m[3][1]);
  vec4 row2 = vec4(m[0][2], m[1][2], m[2][2], m[3][2]);
  vec4 row3 = vec4(m[0][3], m[1][3], m[2][3], m[3][3]);
  vec4 planes[6] = vec4[](row3 + row0, row3 - row0, row3 + row1, row3 - row1, row2, row3 - row2);
  [[unroll]] for (int p = 0; p < 6; ++p) {
    vec4 plane = planes[p];
    // The box's corner farthest along the plane's normal.
    vec3 corner = mix(lo, hi, greaterThanEqual(plane.xyz, vec3(0.0)));
    if (dot(plane.xyz, corner) + plane.w < 0.0) return;
  }
  if (pc.list != 0u) {
    uint slot = atomicAdd(moving_total, 1u);
    if (slot < pc.capacity) pairs[slot] = uvec2(caster, view);
    return;
  }
  uint slot = atomicAdd(total, 1u);
  if (slot >= pc.capacity) return;
  pairs[slot] = uvec2(caster, view);
  atomicAdd(counts[views[view].info.y * pc.group_count + caster_group(casters[caster])], 1u);
}
