// SPDX-License-Identifier: MIT
// One light as the shaders see it: every light of the frame is one element of the Lights
// storage buffer (lights_interface.glsl). Must match sg::shadows::GpuLight
// (systems/shadows/gpu_light.h); tests/shadows/light_record_layout_test.cpp compares the two
// from glslang's reflection of this declaration. std430, every member 16-byte aligned: 208 bytes.
#ifndef SG_LIGHT_RECORD_GLSL
#define SG_LIGHT_RECORD_GLSL

const uint LIGHT_POINT = 0u;
const uint LIGHT_SPOT = 1u;
const uint LIGHT_DIRECTIONAL = 2u;
const uint LIGHT_CYLINDER = 3u;

const uint FALLOFF_LINEAR_WINDOW = 0u;
const uint FALLOFF_GLTF_PUNCTUAL = 1u;

const uint SHADOW_HARD = 0u;
const uint SHADOW_PCF = 1u;
const uint SHADOW_NOISE = 2u;
const uint SHADOW_PCSS = 3u;
const uint SHADOW_PCSS_NOISE = 4u;

// info.y: the falloff in bits 0 to 7, the layers the light lights from this bit on.
const uint LIGHT_MASK_SHIFT = 8u;

// info.z: the algorithm in bits 0 to 7, then its kernel's sizes (sg::scene::ShadowKernel): the
// pcf grid's half width (2 bits), the pcss blocker and filter taps less one (4 and 5 bits), log2
// of the noise taps' stride through NOISE_SAMPLES (2 bits).
const uint KERNEL_PCF_SHIFT = 8u;
const uint KERNEL_BLOCKER_SHIFT = 10u;
const uint KERNEL_FILTER_SHIFT = 14u;
const uint KERNEL_NOISE_SHIFT = 19u;

const uint NO_SHADOW_MAP = 0xFFFFFFFFu;
// info.w of a directional light whose maps are cascades (systems/shadows/cascades.h): each is a
// record of its own after the frame's lights, holding its map in the shadow fields.
const uint CASCADED_SHADOW_MAPS = 0xFFFFFFFEu;
// The bit a directional light with cascades sets in a pass's LIGHT_TYPES (lights_interface.glsl)
// instead of LIGHT_DIRECTIONAL's (sg::shadows::light_type_bits).
const uint CASCADED_TYPE_BIT = 4u;

struct Light {
  vec4 position_range;        // xyz: world position (point, spot, cylinder); w: range R (point, spot; 0 otherwise)
  vec4 direction_type;        // xyz: unit direction the light travels (spot, directional, cylinder);
                              // w: its contact shadows' length, world units (0: none)
  uvec4 info;                 // x: type (LIGHT_*); y: bits 0-7 falloff (FALLOFF_*), bits 8-15 the layers
                              // it lights (ShadowSettings::light_mask); z: bits 0-7 algorithm (SHADOW_*),
                              // then its kernel's sizes (KERNEL_*);
                              // w: the shadow atlas layer of its map (or of all six cube faces), NO_SHADOW_MAP
                              // or CASCADED_SHADOW_MAPS
  vec4 shape;                 // spot: x cos(inner), y cos(outer); cylinder: z inner radius r, w outer radius R;
                              // cascaded directional: x the first cascade's record, y the cascades in use
  vec4 shadow_color_density;  // rgb: shadow color sc; a: density
  vec4 shadow_bias;           // x: constant bias b0, y: slope bias b1, z: pcf radius (texels), w: light size (world units)
  vec4 color_intensity;       // rgb: linear color; a: intensity
  vec4 shadow_rect;           // xy: 2D maps' uv offset in the layer; zw: uv scale of its (each face's) tile
  vec4 shadow_depth;          // x: near, y: far, z: texel size in uv of the light's map (1/resolution),
                              // w: 0 perspective, 1 orthographic
  mat4 shadow_matrix;         // 2D maps: world -> light clip space (Vulkan, depth [0,1]);
                              // point lights: columns 0..2 hold the uv offsets of faces 0..5, two a
                              // column, column 3 the position the cube was rendered from (xyz)
};

// Whether `light` lights a surface on `layers` (MeshInstance::light_layers).
bool lights_layers(Light light, uint layers) { return ((light.info.y >> LIGHT_MASK_SHIFT) & layers) != 0u; }

uint light_algorithm(Light light) { return light.info.z & ((1u << KERNEL_PCF_SHIFT) - 1u); }
int pcf_half_width(Light light) { return int((light.info.z >> KERNEL_PCF_SHIFT) & 3u); }
uint pcss_blocker_taps(Light light) { return ((light.info.z >> KERNEL_BLOCKER_SHIFT) & 15u) + 1u; }
uint pcss_filter_taps(Light light) { return ((light.info.z >> KERNEL_FILTER_SHIFT) & 31u) + 1u; }
uint noise_tap_stride(Light light) { return 1u << ((light.info.z >> KERNEL_NOISE_SHIFT) & 3u); }

uint light_falloff(Light light) { return light.info.y & ((1u << LIGHT_MASK_SHIFT) - 1u); }

#endif
