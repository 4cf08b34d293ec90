#define GL_GLEXT_PROTOTYPES 1  // libOSMesa exports the GL 2+ entry points itself
#include "llvmpipe_renderer.hpp"

#include <GL/gl.h>
#include <GL/glext.h>
#include <GL/osmesa.h>

#include <algorithm>
#include <limits>
#include <stdexcept>
#include <string>

namespace cig::bench {

namespace {

// Polygons: position (Xs, Ys, Zs) and colour x Is. Clip w = Zs makes gl_FragCoord.w = 1/Zs.
const char* const kPolygonVertexShader = R"(
layout(location = 0) in vec3 position;
layout(location = 1) in vec3 colour;
uniform float depth_scale;
noperspective out vec3 shade;
void main() {
  gl_Position = vec4(position.x * position.z, -position.y * position.z, depth_scale, position.z);
  shade = colour;
}
)";

// Light points: a point sprite covering the disc, cut to it in the fragment shader.
const char* const kLightVertexShader = R"(
layout(location = 0) in vec3 position;
layout(location = 1) in vec3 colour;
layout(location = 2) in float radius;  // in samples
uniform float depth_scale;
uniform float half_size;  // 2N: window units per Xs unit
flat out vec3 shade;
flat out vec2 centre;
flat out float radius2;
void main() {
  gl_Position = vec4(position.x * position.z, -position.y * position.z, depth_scale, position.z);
  gl_PointSize = 2.0 * ceil(radius) + 2.0;
  centre = vec2(position.x + 1.0, 1.0 - position.y) * half_size;
  radius2 = radius * radius;
  shade = colour;
}
)";

// The fog of the reference (reference_raster.cpp: fog_factor) on the eye depth Zs.
const char* const kFragmentShader = R"(
#ifdef LIGHT
flat in vec3 shade;
flat in vec2 centre;
flat in float radius2;
#else
noperspective in vec3 shade;
#endif
uniform vec3 fog_colour;
uniform float fog_start, fog_scale;
out vec4 frag;
void main() {
#ifdef LIGHT
  vec2 d = gl_FragCoord.xy - centre;
  if (dot(d, d) > radius2) discard;
#endif
#ifdef SCREEN_DOOR
  // The reference keeps sample (i, j) when i + j is even; j = SN - 1 - row (rows run bottom up;
  // SN even: i + j is even when x + row is odd).
  if (((int(gl_FragCoord.x) + int(gl_FragCoord.y)) & 1) == 0) discard;
#endif
  float f = clamp((1.0 / gl_FragCoord.w - fog_start) * fog_scale, 0.0, 1.0);
  frag = vec4(mix(shade, fog_colour, f), 1.0);
}
)";

unsigned compile(GLenum kind, const std::string& defines, const char* body) {
  const std::string text = "#version 330 core\n" + defines + body;
  const char* source = text.c_str();
  const GLuint shader = glCreateShader(kind);
  glShaderSource(shader, 1, &source, nullptr);
  glCompileShader(shader);
  GLint ok = 0;
  glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
  if (!ok) {
    char log[2048];
    glGetShaderInfoLog(shader, sizeof log, nullptr, log);
    throw std::runtime_error(std::string("llvmpipe: shader: ") + log);
  }
  return shader;
}

unsigned link(const std::string& defines, const char* vertex_body) {
  const GLuint program = glCreateProgram();
  const GLuint vs = compile(GL_VERTEX_SHADER, defines, vertex_body);
  const GLuint fs = compile(GL_FRAGMENT_SHADER, defines, kFragmentShader);
  glAttachShader(program, vs);
  glAttachShader(program, fs);
  glLinkProgram(program);
  glDeleteShader(vs);
  glDeleteShader(fs);
  GLint ok = 0;
  glGetProgramiv(program, GL_LINK_STATUS, &ok);
  if (!ok) throw std::runtime_error("llvmpipe: program does not link");
  return program;
}

void push_rgb(std::vector<float>& out, const Rgb& c, double scale) {
  out.push_back(float(c.r * scale));
  out.push_back(float(c.g * scale));
  out.push_back(float(c.b * scale));
}

}  // namespace

