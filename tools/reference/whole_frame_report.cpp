// SPDX-License-Identifier: MIT
#include "tools/reference/whole_frame_report.h"

#include <nlohmann/json.hpp>

namespace sg::reference {

void print_whole_frame(std::FILE* out, const WholeFrameReport& report) {
  const FrameError& e = report.error;
  std::fprintf(
      out,
      "\n%s, %ux%u, scene %s, frame %u (GPU frame %.2f ms before it); %llu lights, %llu shadowed (%llu "
      "without a map)\n",
      report.device.c_str(), report.width, report.height, report.scene.c_str(), report.frames,
      report.gpu_frame_ms, static_cast<unsigned long long>(report.lights),
      static_cast<unsigned long long>(report.shadowed_lights),
      static_cast<unsigned long long>(report.lights_without_map));
  if (report.sampled_fraction < 1.0) {
    std::fprintf(out, "sampled: %.1f%% of the frame's %llu (pixel, light) pairs, drawn at random\n",
                 100.0 * report.sampled_fraction, static_cast<unsigned long long>(report.frame_pairs));
  }
  std::fprintf(out,
               "frame: misclassified %.3f%% of %llu lit pixels, MAE %.4f; %llu pairs compared, %llu in edge "
               "bands (%d px); traced in %.1f s\n\n",
               100.0 * e.misclassified, static_cast<unsigned long long>(e.lit_pixels), e.mae,
               static_cast<unsigned long long>(e.pairs), static_cast<unsigned long long>(e.band_pairs),
               report.edge_band, report.trace_seconds);
  if (report.lighting_list_pairs) {
    std::fprintf(
        out, "light lists: %llu (tile, light) pairs, %llu of them lighting a pixel (%.1f%%)\n\n",
        static_cast<unsigned long long>(report.list_pairs),
        static_cast<unsigned long long>(*report.lighting_list_pairs),
        report.list_pairs ? 100.0 * double(*report.lighting_list_pairs) / double(report.list_pairs) : 0.0);
  } else {
    std::fprintf(out,
                 "light lists: %llu (tile, light) pairs; those lighting a pixel are counted only where "
                 "every pair is traced (raise --pairs-per-pixel)\n\n",
                 static_cast<unsigned long long>(report.list_pairs));
  }
  std::fprintf(
      out,
      "| light | type | algorithm | map | pairs | weight share | misclassified | MAE | adds to frame "
      "misclassified | adds to frame MAE |\n");
  std::fprintf(out, "|---|---|---|---:|---:|---:|---:|---:|---:|---:|\n");
  for (const FrameLightRow& row : report.worst) {
    const LightError& l = row.error;
    std::fprintf(out, "| %s | %s | %s | %u | %llu | %.2f%% | %.2f%% | %.3f | %.3f%% | %.4f |\n",
                 row.name.c_str(), std::string(to_string(row.type)).c_str(), row.algorithm.c_str(),
                 row.resolution, static_cast<unsigned long long>(l.pairs), 100.0 * l.weight_share,
                 100.0 * l.misclassified, l.mae, 100.0 * l.frame_misclassified, l.frame_mae);
  }
}

nlohmann::json to_json(const WholeFrameReport& report) {
  const FrameError& e = report.error;
  nlohmann::json lights = nlohmann::json::array();
  for (const FrameLightRow& row : report.worst) {
    const LightError& l = row.error;
    lights.push_back({{"name", row.name},
                      {"type", to_string(row.type)},
                      {"algorithm", row.algorithm},
                      {"resolution", row.resolution},
                      {"pairs", l.pairs},
                      {"weight_share", l.weight_share},
                      {"misclassified", l.misclassified},
                      {"mae", l.mae},
                      {"frame_misclassified", l.frame_misclassified},
                      {"frame_mae", l.frame_mae}});
  }
  return {{"device", report.device},
          {"scene", report.scene},
          {"width", report.width},
          {"height", report.height},
          {"frames", report.frames},
          {"gpu_frame_ms", report.gpu_frame_ms},
          {"lights", report.lights},
          {"shadowed_lights", report.shadowed_lights},
          {"lights_without_map", report.lights_without_map},
          {"soft_samples", report.soft_samples},
          {"edge_band", report.edge_band},
          {"trace_seconds", report.trace_seconds},
          {"frame",
           {{"misclassified", e.misclassified},
            {"mae", e.mae},
            {"lit_pixels", e.lit_pixels},
            {"pairs", e.pairs},
            {"band_pairs", e.band_pairs},
            {"frame_pairs", report.frame_pairs},
            {"traced_pairs", report.traced_pairs},
            {"list_pairs", report.list_pairs},
            {"lighting_list_pairs",
             report.lighting_list_pairs ? nlohmann::json(*report.lighting_list_pairs) : nlohmann::json()},
            {"sampled_fraction", report.sampled_fraction},
            {"sampled", report.sampled_fraction < 1.0}}},
          {"worst_lights", std::move(lights)}};
}

}  // namespace sg::reference
