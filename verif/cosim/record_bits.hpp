// Bit-level records of the quadtree RTL (rtl/quadtree/README.md, "Records"): the C++ kernels'
// QuadWindow packed LSB first exactly as the RTL carries it, so that the co-simulation compares the
// RTL's records with the model's bit for bit, and reports a mismatch field by field.
//
// The layout has one SystemVerilog place, rtl/quadtree/qt_pkg.sv (field numbers F_*, field_count,
// field_elem_w), and one C++ place, RecordFields<P>::visit below: the fields in the same order,
// each named once, its width and signedness taken from the type the hls/ record gives it
// (hls/quadtree/records.hpp), its element count from the member's array extent. Everything else
// here (offsets, packing, comparing, describing) is derived from that list. cosim.RtlLayout.* and
// rtl.RtlWindowFields.* check the two places against the Verilated models.
#pragma once

#include <array>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <tuple>
#include <type_traits>
#include <vector>

#include "hls/quadtree/mask_memory.hpp"
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
  // Copies `width` bits starting at bit `lo` of raw LSB-first words (a Verilator port), a word at
  // a time (the co-simulation reads a record or two every cycle); reads no word past the last bit.
  void load(const std::uint32_t* words, int lo, int width) {
    *this = Bits(width);
    if (width <= 0) return;
    const int base = lo >> 5, shift = lo & 31, last = (lo + width - 1) >> 5;
    for (std::size_t k = 0; k < w_.size(); ++k) {
      const int at = base + int(k);
      std::uint64_t v = words[at] >> shift;
      if (shift != 0 && at + 1 <= last) v |= std::uint64_t(words[at + 1]) << (32 - shift);
      w_[k] = std::uint32_t(v);
    }
    if ((width & 31) != 0) w_.back() &= (1u << (width & 31)) - 1u;
  }
  bool operator==(const Bits& o) const { return width_ == o.width_ && w_ == o.w_; }
  bool operator!=(const Bits& o) const { return !(*this == o); }

 private:
  int width_ = 0;
  std::vector<std::uint32_t> w_;
};

// Width, signedness and raw bits of a record member's type: hls::Int<W>, hls::UInt<W>, or a
// bool flag (1 bit).
template <class T>
struct BitType;
template <int W>
struct BitType<hls::Int<W>> {
  static constexpr int width = W;
  static constexpr bool is_signed = true;
  static std::uint64_t raw(const hls::Int<W>& v) { return std::uint64_t(v.value()); }
};
template <int W>
struct BitType<hls::UInt<W>> {
  static constexpr int width = W;
  static constexpr bool is_signed = false;
  static std::uint64_t raw(const hls::UInt<W>& v) { return v.value(); }
};
template <>
struct BitType<bool> {
  static constexpr int width = 1;
  static constexpr bool is_signed = false;
  static std::uint64_t raw(bool v) { return v ? 1u : 0u; }
};

// The fields of a pixel record in the RTL's order (qt_pkg F_LEVEL .. F_SAMPLES).
enum class RecordField {
  kLevel,
  kX,
  kY,
  kD,
  kF,
  kId,
  kOpaque,
  kColour,
  kEdgeCount,
  kA,
  kB,
  kDpDi,
  kDpDj,
  kWExponent,
  kStartLevel,
  kStartX,
  kStartY,
  kSamples,
  kCount
};

// The field table: a pixel record (a window and its samples; a window record is the same without
// the samples) as the RTL packs it, LSB first.
template <class P>
struct RecordFields {
  using Window = hls::QuadWindow<P>;
  using Samples = hls::UInt<hls::kSamplesPerPixel>;  // the RTL: the seeds' 4 x 4 lattice

  // Calls visit(field, name, member) for every field in order; member is the hls/ value (an
  // array for per-edge, per-parameter and per-channel fields).
  template <class Visit>
  static void visit(const Window& w, const Samples& samples, Visit&& v) {
    v(RecordField::kLevel, "level", w.level);
    v(RecordField::kX, "x", w.x);
    v(RecordField::kY, "y", w.y);
    v(RecordField::kD, "d", w.d);
    v(RecordField::kF, "f", w.f);
    v(RecordField::kId, "poly.id", w.poly.id);
    v(RecordField::kOpaque, "poly.opaque", w.poly.opaque);
    v(RecordField::kColour, "poly.colour", w.poly.colour);
    v(RecordField::kEdgeCount, "poly.edge_count", w.poly.edge_count);
    v(RecordField::kA, "poly.a", w.poly.a);
    v(RecordField::kB, "poly.b", w.poly.b);
    v(RecordField::kDpDi, "poly.dp_di", w.poly.dp_di);
    v(RecordField::kDpDj, "poly.dp_dj", w.poly.dp_dj);
    v(RecordField::kWExponent, "poly.w_exponent", w.poly.w_exponent);
    v(RecordField::kStartLevel, "poly.start_level", w.poly.start_level);
    v(RecordField::kStartX, "poly.start_x", w.poly.start_x);
    v(RecordField::kStartY, "poly.start_y", w.poly.start_y);
    v(RecordField::kSamples, "samples", samples);
  }

  // Elements of a member (1 for a scalar) and their type.
  template <class T>
  static constexpr int count_of = std::is_array_v<T> ? int(std::extent_v<T>) : 1;
  template <class T>
  using element_of = std::remove_cv_t<std::remove_all_extents_t<T>>;
  // Element k's raw bits.
  template <class T>
  static std::uint64_t element_bits(const T& member, int k) {
    if constexpr (std::is_array_v<T>) return BitType<element_of<T>>::raw(member[k]);
    else return BitType<T>::raw(member);
  }
};

