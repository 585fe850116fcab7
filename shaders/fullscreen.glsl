// SPDX-License-Identifier: MIT
// One triangle that covers the viewport, for passes that shade every pixel of it; uv runs 0..1
// across the viewport (out location 0). Draw 3 vertices, no vertex buffer. The engine's
// fullscreen.vert is this; a pass built outside the engine includes it in a vertex shader of its
// own (sandbox/examples/custom_pass).
#ifndef SG_FULLSCREEN_GLSL
#define SG_FULLSCREEN_GLSL

layout(location = 0) out vec2 out_uv;

void emit_fullscreen_vertex() {
  out_uv = vec2((gl_VertexIndex << 1) & 2, gl_VertexIndex & 2);
  gl_Position = vec4(out_uv * 2.0 - 1.0, 0.0, 1.0);
}

#endif