LlvmpipeRenderer::LlvmpipeRenderer() {
  const int attribs[] = {OSMESA_FORMAT,
                         OSMESA_RGBA,
                         OSMESA_DEPTH_BITS,
                         0,
                         OSMESA_PROFILE,
                         OSMESA_COMPAT_PROFILE,
                         OSMESA_CONTEXT_MAJOR_VERSION,
                         3,
                         OSMESA_CONTEXT_MINOR_VERSION,
                         3,
                         0};
  context_ = OSMesaCreateContextAttribs(attribs, nullptr);
  if (!context_) throw std::runtime_error("llvmpipe: no OSMesa GL 3.3 context");
  context_buffer_.assign(16 * 16 * 4, 0);
  if (!OSMesaMakeCurrent(context_, context_buffer_.data(), GL_UNSIGNED_BYTE, 16, 16))
    throw std::runtime_error("llvmpipe: OSMesaMakeCurrent failed");
  opaque_program_ = link("", kPolygonVertexShader);
  screen_door_program_ = link("#define SCREEN_DOOR\n", kPolygonVertexShader);
  light_program_ = link("#define LIGHT\n", kLightVertexShader);
  glGenVertexArrays(1, &vertex_array_);
  glBindVertexArray(vertex_array_);
  glGenBuffers(1, &polygon_buffer_);
  glGenBuffers(1, &light_buffer_);
  // GL 4.5, which libOSMesa does not export: window depth = c/Zs, no remapping to [-1, 1].
  const auto clip_control = reinterpret_cast<PFNGLCLIPCONTROLPROC>(OSMesaGetProcAddress("glClipControl"));
  if (!clip_control) throw std::runtime_error("llvmpipe: no glClipControl");
  clip_control(GL_LOWER_LEFT, GL_ZERO_TO_ONE);
  glEnable(GL_DEPTH_TEST);
  glEnable(GL_PROGRAM_POINT_SIZE);
  glClearDepth(0.0);  // reversed depth: 0 is infinitely far
}

LlvmpipeRenderer::~LlvmpipeRenderer() {
  if (!context_) return;
  glDeleteFramebuffers(1, &fbo_);
  glDeleteRenderbuffers(1, &colour_rb_);
  glDeleteRenderbuffers(1, &depth_rb_);
  glDeleteBuffers(1, &polygon_buffer_);
  glDeleteBuffers(1, &light_buffer_);
  glDeleteVertexArrays(1, &vertex_array_);
  glDeleteProgram(opaque_program_);
  glDeleteProgram(screen_door_program_);
  glDeleteProgram(light_program_);
  OSMesaDestroyContext(context_);
}

void LlvmpipeRenderer::resize(int samples) {
  if (samples == samples_) return;
  if (fbo_ == 0) {
    glGenFramebuffers(1, &fbo_);
    glGenRenderbuffers(1, &colour_rb_);
    glGenRenderbuffers(1, &depth_rb_);
  }
  glBindRenderbuffer(GL_RENDERBUFFER, colour_rb_);
  glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, samples, samples);
  glBindRenderbuffer(GL_RENDERBUFFER, depth_rb_);
  glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT32F, samples, samples);
  glBindFramebuffer(GL_FRAMEBUFFER, fbo_);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, colour_rb_);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depth_rb_);
  if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
    throw std::runtime_error("llvmpipe: framebuffer incomplete");
  glViewport(0, 0, samples, samples);
  samples_ = samples;
  samples_rgba_.resize(std::size_t(samples) * std::size_t(samples) * 4);
}

// Vertex attributes, the fans and the opacity runs; the depth scale c = the nearest Zs, so that
// c/Zs lies in (0, 1] and no vertex is clipped by the near plane.
void LlvmpipeRenderer::build_vertices(const ScreenFrame& frame) {
  polygon_vertices_.clear();
  light_vertices_.clear();
  fan_first_.clear();
  fan_count_.clear();
  runs_.clear();
  double nearest = std::numeric_limits<double>::max();
  for (const ScreenPolygon& p : frame.polygons) {
    if (runs_.empty() || runs_.back().opaque != p.opaque) runs_.push_back({p.opaque, fan_first_.size(), 0});
    ++runs_.back().count;
    fan_first_.push_back(int(polygon_vertices_.size() / 6));
    fan_count_.push_back(int(p.vertices.size()));
    for (const ScreenVertex& v : p.vertices) {
      polygon_vertices_.insert(polygon_vertices_.end(), {float(v.xs), float(v.ys), float(v.zs)});
      push_rgb(polygon_vertices_, p.colour, std::clamp(v.is, 0.0, 1.0));
      nearest = std::min(nearest, v.zs);
    }
  }
  const double radius_scale = samples_ / 4096.0 * 0.5;  // grid units -> sample radius
  for (const ScreenLightPoint& l : frame.light_points) {
    light_vertices_.insert(light_vertices_.end(), {float(l.xs), float(l.ys), float(l.zs)});
    push_rgb(light_vertices_, l.colour, l.intensity);
    light_vertices_.push_back(float(radius_scale * std::min(2048.0 * l.ds, 7.0)));  // reference: light_geometry
    nearest = std::min(nearest, l.zs);
  }
  depth_scale_ = nearest < std::numeric_limits<double>::max() ? float(nearest) : 1.0f;
}

