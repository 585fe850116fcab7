// SPDX-License-Identifier: MIT
// The lighting pass's light resources, beside the instance buffer of scene_interface.glsl. shadow_sampling.glsl says which sampler each binding expects.
#ifndef SG_LIGHTS_INTERFACE_GLSL
#define SG_LIGHTS_INTERFACE_GLSL

#include "bindings.glsl"
#include "light_record.glsl"

// Bit t set where lights of type t (LIGHT_*) may be shaded, bit CASCADED_TYPE_BIT where
// directional lights with cascades may (sg::shadows::light_type_bits): a pass that knows the
// types of its lights compiles only their code (a CPU driver runs every branch a shader holds).
// The shading functions take such bits as an argument: LIGHT_TYPES, or, in a pass shading several
// light groups, each group's own.
// constant_id 0 to 2 are the including shaders' own and material.glsl's.
layout(constant_id = 3) const uint LIGHT_TYPES = 0x1Fu;
// constant_id 10 (4 to 9 are the including shaders' own): the device cannot filter the shadow
// atlas's depth format, so shadow_atlas_compare is nearest and each comparison reads one texel
// (sg::LightResources::specialized).
layout(constant_id = 10) const bool NEAREST_COMPARISONS = false;

// The light types of `types` alone, cascaded directional lights counted as directional.
uint light_types_only(uint types) {
  return (types & 0xFu) | ((types >> CASCADED_TYPE_BIT) & 1u) << LIGHT_DIRECTIONAL;
}

// Light `light`'s type, a constant where `types` (a constant) admits one type only.
uint light_type(Light light, uint types) {
  uint only = light_types_only(types);
  if (only == (1u << LIGHT_POINT)) return LIGHT_POINT;
  if (only == (1u << LIGHT_SPOT)) return LIGHT_SPOT;
  if (only == (1u << LIGHT_DIRECTIONAL)) return LIGHT_DIRECTIONAL;
  if (only == (1u << LIGHT_CYLINDER)) return LIGHT_CYLINDER;
  return light.info.x;
}

// Group `group`'s light types from `packed`, five bits a group for the unshadowed and 2D groups
// (sg::shadows::GroupsPresent::group_types); a cube group's lights are point lights.
uint group_light_types(uint packed, uint group) {
  return group < 6u ? (packed >> (5u * group)) & 0x1Fu : 1u << LIGHT_POINT;
}

// Every light of the frame (sg::shadows::GpuLight on the C++ side): light_at(i) is the i-th record.
#ifdef LIGHT_RECORDS_IN_STORAGE
// A storage buffer, in a shader's storage_records variant (LightRecordsIn in
// systems/lighting/lighting_path.h says which passes take it where): the lanes of a GPU's warp
// that read one light's record load it once, where 13 texel fetches go through the texture units
// for every lane.
layout(std430, set = 0, binding = lights_binding) readonly buffer LightRecords { Light light_records[]; };

Light light_at(uint index) { return light_records[index]; }
uvec4 light_info_at(uint index) { return light_records[index].info; }
#else
// 208 bytes as 13 texels of a uniform texel buffer: llvmpipe fetches texels for all lanes at once,
// where it loads storage-buffer words lane by lane, one loop per load. The members lie at the
// offsets of Light's std430 layout, 16 bytes a texel.
layout(set = 0, binding = lights_binding) uniform usamplerBuffer light_records;

const int LIGHT_RECORD_TEXELS = 13;

Light light_at(uint index) {
  int first = int(index) * LIGHT_RECORD_TEXELS;
  Light light;
  light.position_range = uintBitsToFloat(texelFetch(light_records, first));
  light.direction_type = uintBitsToFloat(texelFetch(light_records, first + 1));
  light.info = texelFetch(light_records, first + 2);
  light.shape = uintBitsToFloat(texelFetch(light_records, first + 3));
  light.shadow_color_density = uintBitsToFloat(texelFetch(light_records, first + 4));
  light.shadow_bias = uintBitsToFloat(texelFetch(light_records, first + 5));
  light.color_intensity = uintBitsToFloat(texelFetch(light_records, first + 6));
  light.shadow_rect = uintBitsToFloat(texelFetch(light_records, first + 7));
  light.shadow_depth = uintBitsToFloat(texelFetch(light_records, first + 8));
  light.shadow_matrix[0] = uintBitsToFloat(texelFetch(light_records, first + 9));
  light.shadow_matrix[1] = uintBitsToFloat(texelFetch(light_records, first + 10));
  light.shadow_matrix[2] = uintBitsToFloat(texelFetch(light_records, first + 11));
  light.shadow_matrix[3] = uintBitsToFloat(texelFetch(light_records, first + 12));
  return light;
}

// Record `index`'s info alone (Light::info): a walk over records sorted by group reads it to find
// where a group ends, one texel where the whole record is 13.
uvec4 light_info_at(uint index) { return texelFetch(light_records, int(index) * LIGHT_RECORD_TEXELS + 2); }
#endif

// Every shadow map: one depth array of atlas pages; a 2D map is the tile shadow_rect of layer
// info.w, a point light's cube six tiles of that layer (light_record.glsl).
layout(set = 0, binding = shadow_maps_binding) uniform sampler2DArray shadow_atlas;
// The same image through a comparison sampler, for hardware PCF.
layout(set = 0, binding = shadow_maps_compare_binding) uniform sampler2DArrayShadow shadow_atlas_compare;

#endif
