// SPDX-License-Identifier: MIT
#version 460
// One triangle that covers the viewport, for passes that shade every pixel of it; uv runs 0..1
// across the viewport (out location 0). Draw 3 vertices, no vertex buffer.
layout(location = 0) out vec2 out_uv;

void main() {
  out_uv = vec2((gl_VertexIndex << 1) & 2, gl_VertexIndex & 2);
  gl_Position = vec4(out_uv * 2.0 - 1.0, 0.0, 1.0);
}