// The offsets of the field table: one slot per element, in packing order.
template <class P>
struct RecordLayout {
  using Fields = RecordFields<P>;
  struct Slot {
    RecordField field;
    std::string name;  // "x", "d[3]", "poly.colour[0]", ...
    int lo, width;
    bool is_signed;
  };
  std::vector<Slot> slots;
  std::array<int, std::size_t(RecordField::kCount)> first{};  // a field's first slot
  int win_w = 0, pix_w = 0;

  RecordLayout() {
    int at = 0, next_field = 0;
    const typename Fields::Window w{};
    const typename Fields::Samples s{};
    Fields::visit(w, s, [&](RecordField f, const char* name, const auto& member) {
      using T = std::remove_cv_t<std::remove_reference_t<decltype(member)>>;
      using E = typename Fields::template element_of<T>;
      constexpr int n = Fields::template count_of<T>;
      // field_count() and the RTL's field numbers rely on the visit order being the enum's.
      if (f != RecordField(next_field++))
        throw std::logic_error("RecordFields::visit: fields out of RecordField order");
      first[std::size_t(f)] = int(slots.size());
      if (f == RecordField::kSamples) win_w = at;
      for (int k = 0; k < n; ++k) {
        const std::string label = std::is_array_v<T> ? std::string(name) + "[" + std::to_string(k) + "]" : name;
        slots.push_back({f, label, at, BitType<E>::width, BitType<E>::is_signed});
        at += BitType<E>::width;
      }
    });
    if (next_field != int(RecordField::kCount)) throw std::logic_error("RecordFields::visit: a field is missing");
    pix_w = at;
  }

  const Slot& slot(RecordField f, int element = 0) const { return slots[std::size_t(first[std::size_t(f)] + element)]; }
  // A field's elements, its offset and its width over all its elements.
  int field_count(RecordField f) const {
    const int end = f == RecordField::kSamples ? int(slots.size()) : first[std::size_t(f) + 1];
    return end - first[std::size_t(f)];
  }
  int field_lo(RecordField f) const { return slot(f).lo; }
  int field_width(RecordField f) const {
    const Slot& last = slot(f, field_count(f) - 1);
    return last.lo + last.width - slot(f).lo;
  }
};

// Packs a window (and, for pixel records, its samples) into a PIX_W-bit record.
template <class P>
Bits pack_record(const RecordLayout<P>& L, const hls::QuadWindow<P>& w, unsigned samples) {
  using Fields = RecordFields<P>;
  Bits b(L.pix_w);
  std::size_t slot = 0;
  Fields::visit(w, typename Fields::Samples(samples), [&](RecordField, const char*, const auto& member) {
    using T = std::remove_cv_t<std::remove_reference_t<decltype(member)>>;
    for (int k = 0; k < Fields::template count_of<T>; ++k) {
      const auto& s = L.slots[slot++];
      b.put(s.lo, s.width, Fields::element_bits(member, k));
    }
  });
  return b;
}

template <class P>
std::int64_t slot_value(const typename RecordLayout<P>::Slot& s, const Bits& r) {
  return s.is_signed ? r.get_signed(s.lo, s.width) : std::int64_t(r.get(s.lo, s.width));
}

// The first field in which two records differ: "name: expected E, got G" ("" when equal).
template <class P>
std::string first_field_difference(const RecordLayout<P>& L, const Bits& expected, const Bits& got) {
  for (const auto& s : L.slots) {
    const std::int64_t e = slot_value<P>(s, expected), g = slot_value<P>(s, got);
    if (e != g) return s.name + ": expected " + std::to_string(e) + ", got " + std::to_string(g);
  }
  return "";
}

// A short description of a record: level, address, polygon.
template <class P>
std::string describe_record(const RecordLayout<P>& L, const Bits& r) {
  auto field = [&](RecordField f) { return std::to_string(slot_value<P>(L.slot(f), r)); };
  return "level " + field(RecordField::kLevel) + " window (" + field(RecordField::kX) + ", " + field(RecordField::kY) +
         ") of polygon " + field(RecordField::kId);
}

// A mask set request {level, x, y, child} (qt_pkg::mask_set_t), LSB first: child, y, x, level.
// Its widths are those of the hls mask memory's set request, the arguments of mask_memory_top.
struct MaskSetLayout {
  template <class F>
  struct Arguments;
  template <class R, class... A>
  struct Arguments<R (*)(A...)> {
    using type = std::tuple<std::remove_cv_t<std::remove_reference_t<A>>...>;
  };
  using Request = Arguments<decltype(&hls::mask_memory_top)>::type;  // (memory, level, x, y, child)
  static constexpr int level_w = BitType<std::tuple_element_t<1, Request>>::width;
  static constexpr int x_w = BitType<std::tuple_element_t<2, Request>>::width;
  static constexpr int y_w = BitType<std::tuple_element_t<3, Request>>::width;
  static constexpr int child_w = BitType<std::tuple_element_t<4, Request>>::width;
  static constexpr int child_lo = 0;
  static constexpr int y_lo = child_lo + child_w;
  static constexpr int x_lo = y_lo + y_w;
  static constexpr int level_lo = x_lo + x_w;
  static constexpr int width = level_lo + level_w;  // qt_pkg::MASK_SET_W

  struct Fields {
    int level, x, y, child;
  };
  static Fields decode(std::uint64_t bits) {
    auto field = [&](int lo, int w) { return int((bits >> lo) & ((1ull << w) - 1)); };
    return {field(level_lo, level_w), field(x_lo, x_w), field(y_lo, y_w), field(child_lo, child_w)};
  }
};

}  // namespace cig::cosim
