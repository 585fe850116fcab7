// SPDX-License-Identifier: MIT
#version 460
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_control_flow_attributes : require
// Keeps every (caster, view) pair whose caster shares a layer with the view's light's caster mask
// and whose world bounds meet the view's frustum, but for a transparent caster whose bounds hold
// the view's light (a light inside a glass bulb or a marker is not shut in by it;
// ShadowCasterLists::add_view does the same per light): one workgroup per view (a row of
// views from view_base), testing the casters' blocks first (CASTER_BLOCK casters each, records
// block_base on), then the casters of the blocks that pass, a thread each (records caster_base
// on). Pairs go to culled_pairs in any order (at most `capacity`; the list's total counts every
// kept pair, so the CPU learns when to grow); each list 0 pair counts towards its draw (view
// kind, caster group). Counts start at zero.
#include "shadow_batch_compute.glsl"

// A thread per block, then per caster of a block. With 100,000 lights (14,682 casters, 4,096 views
// a frame) the pass took 0.12 ms, against 1.09-1.12 testing every pair with a thread each
// (H200, 1920x1080, 2026-12-04). With 1,024 lights at eye height the raster reading the pairs
// took 0.61 ms against 0.51, likely because they now come by view, the views in the order their
// workgroups ran rather than roughly in view order; placing each block's pairs together did not
// change that.
layout(local_size_x = CASTER_BLOCK) in;

layout(std430, set = 0, binding = culled_pairs_binding) writeonly buffer Pairs { uvec2 pairs[]; };

shared uint blocks_met[CASTER_BLOCK];  // this round's blocks that meet the view
shared uint blocks_met_count;

// The view's frustum planes (as shadows::frustum_planes: dot(plane.xyz, p) + plane.w >= 0 inside,
// Vulkan depth 0..1), from its matrix's rows rather than the record: 96 bytes less a view for the
// CPU to fill and upload each frame.
vec4 planes[6];

// Whether the box [lo, hi] meets the frustum: its corner farthest along each plane's normal is
// inside that plane.
bool box_meets_frustum(vec3 lo, vec3 hi) {
  [[unroll]] for (int p = 0; p < 6; ++p) {
    vec3 corner = mix(lo, hi, greaterThanEqual(planes[p].xyz, vec3(0.0)));
    if (dot(planes[p].xyz, corner) + planes[p].w < 0.0) return false;
  }
  return true;
}

// Whether the caster (or block) record shares a layer with the view and meets its frustum.
bool record_meets_view(ShadowCaster record, ShadowView view) {
  return caster_in_view(record, view) && box_meets_frustum(record.lo, record.hi);
}

// Whether the cull keeps the pair.
bool kept(ShadowCaster caster, ShadowView view) {
  if (pc.skip_moving != 0u && caster_moving(caster)) return false;
  if (!record_meets_view(caster, view)) return false;
  if (caster_blended(caster)) {
    vec4 light = view.position_far;
    if (light.w >= 0.0 && all(greaterThanEqual(light.xyz, caster.lo)) && all(lessThanEqual(light.xyz, caster.hi))) return false;
  }
  return true;
}

// Lists the pair, and counts it towards its draw (list 0).
void keep(uint caster, ShadowCaster caster_record, uint view, ShadowView view_record) {
  if (pc.list != 0u) {
    uint slot = atomicAdd(moving_total, 1u);
    if (slot < pc.capacity) pairs[slot] = uvec2(caster, view);
    return;
  }
  uint slot = atomicAdd(total, 1u);
  if (slot >= pc.capacity) return;
  pairs[slot] = uvec2(caster, view);
  atomicAdd(counts[view_record.info.y * pc.group_count + caster_group(caster_record)], 1u);
}

void main() {
  uint local = gl_LocalInvocationIndex;
  uint view = pc.view_base + gl_WorkGroupID.y;
  ShadowView view_record = views[view];
  mat4 m = view_record.view_projection;
  vec4 row0 = vec4(m[0][0], m[1][0], m[2][0], m[3][0]);
  vec4 row1 = vec4(m[0][1], m[1][1], m[2][1], m[3][1]);
  vec4 row2 = vec4(m[0][2], m[1][2], m[2][2], m[3][2]);
  vec4 row3 = vec4(m[0][3], m[1][3], m[2][3], m[3][3]);
  planes = vec4[](row3 + row0, row3 - row0, row3 + row1, row3 - row1, row2, row3 - row2);
  uint block_count = (pc.caster_count + CASTER_BLOCK - 1u) / CASTER_BLOCK;
  for (uint first = 0u; first < block_count; first += CASTER_BLOCK) {
    if (local == 0u) blocks_met_count = 0u;
    barrier();
    uint block = first + local;
    if (block < block_count && record_meets_view(casters[pc.block_base + block], view_record)) {
      blocks_met[atomicAdd(blocks_met_count, 1u)] = block;
    }
    barrier();
    uint met = blocks_met_count;
    for (uint b = 0u; b < met; ++b) {
      uint k = blocks_met[b] * CASTER_BLOCK + local;
      if (k >= pc.caster_count) continue;
      uint caster = pc.caster_base + k;
      ShadowCaster caster_record = casters[caster];
      if (kept(caster_record, view_record)) keep(caster, caster_record, view, view_record);
    }
    barrier();
  }
}
