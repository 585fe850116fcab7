// SPDX-License-Identifier: MIT
#pragma once
// shadowgraph-reference's results as a Markdown table and as JSON.
#include <cstdio>
#include <string>

#include <nlohmann/json_fwd.hpp>

#include "tools/reference/run_reference.h"

namespace sg::reference {

// One row per light, algorithm and resolution; then, when measured, one per algorithm's cost.
void print_tables(std::FILE* out, const ReferenceReport& report);

// Keys: device, scene, width, height, soft_samples, edge_band, lights[] (name, type,
// trace_seconds, runs[]: algorithm, requested_resolution, resolution, measured, shadowed,
// outside_band, misclassified, acne, penumbra and outside_penumbra {pixels, mae, rmse}), costs[]
// (algorithm, lighting_ms, shadow_maps_ms, frame_ms, shadowed_lights, lighting_ms_per_light:
// the lighting's extra over "off" per shadowed light).
nlohmann::json to_json(const ReferenceReport& report);
// Writes `json` to `path`, indented; throws std::runtime_error naming the path on failure.
void write_json(const std::string& path, const nlohmann::json& json);

}  // namespace sg::reference
