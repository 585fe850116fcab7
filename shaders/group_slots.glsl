// SPDX-License-Identifier: MIT
// Which light groups a shader that shades several groups at once calls its shading for
// (scene_fused.frag, transparent_tiled.frag, tiled_lighting_set.comp): one call a slot, each with
// the group in it. A CPU driver inlines each call's whole shading code, every algorithm's, before
// the groups a pipeline lacks drop out, and so a pipeline's build time grows with its calls: on
// lavapipe, a pipeline of the fused forward pass for one light took 2.0-3.9 s to build with a
// call for each of the eleven groups and 0.15-0.37 s with one (2026-12-06). A shader that defines
// GROUP_SLOTS, the calls it makes, takes their groups from GROUP_SLOT_LIST (a slot it leaves
// empty holds group 15); one that does not has a slot for every group. FOR_EACH_GROUP_SLOT(CALL)
// writes CALL(0u) to CALL(GROUP_SLOTS - 1u), each call site's slot a literal.
#ifndef SG_GROUP_SLOTS_GLSL
#define SG_GROUP_SLOTS_GLSL

#include "light_groups.glsl"

#ifdef GROUP_SLOTS
// constant_id 6: the groups in order, four bits each (systems/shadows/light_groups.h,
// group_slot_list).
layout(constant_id = 6) const uint GROUP_SLOT_LIST = 0u;
uint slot_group(uint slot) { return (GROUP_SLOT_LIST >> (4u * slot)) & 0xFu; }
#else
#define GROUP_SLOTS 11  // LIGHT_GROUP_COUNT, each group in its own slot
uint slot_group(uint slot) { return slot; }
#endif

#if GROUP_SLOTS == 1
#define FOR_EACH_GROUP_SLOT(CALL) CALL(0u)
#elif GROUP_SLOTS == 2
#define FOR_EACH_GROUP_SLOT(CALL) CALL(0u) CALL(1u)
#elif GROUP_SLOTS == 3
#define FOR_EACH_GROUP_SLOT(CALL) CALL(0u) CALL(1u) CALL(2u)
#elif GROUP_SLOTS == 4
#define FOR_EACH_GROUP_SLOT(CALL) CALL(0u) CALL(1u) CALL(2u) CALL(3u)
#elif GROUP_SLOTS == 11
#define FOR_EACH_GROUP_SLOT(CALL) \
  CALL(0u) CALL(1u) CALL(2u) CALL(3u) CALL(4u) CALL(5u) CALL(6u) CALL(7u) CALL(8u) CALL(9u) CALL(10u)
#else
#error GROUP_SLOTS must be 1 to 4 or 11
#endif

#endif
