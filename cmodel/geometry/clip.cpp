#include "geometry/clip.hpp"

namespace cig {

// Counted as it runs (seed 000's units): per edge, the plane distances of both ends (the code
// evaluates each end's a x + b y + c z + d: 2 x (3 M + 3 A)) and 2 C (is the first end inside? does
// the edge cross?); per vertex kept, 4 L (eye, intensity written); per intersection, s = din /
// (din - dout) (1 A, 1 D), eye = in + s (ou - in) (3 A, 3 M, 3 A) and the intensity likewise (2 A,
// 1 M), 4 L written; per plane, 1 C (3 vertices left?). The capacity guard is the model's, not the
// machine's, and the copy back (p = out) a buffer swap: neither is counted.
bool clip_polygon(ClipPolygon& p, const ClipPlane& plane, ClipCount& count) {
  ClipPolygon out;
  OperationCounts ops;  // local: plain adds in the loop, one += at the end
  std::uint64_t intersections = 0;
  for (int i = 0; i < p.n; ++i) {
    const ClipVertex& a = p.v[i];
    const ClipVertex& b = p.v[(i + 1) % p.n];
    const double da = plane.distance(a.eye);
    const double db = plane.distance(b.eye);
    ops.M += 6;  // two distances, 3 M + 3 A each
    ops.A += 6;
    ops.C += 2;  // da >= 0; (da >= 0) != (db >= 0)
    // The capacity guard only matters for rounding noise on nearly collinear vertices: a convex
    // polygon crosses a plane at most twice, gaining at most one vertex.
    if (da >= 0 && out.n < kMaxScreenVertices) {
      out.v[out.n++] = a;
      ops.L += 4;  // eye (3) and intensity written
    }
    if ((da >= 0) != (db >= 0) && out.n < kMaxScreenVertices) {
      const ClipVertex& in = da >= 0 ? a : b;
      const ClipVertex& ou = da >= 0 ? b : a;
      const double din = da >= 0 ? da : db;
      const double dout = da >= 0 ? db : da;
      const double s = din / (din - dout);
      ClipVertex c;
      c.eye = in.eye + s * (ou.eye - in.eye);
      c.intensity = in.intensity + s * (ou.intensity - in.intensity);
      out.v[out.n++] = c;
      ++intersections;
      ops.A += 1 + 6 + 2;  // din - dout; eye: 3 A (ou - in) + 3 A (in + ...); intensity: 2 A
      ops.M += 3 + 1;      // s times the eye difference (3 M) and the intensity difference (1 M)
      ops.D += 1;          // s
      ops.L += 4;          // the new vertex written
    }
  }
  ops.C += 1;  // p.n >= 3
  count.ops += ops;
  count.intersections += intersections;
  p = out;
  return p.n >= 3;
}

bool clip_polygon(ClipPolygon& p, const ClipPlane& plane) {
  ClipCount ignored;
  return clip_polygon(p, plane, ignored);
}

bool clip_polygon(ClipPolygon& p, const ViewPyramid& pyramid, std::uint8_t planes, ClipCount& count) {
  for (int k = 0; k < kClipPlanes; ++k) {
    ++count.ops.C;  // the outcode's bit k tested
    if ((planes >> k) & 1u)
      if (!clip_polygon(p, pyramid.plane[k], count)) return false;
  }
  return true;
}

bool clip_polygon(ClipPolygon& p, const ViewPyramid& pyramid, std::uint8_t planes) {
  ClipCount ignored;
  return clip_polygon(p, pyramid, planes, ignored);
}

}  // namespace cig
