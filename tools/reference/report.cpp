// SPDX-License-Identifier: MIT
#include "tools/reference/report.h"

#include <fstream>
#include <stdexcept>

#include <nlohmann/json.hpp>

namespace sg::reference {
namespace {

nlohmann::json error_json(const ErrorStats& stats) {
  return {{"pixels", stats.pixels}, {"mae", stats.mean_absolute}, {"rmse", stats.rms}};
}

// The lighting's extra GPU time over no shadows, per shadowed light.
double lighting_per_light(const AlgorithmCost& cost, const ReferenceReport& report) {
  if (report.costs.empty() || cost.cost.shadowed_lights == 0) return 0.0;
  return (cost.cost.lighting_ms - report.costs.front().cost.lighting_ms) / cost.cost.shadowed_lights;
}

}  // namespace

void print_tables(std::FILE* out, const ReferenceReport& report) {
  std::fprintf(out, "\n%s, %ux%u, scene %s; soft reference %u rays a pixel, edge band %d px\n\n",
               report.device.c_str(), report.width, report.height, report.scene.c_str(), report.soft_samples,
               report.edge_band);
  std::fprintf(
      out,
      "| light | type | algorithm | map | misclassified | penumbra MAE | penumbra RMSE | outside MAE | "
      "outside RMSE | acne | pixels |\n");
  std::fprintf(out, "|---|---|---|---:|---:|---:|---:|---:|---:|---:|---:|\n");
  for (const LightReport& light : report.lights) {
    for (const AlgorithmRun& run : light.runs) {
      const ShadowMetrics& m = run.metrics;
      std::fprintf(out, "| %s | %s | %s | %u | %.2f%% | %.3f | %.3f | %.3f | %.3f | %.2f%% | %llu |\n",
                   light.name.c_str(), std::string(to_string(light.type)).c_str(),
                   std::string(to_string(run.algorithm)).c_str(), run.resolution, 100.0 * m.misclassified,
                   m.penumbra.mean_absolute, m.penumbra.rms, m.umbra_and_lit.mean_absolute,
                   m.umbra_and_lit.rms, 100.0 * m.acne, static_cast<unsigned long long>(m.measured));
    }
  }
  if (report.costs.empty()) return;
  std::fprintf(out,
               "\n| algorithm | GPU frame (ms) | shadow maps (ms) | lighting (ms) | lighting per shadowed "
               "light (ms) |\n");
  std::fprintf(out, "|---|---:|---:|---:|---:|\n");
  for (const AlgorithmCost& cost : report.costs) {
    std::fprintf(out, "| %s | %.3f | %.3f | %.3f | %.4f |\n", cost.algorithm.c_str(), cost.cost.frame_ms,
                 cost.cost.shadow_maps_ms, cost.cost.lighting_ms, lighting_per_light(cost, report));
  }
}

nlohmann::json to_json(const ReferenceReport& report) {
  nlohmann::json lights = nlohmann::json::array();
  for (const LightReport& light : report.lights) {
    nlohmann::json runs = nlohmann::json::array();
    for (const AlgorithmRun& run : light.runs) {
      const ShadowMetrics& m = run.metrics;
      runs.push_back({{"algorithm", to_string(run.algorithm)},
                      {"requested_resolution", run.requested_resolution},
                      {"resolution", run.resolution},
                      {"measured", m.measured},
                      {"shadowed", m.shadowed},
                      {"outside_band", m.outside_band},
                      {"misclassified", m.misclassified},
                      {"lit", m.lit},
                      {"acne", m.acne},
                      {"penumbra", error_json(m.penumbra)},
                      {"outside_penumbra", error_json(m.umbra_and_lit)}});
    }
    lights.push_back({{"name", light.name},
                      {"type", to_string(light.type)},
                      {"trace_seconds", light.trace_seconds},
                      {"runs", std::move(runs)}});
  }
  nlohmann::json costs = nlohmann::json::array();
  for (const AlgorithmCost& cost : report.costs) {
    costs.push_back({{"algorithm", cost.algorithm},
                     {"lighting_ms", cost.cost.lighting_ms},
                     {"shadow_maps_ms", cost.cost.shadow_maps_ms},
                     {"frame_ms", cost.cost.frame_ms},
                     {"shadowed_lights", cost.cost.shadowed_lights},
                     {"lighting_ms_per_light", lighting_per_light(cost, report)}});
  }
  return {{"device", report.device},
          {"scene", report.scene},
          {"width", report.width},
          {"height", report.height},
          {"soft_samples", report.soft_samples},
          {"edge_band", report.edge_band},
          {"lights", std::move(lights)},
          {"costs", std::move(costs)},
          {"interrupted", report.interrupted}};
}

void write_json(const std::string& path, const nlohmann::json& json) {
  std::ofstream file(path);
  file << json.dump(2) << '\n';
  if (!file) throw std::runtime_error("cannot write JSON file '" + path + "'");
}

}  // namespace sg::reference
