// The priority compiler (issue 31): the seeds' raster engines decide visibility by list order
// (priority), so a subobject's polygon list must be an order in which no polygon can hide one
// listed before it, from every eye position. A modeller's list is such an order for convex parts
// and for hand-ordered decals (runway markings before the runway); a general mesh (any model
// read through assimp) is not. Such subobjects are compiled at scene load into a tree
// (Subobject::bsp): the strongly connected components of "may hide" in a visibility order, and for
// each cycle a binary space partition by one of its polygons' planes, splitting the polygons that
// straddle it. Stage B walks the tree per view (walk_priority_tree, geometry/geometric_processor.hpp),
// which gives a visibility order. Objects that interpenetrate a model are merged into one object
// with one tree (an occlusion group of seed 000 whose parts no order by distance can draw).
//
// Which subobjects: a model's ("priority_order": "tree", the default for "model") when its order
// is not valid; an inline list ("modeller", its default) is kept and, when not valid, counted.
// A subobject is left alone when its order is already valid: for every pair i listed before j,
// either j lies wholly behind-or-on i's plane or i lies wholly in-front-or-on j's plane (then j
// can never come between the eye and i, whatever the eye). So no split happens where none is needed.
//
// Compiled trees are cached by content hash (the subobject's vertices and polygons and the
// compiler's version) in a directory of files this compiler alone writes, so a second load is a read.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>

#include "scene/scene.hpp"

namespace cig {

struct PriorityCompilerOptions {
  bool enabled = true;
  std::string cache_dir;  // "" : no cache
  // A subobject whose splitting would grow it beyond this factor (plus split_allowance polygons)
  // keeps its modeller's order and is counted as not compiled.
  double max_growth = 8;
  std::size_t split_allowance = 1024;
};

// Default cache directory: $XDG_CACHE_HOME/cig/priority, or $HOME/.cache/cig/priority, or "" (none).
std::string default_priority_cache_dir();

// Compiles every subobject that needs it, in place (polygons reordered and split, vertices added,
// model_faces kept in step). Convex polyhedra (stage F's objects) are never touched.
PriorityCompileSummary compile_priorities(Scene& scene, const PriorityCompilerOptions& options);

// True when the subobject's list is a visibility order from every eye position (the pair test above).
bool modeller_order_valid(const Subobject& s);

}  // namespace cig