void LlvmpipeRenderer::set_uniforms(unsigned program, const ScreenFrame& frame) const {
  glUseProgram(program);
  const Fog& fog = frame.fog;
  glUniform1f(glGetUniformLocation(program, "depth_scale"), depth_scale_);
  glUniform3f(glGetUniformLocation(program, "fog_colour"), float(fog.colour.r), float(fog.colour.g),
              float(fog.colour.b));
  glUniform1f(glGetUniformLocation(program, "fog_start"), float(fog.start));
  glUniform1f(glGetUniformLocation(program, "fog_scale"), float(1.0 / (fog.end - fog.start)));
  const GLint half_size = glGetUniformLocation(program, "half_size");
  if (half_size >= 0) glUniform1f(half_size, float(samples_) / 2);
}

void LlvmpipeRenderer::draw_polygons(const ScreenFrame& frame) {
  if (fan_first_.empty()) return;
  glBindBuffer(GL_ARRAY_BUFFER, polygon_buffer_);
  glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(polygon_vertices_.size() * sizeof(float)), polygon_vertices_.data(),
               GL_STREAM_DRAW);
  glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, 6 * sizeof(float), nullptr);
  glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, 6 * sizeof(float), reinterpret_cast<void*>(3 * sizeof(float)));
  glEnableVertexAttribArray(0);
  glEnableVertexAttribArray(1);
  glDisableVertexAttribArray(2);
  glDepthFunc(GL_GREATER);  // strict: on a tie the polygon drawn first, earlier in the list, stays
  set_uniforms(opaque_program_, frame);
  set_uniforms(screen_door_program_, frame);
  for (const Run& run : runs_) {
    glUseProgram(run.opaque ? opaque_program_ : screen_door_program_);
    glMultiDrawArrays(GL_TRIANGLE_FAN, &fan_first_[run.first], &fan_count_[run.first], GLsizei(run.count));
  }
}

void LlvmpipeRenderer::draw_lights(const ScreenFrame& frame) {
  if (light_vertices_.empty()) return;
  glBindBuffer(GL_ARRAY_BUFFER, light_buffer_);
  glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(light_vertices_.size() * sizeof(float)), light_vertices_.data(),
               GL_STREAM_DRAW);
  const GLsizei stride = 7 * sizeof(float);
  glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, stride, nullptr);
  glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, stride, reinterpret_cast<void*>(3 * sizeof(float)));
  glVertexAttribPointer(2, 1, GL_FLOAT, GL_FALSE, stride, reinterpret_cast<void*>(6 * sizeof(float)));
  glEnableVertexAttribArray(0);
  glEnableVertexAttribArray(1);
  glEnableVertexAttribArray(2);
  glDepthFunc(GL_GEQUAL);  // the reference draws a light at least as near as the surface
  set_uniforms(light_program_, frame);
  glDrawArrays(GL_POINTS, 0, GLsizei(light_vertices_.size() / 7));
}

// S x S box filter, rounded; GL rows run bottom up, so raster line y reads rows SN - 1 - (Sy + k).
Image LlvmpipeRenderer::resolve(int n, int side) {
  glReadPixels(0, 0, samples_, samples_, GL_RGBA, GL_UNSIGNED_BYTE, samples_rgba_.data());
  Image out(n, n);
  std::vector<unsigned> sum(std::size_t(n) * 3);
  const std::size_t row_bytes = std::size_t(samples_) * 4;
  for (int y = 0; y < n; ++y) {
    std::fill(sum.begin(), sum.end(), 0u);
    for (int k = 0; k < side; ++k) {
      const std::uint8_t* row = &samples_rgba_[std::size_t(samples_ - 1 - (side * y + k)) * row_bytes];
      for (int x = 0; x < n; ++x)
        for (int s = 0; s < side; ++s) {
          const std::uint8_t* p = row + (std::size_t(side * x + s)) * 4;
          sum[3 * x] += p[0];
          sum[3 * x + 1] += p[1];
          sum[3 * x + 2] += p[2];
        }
    }
    std::uint8_t* dst = out.at(0, y);
    const unsigned count = unsigned(side * side);
    for (std::size_t c = 0; c < sum.size(); ++c) dst[c] = std::uint8_t((sum[c] + count / 2) / count);
  }
  return out;
}

std::string LlvmpipeRenderer::version() const {
  return std::string(reinterpret_cast<const char*>(glGetString(GL_RENDERER))) + ", OpenGL " +
         reinterpret_cast<const char*>(glGetString(GL_VERSION));
}

Image LlvmpipeRenderer::render(const ScreenFrame& frame, int side) {
  resize(side * frame.raster);
  build_vertices(frame);
  glBindFramebuffer(GL_FRAMEBUFFER, fbo_);
  glClearColor(float(frame.background.r), float(frame.background.g), float(frame.background.b), 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  draw_polygons(frame);
  draw_lights(frame);
  return resolve(frame.raster, side);
}

}  // namespace cig::bench
