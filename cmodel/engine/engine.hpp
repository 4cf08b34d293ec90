// Raster engines behind one interface, so that the CLI and the verification harness drive any of
// them the same way: "float" (the reference), later "segment" (formatter + segment processor),
// "quadtree" (recursive subdivision) and "invparam" (inverse-parameter systolic array).
#pragma once

#include <map>
#include <memory>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "frame/screen_frame.hpp"
#include "reference/reference_raster.hpp"

namespace cig {

struct EngineOptions {
  bool snap = false;  // snap positions to the formatter grid first (float engine)
  std::map<std::string, std::string> params;  // engine-specific settings (--engine-opt KEY=VALUE)
};

struct EngineRun {
  RasterImage out;
  nlohmann::ordered_json report;  // what the engine did and took, per stage
};

class RasterEngine {
 public:
  virtual ~RasterEngine() = default;
  virtual const char* name() const = 0;
  virtual EngineRun render(const ScreenFrame& frame) = 0;
  // Checks the engine's options against a raster size before any work (InputError).
  virtual void check_raster(int /*raster*/) const {}
};

// Throws InputError (naming the option) for an unknown engine or an option it does not accept.
std::unique_ptr<RasterEngine> make_engine(const std::string& name, const EngineOptions& options);
std::vector<std::string> engine_names();

}  // namespace cig
