// The lighting pass's light resources, beside the instance buffer of scene_interface.glsl. shadow_sampling.glsl says which sampler each binding expects.
#ifndef SG_LIGHTS_INTERFACE_GLSL
#define SG_LIGHTS_INTERFACE_GLSL

#include "bindings.glsl"
#include "light_record.glsl"

// Every light of the frame (sg::shadows::GpuLight on the C++ side).
layout(std430, set = 0, binding = lights_binding) readonly buffer Lights { Light lights[]; };
// Every shadow map: one depth array of atlas pages; a 2D map is the tile shadow_rect of layer
// info.w, a point light's cube six tiles of that layer (light_record.glsl).
layout(set = 0, binding = shadow_maps_binding) uniform sampler2DArray shadow_atlas;
// The same image through a comparison sampler, for hardware PCF.
layout(set = 0, binding = shadow_maps_compare_binding) uniform sampler2DArrayShadow shadow_atlas_compare;

#endif
