// Convex polyhedra for stage F (seed 002, SPEC F): an object that declares "polyhedron": true must
// be a closed, convex, outward-oriented solid whose faces are planes n.r = D. The scene loader
// checks it here once, after reading the object's subobjects, and keeps its face planes.
#pragma once

#include <cstdint>
#include <string>

#include "scene/scene.hpp"

namespace cig {

// Tolerance of the polyhedron rules, relative to the object's size (the diagonal of the bounding
// box of its vertices): a face is planar when every vertex of it lies within kPolyhedronTolerance
// x size of the face's plane, polygons within it of one plane (and facing the same way) are one
// face, and the solid is convex when every vertex lies on the inner side of every face plane or
// within this distance outside it. 1e-6 x a 40 km ground slab is 4 cm; x a 20 m hangar 0.02 mm.
constexpr double kPolyhedronTolerance = 1e-6;

// The rule an object breaks and the polygon it concerns (-1: the object as a whole).
struct PolyhedronIssue {
  std::string rule;
  std::int32_t subobject = -1, polygon = -1;
};

// Checks that the object's polygons (every subobject's, vertices welded by exact position) bound a
// closed convex polyhedron: every edge shared by exactly two polygons in opposite directions, every
// face planar, every edge folding outward and every vertex inside every face plane (within the
// tolerance). A solid that is not convex is reported at the first edge that turns inward (in polygon
// order, then edge order; polyhedron.cpp), naming its two polygons (a model's by mesh and face) and
// its two vertices. Polygons wound inward as a whole are reversed (o.hull.reoriented). Fills o.hull;
// returns an empty rule when valid.
PolyhedronIssue build_polyhedron(Object& o);

}  // namespace cig
