// What the priority engines share to render N parts of one list (RasterEngine::render_parts):
// each part on its own pipeline instance and worker thread, and the parts' polygon offsets in the
// whole list.
#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include <nlohmann/json.hpp>

#include "common/parallel.hpp"
#include "common/timing.hpp"
#include "frame/screen_frame.hpp"

namespace cig {

// offsets[k]: the polygons before part k.
inline std::vector<std::int32_t> part_offsets(const std::vector<const ScreenFrame*>& parts) {
  std::vector<std::int32_t> offsets;
  std::int32_t offset = 0;
  for (const ScreenFrame* part : parts) {
    offsets.push_back(offset);
    offset += std::int32_t(part->polygons.size());
  }
  return offsets;
}

// pipes[k]->rasterise_part(*parts[k]) for every part, one worker thread each (pipes grown with
// make() as needed); the pipelines' reports in part order, and their wall time in report["pipelines_ms"].
template <class Pipe, class Make>
void rasterise_parts(std::vector<std::unique_ptr<Pipe>>& pipes, const std::vector<const ScreenFrame*>& parts,
                     Make&& make, nlohmann::ordered_json& report) {
  while (pipes.size() < parts.size()) pipes.push_back(make());
  nlohmann::ordered_json per_part = nlohmann::ordered_json::array();
  for (std::size_t k = 0; k < parts.size(); ++k) per_part.push_back(nullptr);
  const auto t0 = Clock::now();
  parallel_for(parts.size(), int(parts.size()),
               [&](std::size_t k, int) { per_part[k] = pipes[k]->rasterise_part(*parts[k]); });
  report["pipelines"] = std::move(per_part);
  report["pipelines_ms"] = ms_since(t0);
}

}  // namespace cig
