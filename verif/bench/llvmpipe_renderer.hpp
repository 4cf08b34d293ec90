// The peer of the cig raster engines in bench_llvmpipe: Mesa's llvmpipe (a software rasteriser that
// JIT-compiles its shaders with LLVM) through OSMesa, doing the work the engines do on the same
// screen polygon list (ScreenFrame), so that their CPU times compare:
//   * S x S samples per pixel (16 by default, as the engines): the list drawn at SN x SN without
//     MSAA, the samples at the centres of the big image's pixels, which are exactly the formatter's
//     sample lattice (reference/sample_lattice.hpp: sample i at (SN/2)(Xs + 1) - 1/2);
//   * clip coordinates (Xs Zs, -Ys Zs, c, Zs) with glClipControl(ZERO_TO_ONE): the depth buffer
//     (32-bit float) holds c/Zs, the reference's w = 1/Zs scaled, perspective-correct; reversed
//     (nearer is larger, GL_GREATER; lights GL_GEQUAL) because float depth is finest near 0, where
//     the far surfaces are; ties go to the polygon drawn first, which is the list's priority order;
//   * Gouraud: colour x Is, `noperspective` (the seed interpolates in screen space);
//   * fog per fragment, the reference's linear factor on the eye depth Zs = 1/gl_FragCoord.w;
//   * polygons as GL_TRIANGLE_FAN in list order; non-opaque ones through a second program with the
//     reference's screen-door checkerboard; light points as GL_POINTS cut to the reference's discs;
//   * glReadPixels and an S x S box filter to N x N on the CPU.
// Differences from the reference that remain: llvmpipe's float setup (depth ties of coplanar
// polygons are not exact, so decals may fight), per-sample 8-bit colour before the box filter, and
// light points depth-tested per sample instead of visible or hidden as a whole.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "frame/screen_frame.hpp"
#include "image/image.hpp"

struct osmesa_context;  // <GL/osmesa.h>, kept out of the users of this header

namespace cig::bench {

class LlvmpipeRenderer {
 public:
  // Creates the OSMesa context (a GL 3.3+ compatibility profile) and compiles the programs. Set
  // LP_NUM_THREADS=0 before the first OSMesa call to keep llvmpipe on the calling thread.
  LlvmpipeRenderer();
  ~LlvmpipeRenderer();
  LlvmpipeRenderer(const LlvmpipeRenderer&) = delete;
  LlvmpipeRenderer& operator=(const LlvmpipeRenderer&) = delete;

  // All of it: vertices, draw, read back, box filter; `side` S samples a pixel side (1, 2, 4, 8).
  Image render(const ScreenFrame& frame, int side = 4);
  std::string version() const;  // GL_RENDERER and GL_VERSION

 private:
  struct Run {  // consecutive polygons of one opacity: one glMultiDrawArrays
    bool opaque;
    std::size_t first, count;
  };
  void resize(int samples);  // the framebuffer object, SN x SN
  void build_vertices(const ScreenFrame& frame);
  void set_uniforms(unsigned program, const ScreenFrame& frame) const;
  void draw_polygons(const ScreenFrame& frame);
  void draw_lights(const ScreenFrame& frame);
  Image resolve(int n, int side);

  osmesa_context* context_ = nullptr;
  std::vector<std::uint8_t> context_buffer_;  // OSMesa's own framebuffer (unused: we draw to the FBO)
  unsigned opaque_program_ = 0, screen_door_program_ = 0, light_program_ = 0;
  unsigned vertex_array_ = 0, polygon_buffer_ = 0, light_buffer_ = 0;
  unsigned fbo_ = 0, colour_rb_ = 0, depth_rb_ = 0;
  int samples_ = 0;        // SN
  float depth_scale_ = 1;  // c: the depth buffer holds c/Zs, at most 1
  // Per frame, reused: vertex attributes, the fans' firsts and counts, the read-back samples.
  std::vector<float> polygon_vertices_, light_vertices_;
  std::vector<int> fan_first_, fan_count_;
  std::vector<Run> runs_;
  std::vector<std::uint8_t> samples_rgba_;
};

}  // namespace cig::bench
