// SPDX-License-Identifier: MIT
#pragma once
// shadowgraph-reference --whole-frame's results as a Markdown summary and as JSON.
#include <cstdio>

#include <nlohmann/json_fwd.hpp>

#include "tools/reference/whole_frame.h"

namespace sg::reference {

// The frame's figures, then one row per reported light, the worst first.
void print_whole_frame(std::FILE* out, const WholeFrameReport& report);

// Keys: device, scene, width, height, frames, gpu_frame_ms, lights, shadowed_lights, lights_without_map,
// soft_samples, edge_band, trace_seconds; frame {misclassified, mae, lit_pixels, pairs,
// band_pairs, frame_pairs, traced_pairs, list_pairs, lighting_list_pairs (null where sampled),
// sampled_fraction, sampled: whether pairs were sampled};
// worst_lights[] (name, type, algorithm, resolution, pairs, weight_share, misclassified, mae,
// frame_misclassified, frame_mae), the worst first.
nlohmann::json to_json(const WholeFrameReport& report);

}  // namespace sg::reference
