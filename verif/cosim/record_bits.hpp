// Bit-level records of the quadtree RTL (rtl/README.md, "Records"): the C++ kernels' QuadWindow
// packed LSB first exactly as the RTL carries it, so that the co-simulation compares the RTL's
// records with the model's bit for bit, and reports a mismatch field by field.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "hls/quadtree/records.hpp"

namespace cig::cosim {

// An LSB-first bit vector in 32-bit words (the layout of Verilator's VlWide).
class Bits {
 public:
  Bits() = default;
  explicit Bits(int width) : width_(width), w_(std::size_t((width + 31) / 32), 0u) {}
  int width() const { return width_; }
  const std::uint32_t* words() const { return w_.data(); }
  std::uint32_t* words() { return w_.data(); }
  std::size_t word_count() const { return w_.size(); }

  void put(int lo, int width, std::uint64_t v) {
    for (int b = 0; b < width; ++b) {
      const int i = lo + b;
      const std::uint32_t m = 1u << (i & 31);
      if ((v >> b) & 1u) w_[std::size_t(i >> 5)] |= m;
      else w_[std::size_t(i >> 5)] &= ~m;
    }
  }
  std::uint64_t get(int lo, int width) const {
    std::uint64_t v = 0;
    for (int b = 0; b < width; ++b) {
      const int i = lo + b;
      v |= std::uint64_t((w_[std::size_t(i >> 5)] >> (i & 31)) & 1u) << b;
    }
    return v;
  }
  std::int64_t get_signed(int lo, int width) const {
    const std::uint64_t v = get(lo, width);
    return width >= 64 ? std::int64_t(v) : std::int64_t(v << (64 - width)) >> (64 - width);
  }
  // Copies `width` bits starting at bit `lo` of raw LSB-first words (a Verilator port).
  void load(const std::uint32_t* words, int lo, int width) {
    *this = Bits(width);
    for (int b = 0; b < width; ++b) {
      const int i = lo + b;
      if ((words[i >> 5] >> (i & 31)) & 1u) w_[std::size_t(b >> 5)] |= 1u << (b & 31);
    }
  }
  bool operator==(const Bits& o) const { return width_ == o.width_ && w_ == o.w_; }
  bool operator!=(const Bits& o) const { return !(*this == o); }

 private:
  int width_ = 0;
  std::vector<std::uint32_t> w_;
};

// Field layout of a pixel-record-wide item (rtl/README.md).
struct RecordLayout {
  int ne = hls::kQuadMaxEdges, np = hls::kQuadParams, ew = 32, aw = 22, pw = 0, gw = 0;
  struct Field {
    std::string name;
    int lo, width;
    bool is_signed;
  };
  std::vector<Field> fields;
  int win_w = 0, pix_w = 0;

  RecordLayout(int param_width, int gradient_width) : pw(param_width), gw(gradient_width) {
    int at = 0;
    auto add = [&](const std::string& n, int w, bool s) {
      fields.push_back({n, at, w, s});
      at += w;
    };
    add("level", 4, false);
    add("x", 10, false);
    add("y", 10, false);
    for (int e = 0; e < ne; ++e) add("d[" + std::to_string(e) + "]", ew, true);
    for (int p = 0; p < np; ++p) add("f[" + std::to_string(p) + "]", pw, true);
    add("poly.id", 16, false);
    add("poly.opaque", 1, false);
    for (int c = 0; c < 3; ++c) add("poly.colour[" + std::to_string(c) + "]", 8, false);
    add("poly.edge_count", 4, false);
    for (int e = 0; e < ne; ++e) add("poly.a[" + std::to_string(e) + "]", aw, true);
    for (int e = 0; e < ne; ++e) add("poly.b[" + std::to_string(e) + "]", aw, true);
    for (int p = 0; p < np; ++p) add("poly.dp_di[" + std::to_string(p) + "]", gw, true);
    for (int p = 0; p < np; ++p) add("poly.dp_dj[" + std::to_string(p) + "]", gw, true);
    add("poly.w_exponent", 10, true);
    win_w = at;
    add("samples", 16, false);
    pix_w = at;
  }
};

// Packs a window (and, for pixel records, its samples) into a PIX_W-bit record.
template <class P>
Bits pack_record(const RecordLayout& L, const hls::QuadWindow<P>& w, unsigned samples) {
  Bits b(L.pix_w);
  std::size_t f = 0;
  auto put = [&](std::uint64_t v) {
    const auto& fd = L.fields[f++];
    b.put(fd.lo, fd.width, v);
  };
  put(w.level.value());
  put(w.x.value());
  put(w.y.value());
  for (int e = 0; e < L.ne; ++e) put(std::uint64_t(w.d[e].value()));
  for (int p = 0; p < L.np; ++p) put(std::uint64_t(w.f[p].value()));
  put(w.poly.id.value());
  put(w.poly.opaque ? 1u : 0u);
  for (int c = 0; c < 3; ++c) put(w.poly.colour[c].value());
  put(w.poly.edge_count.value());
  for (int e = 0; e < L.ne; ++e) put(std::uint64_t(w.poly.a[e].value()));
  for (int e = 0; e < L.ne; ++e) put(std::uint64_t(w.poly.b[e].value()));
  for (int p = 0; p < L.np; ++p) put(std::uint64_t(w.poly.dp_di[p].value()));
  for (int p = 0; p < L.np; ++p) put(std::uint64_t(w.poly.dp_dj[p].value()));
  put(std::uint64_t(w.poly.w_exponent.value()));
  put(samples);
  return b;
}

// The first field in which two records differ: "name: expected E, got G" ("" when equal).
inline std::string first_field_difference(const RecordLayout& L, const Bits& expected, const Bits& got) {
  for (const auto& fd : L.fields) {
    const std::int64_t e =
        fd.is_signed ? expected.get_signed(fd.lo, fd.width) : std::int64_t(expected.get(fd.lo, fd.width));
    const std::int64_t g = fd.is_signed ? got.get_signed(fd.lo, fd.width) : std::int64_t(got.get(fd.lo, fd.width));
    if (e != g) return fd.name + ": expected " + std::to_string(e) + ", got " + std::to_string(g);
  }
  return "";
}

// A short description of a record: level, address, polygon.
inline std::string describe_record(const RecordLayout& L, const Bits& r) {
  return "level " + std::to_string(r.get(L.fields[0].lo, 4)) + " window (" + std::to_string(r.get(L.fields[1].lo, 10)) +
         ", " + std::to_string(r.get(L.fields[2].lo, 10)) + ") of polygon " +
         std::to_string(r.get(L.fields[std::size_t(3 + L.ne + L.np)].lo, 16));
}

}  // namespace cig::cosim
