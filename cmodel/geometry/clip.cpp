#include "geometry/clip.hpp"

namespace cig {

bool clip_polygon(ClipPolygon& p, const ClipPlane& plane) {
  ClipPolygon out;
  for (int i = 0; i < p.n; ++i) {
    const ClipVertex& a = p.v[i];
    const ClipVertex& b = p.v[(i + 1) % p.n];
    const double da = plane.distance(a.eye);
    const double db = plane.distance(b.eye);
    // The capacity guard only matters for rounding noise on nearly collinear vertices: a convex
    // polygon crosses a plane at most twice, gaining at most one vertex.
    if (da >= 0 && out.n < kMaxScreenVertices) out.v[out.n++] = a;
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
    }
  }
  p = out;
  return p.n >= 3;
}

bool clip_polygon(ClipPolygon& p, const ViewPyramid& pyramid, std::uint8_t planes) {
  for (int k = 0; k < kClipPlanes; ++k)
    if ((planes >> k) & 1u)
      if (!clip_polygon(p, pyramid.plane[k])) return false;
  return true;
}

}  // namespace cig
