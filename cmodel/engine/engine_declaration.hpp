// The engine kit: what one raster engine declares beside its code, its row of `cig engines`: its
// name, what it models, what it draws and models (EngineCapabilities), its factory, its settings
// table (engine_options.hpp) and the counts it may drop. The registry (registry/engine_registry.hpp)
// lists the declarations and decides everything from them, never from an engine's name; a new
// engine is a new declaration and one line in the registry's list.
#pragma once

#include <memory>
#include <vector>

#include "engine/engine.hpp"

namespace cig {

struct EngineCapabilities {
  bool bit_accurate = false;        // the hls/ kernels' words; false: a double model (a twin, the reference)
  bool polygons = false;            // draws the frame's polygons (every engine but stage F's)
  bool polyhedra = false;           // draws the frame's convex polyhedra (stage F)
  bool pipelines = false;           // merges rendering pipelines (--pipelines)
  bool formatter = false;           // has stage C's formatter: subpixel=B sets its grid, --snap does not apply
  bool reference = false;           // the ground truth the commands judge against (--reference); snaps by --snap
  const char* hardware_model = "";  // the RTL it co-simulates with record for record (`cig cosim`), or ""
  const char* twin_of = "";         // the bit-accurate engine whose kernels it runs on double, or ""
};

struct EngineDeclaration {
  const char* name;    // --engine NAME
  const char* models;  // the stage and the seed it models
  EngineCapabilities can;
  std::unique_ptr<RasterEngine> (*make)(const EngineOptions&);
  std::vector<EngineOptionSpec> (*options)();  // its --engine-opt table (subpixel= added by the registry)
  const std::vector<DropKind>& (*drops)();     // the keys of its report's "dropped"
};

// A double twin's capabilities: the bit-accurate engine's, on double arithmetic, without its
// hardware model (the RTL co-simulates with the bit-accurate engine only), naming the engine.
inline EngineCapabilities twin_capabilities(EngineCapabilities fixed, const char* fixed_name) {
  fixed.bit_accurate = false;
  fixed.hardware_model = "";
  fixed.twin_of = fixed_name;
  return fixed;
}

// An engine that can drop nothing.
inline const std::vector<DropKind>& no_drop_kinds() {
  static const std::vector<DropKind> kNone;
  return kNone;
}

}  // namespace cig
