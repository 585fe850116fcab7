// SPDX-License-Identifier: MIT
#version 460
#extension GL_GOOGLE_include_directive : require
// Turns the culled pairs' counts into the frame's indirect draws and dispatches: draw k * groups + g draws
// caster group g's mesh once per pair of view kind k, its instances a range of the sorted
// pairs starting where the previous draw's end. Also writes the scatter's dispatch, its cursors
// (each draw's first instance), the raster's dispatches of both lists, and the lists' totals for
// the CPU (shadow_feedback). One thread: there
// are two draws per mesh, a few hundred at most.
#include "shadow_batch_compute.glsl"

layout(local_size_x = 1) in;

layout(std430, set = 0, binding = caster_meshes_binding) readonly buffer Meshes { CasterMesh meshes[]; };
layout(std430, set = 0, binding = shadow_draws_binding) writeonly buffer Draws {
  uvec4 scatter_dispatch;  // x, y, z workgroups of shadow_scatter.comp
  uvec4 raster_dispatch;   // and of shadow_raster.comp, a workgroup per pair of list 0
  uvec4 moving_raster_dispatch;  // of list 1
  DrawCommand draws[];
};
layout(std430, set = 0, binding = shadow_feedback_binding) writeonly buffer Feedback {
  uint kept_pairs;
  uint kept_moving_pairs;
};

void main() {
  uint draws_total = draw_count();
  uint first = 0u;
  for (uint d = 0u; d < draws_total; ++d) {
    CasterMesh mesh = meshes[d % pc.group_count];
    uint n = counts[d];
    draws[d] = DrawCommand(mesh.index_count, n, mesh.first_index, mesh.vertex_offset, first);
    counts[draws_total + d] = first;
    first += n;
  }
  uint stored = min(total, pc.capacity);
  scatter_dispatch = uvec4(min((stored + 63u) / 64u, 65535u), 1u, 1u, 0u);
  raster_dispatch = uvec4(min(stored, 65535u), 1u, 1u, 0u);
  moving_raster_dispatch = uvec4(min(min(moving_total, pc.moving_capacity), 65535u), 1u, 1u, 0u);
  kept_pairs = total;
  kept_moving_pairs = moving_total;
}
