// SPDX-License-Identifier: MIT
#version 460
// Many small shadow views in one target, as a tiled shadow atlas would hold them: each command
// of one multi-draw indirect call is one view, its firstInstance the view's index (as the
// engine's indirect draws index per-instance data, and unlike gl_DrawID it survives splitting
// the call), and the shader moves the mesh (NDC -1..1) into that view's tile, row by row. This
// stands in for a viewport per view; the meshes stay inside their tile, so no scissor is needed.
layout(location = 0) in vec2 in_position;

layout(push_constant) uniform Tiles {
  uint tiles_per_row;
}
tiles;

void main() {
  const uint view = uint(gl_InstanceIndex);
  const vec2 tile = vec2(view % tiles.tiles_per_row, view / tiles.tiles_per_row);
  const vec2 target_uv = (in_position * 0.5 + 0.5 + tile) / float(tiles.tiles_per_row);
  gl_Position = vec4(target_uv * 2.0 - 1.0, 0.5, 1.0);
}
