// Records of the segment processor (SPEC D, seed 001): what flows between its kernels and what
// its memories hold. Every field has its width here; the kernels use only these records, the
// formatter's (hls/formatter/records.hpp) and the type layer.
//
//   FormattedPrimitive (hls/formatter: eq. 1, X, Y 12 bits, I 8, D 3, Z e8m7)
//     edge_generator_top   -> PolygonEdges         (left/right chains, slopes eq. 2, area eq. 5-6,
//                                                   area code, segment counts per field)
//     frame memory (2 banks x 16K words; headers and edges)     overload threshold (eq. 6 codes)
//     segment_generator_top-> Segment per raster line (4 X values, type, I and Z at the ends,
//                                                   eq. 3-4)
//     light_segments_top   -> Segment per sample row of a light point (coding table)
//     y_sorter_top         -> per-line linked lists in segment memory (2 banks x 48K: even and
//                             odd lines), head pointers, counts
//     video_channel_top    -> pixels of one line (I and Z along the segment, colour x I, fog by
//                             Z, priority, 4 x 4 sub-pixel coverage)
//
// Geometry: the formatter grid and the sample lattice of hls/formatter/sample_lattice.hpp (grid
// units X, Y in 0..4095; with S = 2^t samples a side per pixel, raster line L holds the S sample
// rows SL + r, r = 0..S-1; positions in half units, exact for lattices of 64..4096 rows; the
// seeds' S = 4 is the default).
#pragma once

#include "hls/formatter/records.hpp"

CIG_HLS_BEGIN_NAMESPACE

constexpr int kRowsPerLine = kSamplesPerSide;        // sample rows per raster line, default lattice
constexpr int kMaxRowsPerLine = kMaxSamplesPerSide;  // ... on the finest lattice (8 x 8 per pixel)
constexpr int kMaxEdgesPerChain = kMaxVertices;      // a chain can hold every edge of the polygon

// ---- Edge generator output / frame memory contents ----------------------------------------------
// One edge of a left or right chain, as the preprocessor needs it: the sample rows it spans, its
// endpoints (for I and Z by eq. 3-4), the slope of eq. 2 per sample row and its first crossing.
template <class P>
struct Edge {
  int row_first = 0, row_last = -1;  // global sample rows whose Y lies in [y_begin, y_end) (< 4096)
  typename P::Coord x_begin, y_begin, x_end, y_end;
  typename P::VertexIntensity i_begin, i_end;
  typename P::Depth z_begin, z_end;
  typename P::Slope dx_per_row;  // eq. 2 times the sample-row spacing
  typename P::Slope x_first;     // X at row_first (the preprocessor's first crossing), in the
                                 // slope's format: it loads the stepping accumulator
};

// Area codes of eq. 6: 0 protected, 1 (largest) .. 15 (smallest).
constexpr int kAreaCodes = 16;

// The polygon header word of the frame memory.
template <class P>
struct PolygonHeader {
  UInt<16> id;
  typename P::Level colour[3];
  bool opaque = true, protect = false;
  UInt<4> area_code;
  typename P::Area twice_area;           // eq. 6 without the 1/2, grid units^2; sign = orientation
  int row_first = 0, row_last = -1;      // sample rows covered by the polygon
  UInt<11> segments_even, segments_odd;  // raster lines crossed, by field (for overload)
  UInt<5> left_count, right_count;
  typename P::Planes planes;  // I and W = 1/Z (perspective-correct mode; travels with the header)
};

template <class P>
struct PolygonEdges {
  bool valid = false;  // false: no sample row crosses it (degenerate): dropped
  PolygonHeader<P> h;
  Edge<P> left[kMaxEdgesPerChain];  // top to bottom
  Edge<P> right[kMaxEdgesPerChain];
};

// Frame-memory words a polygon takes: one header plus one per stored edge.
template <class P>
inline int frame_memory_words(const PolygonEdges<P>& e) {
  return 1 + int(e.h.left_count.value()) + int(e.h.right_count.value());
}

// ---- Segments ---------------------------------------------------------------------------------
// Segment types of the seed (Fig. 3), used by the anti-aliasing filter.
constexpr unsigned kSegTop = 1, kSegBottom = 2, kSegMiddle = 3, kSegWhole = 4;

template <class P>
struct Segment {
  UInt<10> line;                // raster line 0..N-1
  UInt<3> type;                 // kSegTop .. kSegWhole
  UInt<3> row_first, row_last;  // covered sample rows within the line (0..S-1)
  // Left and right X at each of the line's S sample rows (rows outside row_first..row_last
  // unused). The seed's segment carries four X values (left and right at the top and bottom of
  // the line) and interpolates between them; where a chain vertex lies inside the line that
  // misplaces the middle rows and opens cracks between neighbouring polygons, so the rows are
  // stored exactly (SegmentOptions::seed_quadrilateral restores the seed's interpolation).
  typename P::X xl[kMaxRowsPerLine], xr[kMaxRowsPerLine];
  typename P::Intensity il, ir;  // eq. 3 at the ends, at the covered rows' centre
  typename P::Depth zl, zr;      // eq. 4 at the ends
  UInt<16> source;               // polygon id, or light id when is_light
  bool is_light = false;
  bool opaque = true;
  UInt<3> channel;
};

CIG_HLS_END_NAMESPACE
