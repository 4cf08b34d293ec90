// Text vectors of the HLS hand-off testbenches (verif/hls_export, tools/hls_export.sh): a kernel's
// inputs and outputs written as tokens, read back, compared, and measured in bits. Testbench code,
// not kernel code: it uses strings and streams, and it is compiled with the kernels in both type
// configurations (native and -DCIG_HLS_SYSTEMC), so it touches the hls/ types only through their
// value API.
//
// A record is the concatenation of its fields in the order its Fields<T>::visit names them
// (fields_*.hpp; each case's inputs and outputs: top_case.hpp); nothing marks a record's start or
// end, the reader knows the structure.
//   Int<W>, Fixed<W, I>        signed decimal: the raw two's complement value
//   WideInt<W> (W <= 128)      signed decimal: the W-bit two's complement value (stage F's word)
//   UInt<W>, UFixed<W, I>      unsigned decimal: the raw value
//   ZFloat                     its 15-bit code, decimal
//   bool, int                  0/1, decimal
//   T a[N]                     "[" elements "]"; an element followed by "*k" stands for k equal
//                              elements (runs: memories and tables are mostly alike)
#pragma once

#include <cerrno>
#include <cstdint>
#include <cstdlib>
#include <limits>
#include <memory>
#include <sstream>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "hls/types/fixed.hpp"
#include "hls/types/zfloat.hpp"

// WideInt<W> (hls/types/wide_int.hpp) is declared, not included: only the bundles whose kernels
// use it include its header, and its leaf below is instantiated only there.
CIG_HLS_BEGIN_NAMESPACE
template <int W>
class WideInt;
CIG_HLS_END_NAMESPACE

// The testbench calls the synthesis top through CIG_TB_DESIGN, so that Catapult's SCVerify
// (CCS_SCVERIFY) can put the RTL in its place; Vitis HLS replaces the plain call itself. The
// vector generator in the source tree (CIG_TB_IN_TREE) calls the kernel in its namespace: the
// synthesis tops exist only in the bundles (tools/hls_export.sh writes them from the port tables).
#if defined(CCS_SCVERIFY)
#include <mc_scverify.h>
#define CIG_TB_DESIGN(top) CCS_DESIGN(top)
#elif defined(CIG_TB_IN_TREE)
#define CIG_TB_DESIGN(top) ::cig::hls::top
#else
#define CIG_TB_DESIGN(top) ::top
#endif

namespace cig {
namespace hls_tb {

// Fields<T>::visit(v, r) calls v(r.field, "field") for every field of record T, in a fixed order;
// R is T or const T. Specialised per record in fields_*.hpp and per testbench case.
template <class T>
struct Fields;

// ---- Leaves -------------------------------------------------------------------------------------
template <class T>
struct Leaf {
  static constexpr bool is = false;
};
template <int W>
struct Leaf<hls::Int<W>> {
  static constexpr bool is = true, is_signed = true;
  static constexpr int width = W;
  static std::int64_t raw(const hls::Int<W>& x) { return x.value(); }
  static void set(hls::Int<W>& x, std::int64_t v) { x = hls::Int<W>(v); }
};
template <int W>
struct Leaf<hls::UInt<W>> {
  static constexpr bool is = true, is_signed = false;
  static constexpr int width = W;
  static std::uint64_t raw(const hls::UInt<W>& x) { return x.value(); }
  static void set(hls::UInt<W>& x, std::uint64_t v) { x = hls::UInt<W>(v); }
};
template <int W, int I, hls::Quant Q, hls::Overflow O>
struct Leaf<hls::Fixed<W, I, Q, O>> {
  using T = hls::Fixed<W, I, Q, O>;
  static constexpr bool is = true, is_signed = true;
  static constexpr int width = W;
  static std::int64_t raw(const T& x) { return x.raw().value(); }
  static void set(T& x, std::int64_t v) { x = T::from_raw_value(v); }
};
template <int W, int I, hls::Quant Q, hls::Overflow O>
struct Leaf<hls::UFixed<W, I, Q, O>> {
  using T = hls::UFixed<W, I, Q, O>;
  static constexpr bool is = true, is_signed = false;
  static constexpr int width = W;
  static std::uint64_t raw(const T& x) { return x.raw().value(); }
  static void set(T& x, std::uint64_t v) { x = T::from_raw_value(v); }
};
template <>
struct Leaf<hls::ZFloat> {
  static constexpr bool is = true, is_signed = false;
  static constexpr int width = 15;
  static std::uint64_t raw(const hls::ZFloat& x) { return x.bits.value(); }
  static void set(hls::ZFloat& x, std::uint64_t v) { x.bits = hls::UInt<15>(v); }
};
template <>
struct Leaf<bool> {
  static constexpr bool is = true, is_signed = false;
  static constexpr int width = 1;
  static std::uint64_t raw(bool x) { return x ? 1 : 0; }
  static void set(bool& x, std::uint64_t v) { x = v != 0; }
};
template <>
struct Leaf<int> {
  static constexpr bool is = true, is_signed = true;
  static constexpr int width = 32;
  static std::int64_t raw(int x) { return x; }
  static void set(int& x, std::int64_t v) { x = int(v); }
};

// Words wider than 64 bits: a value as a signed 128-bit integer, its decimal text and back.
__extension__ typedef __int128 Int128;
__extension__ typedef unsigned __int128 UInt128;

template <int W>
struct Leaf<hls::WideInt<W>> {
  static constexpr bool is = true, is_signed = true, is_wide = true;
  static constexpr int width = W;
  static Int128 raw(const hls::WideInt<W>& x) {
    return static_cast<Int128>((static_cast<UInt128>(x.high_limb()) << 64) | x.low_limb());
  }
  static void set(hls::WideInt<W>& x, Int128 v) {
    const UInt128 bits = static_cast<UInt128>(v);
    x = hls::WideInt<W>::from_limbs(std::uint64_t(bits >> 64), std::uint64_t(bits));
  }
};
template <class T, class = void>
struct IsWideLeaf : std::false_type {};
template <class T>
struct IsWideLeaf<T, std::enable_if_t<Leaf<T>::is_wide>> : std::true_type {};

inline std::string decimal_of(Int128 v) {
  UInt128 m = v < 0 ? UInt128(0) - static_cast<UInt128>(v) : static_cast<UInt128>(v);
  std::string digits;
  do {
    digits.insert(digits.begin(), char('0' + int(m % 10)));
    m /= 10;
  } while (m != 0);
  return v < 0 ? "-" + digits : digits;
}
// A signed decimal within [lo, hi]; false on any other text.
inline bool parse_decimal(const std::string& t, Int128 lo, Int128 hi, Int128& v) {
  const bool negative = !t.empty() && t[0] == '-';
  const std::size_t first = negative ? 1 : 0;
  if (t.size() == first) return false;
  const UInt128 limit = negative ? UInt128(0) - static_cast<UInt128>(lo) : static_cast<UInt128>(hi);
  UInt128 m = 0;
  for (std::size_t k = first; k < t.size(); ++k) {
    if (t[k] < '0' || t[k] > '9') return false;
    const unsigned d = unsigned(t[k] - '0');
    if (m > limit / 10 || m * 10 + d > limit) return false;  // m * 10 <= limit <= 2^127: no wrap
    m = m * 10 + d;
  }
  v = negative ? static_cast<Int128>(UInt128(0) - m) : static_cast<Int128>(m);
  return true;
}

// What a value is to the walkers below (C++14: tag dispatch, the bundles' standard): an array, a
// leaf (Leaf<T>::is) or a record (Fields<T>); a leaf wider than 64 bits or not.
struct ArrayKind {};
struct LeafKind {};
struct RecordKind {};
template <class T>
using KindOf =
    std::conditional_t<std::is_array<T>::value, ArrayKind, std::conditional_t<Leaf<T>::is, LeafKind, RecordKind>>;
template <class T>
using WideOf = std::integral_constant<bool, IsWideLeaf<T>::value>;

template <class T>
std::string leaf_token(const T& x, std::true_type /*wide*/) {
  return decimal_of(Leaf<T>::raw(x));
}
template <class T>
std::string leaf_token(const T& x, std::false_type /*wide*/) {
  return std::to_string(Leaf<T>::raw(x));
}
template <class T>
std::string leaf_token(const T& x) {
  return leaf_token(x, WideOf<T>{});
}

// ---- Writing --------------------------------------------------------------------------------------
class TextWriter {
 public:
  template <class T>
  void operator()(const T& x, const char*) {
    write(x);
  }
  template <class T>
  void write(const T& x) {
    write(x, KindOf<T>{});
  }
  const std::string& text() const { return text_; }

 private:
  template <class T>
  void write(const T& x, ArrayKind) {
    write_array(x);
  }
  template <class T>
  void write(const T& x, LeafKind) {
    text_ += ' ';
    text_ += leaf_token(x);
  }
  template <class T>
  void write(const T& x, RecordKind) {
    Fields<T>::visit(*this, x);
  }
  template <class E, std::size_t N>
  void write_array(const E (&a)[N]) {
    text_ += " [";
    std::size_t i = 0;
    std::string element = text_of(a[0]);
    while (i < N) {
      std::size_t j = i + 1;
      std::string next;
      while (j < N && (next = text_of(a[j])) == element) ++j;
      text_ += element;
      if (j - i > 1) text_ += " *" + std::to_string(j - i);
      element = std::move(next);
      i = j;
    }
    text_ += " ]";
  }
  template <class E>
  static std::string text_of(const E& e) {
    TextWriter w;
    w.write(e);
    return w.text_;
  }
  std::string text_;
};

template <class T>
std::string to_text(const T& x) {
  TextWriter w;
  w.write(x);
  return w.text();
}

// Assigns a value or an array of them (arrays have no assignment).
template <class T>
void copy_value(T& to, const T& from) {
  to = from;
}
template <class E, std::size_t N>
void copy_value(E (&to)[N], const E (&from)[N]) {
  for (std::size_t k = 0; k < N; ++k) copy_value(to[k], from[k]);
}

// ---- Reading --------------------------------------------------------------------------------------
// Reads a record from a line's tokens; the first error (with the token's position) stops it.
class TextReader {
 public:
  explicit TextReader(const std::string& line) {
    std::istringstream in(line);
    for (std::string t; in >> t;) tokens_.push_back(t);
  }
  template <class T>
  void operator()(T& x, const char*) {
    read(x);
  }
  template <class T>
  void read(T& x) {
    if (error_.empty()) read(x, KindOf<T>{});
  }
  // After the record: every token used.
  void finish() {
    if (error_.empty() && at_ < tokens_.size()) fail("more tokens than the record has");
  }
  const std::string& error() const { return error_; }

 private:
  void fail(const std::string& why) {
    if (error_.empty()) error_ = "token " + std::to_string(at_ + 1) + ": " + why;
  }
  const std::string* next() {
    if (at_ >= tokens_.size()) {
      fail("the line ends inside the record");
      return nullptr;
    }
    return &tokens_[at_++];
  }
  template <class T>
  void read(T& x, ArrayKind) {
    read_array(x);
  }
  template <class T>
  void read(T& x, LeafKind) {
    const std::string* t = next();
    if (t) read_leaf(x, *t, WideOf<T>{});
  }
  template <class T>
  void read(T& x, RecordKind) {
    Fields<T>::visit(*this, x);
  }
  template <class T>
  void read_leaf(T& x, const std::string& t, std::true_type /*wide*/) {
    const int w = Leaf<T>::width;
    const Int128 hi = static_cast<Int128>((UInt128(1) << (w - 1)) - 1), lo = -hi - 1;
    Int128 v = 0;
    if (!parse_decimal(t, lo, hi, v)) return fail("'" + t + "' is not a signed " + std::to_string(w) + "-bit value");
    Leaf<T>::set(x, v);
  }
  template <class T>
  void read_leaf(T& x, const std::string& t, std::false_type /*wide*/) {
    char* end = nullptr;
    errno = 0;
    if (Leaf<T>::is_signed) {
      const long long v = std::strtoll(t.c_str(), &end, 10);
      const int w = Leaf<T>::width;
      const long long lo = w >= 64 ? std::numeric_limits<long long>::min() : -(1LL << (w - 1));
      const long long hi = w >= 64 ? std::numeric_limits<long long>::max() : (1LL << (w - 1)) - 1;
      if (t.empty() || *end != '\0' || errno != 0 || v < lo || v > hi)
        return fail("'" + t + "' is not a signed " + std::to_string(w) + "-bit value");
      Leaf<T>::set(x, v);
    } else {
      const unsigned long long v = std::strtoull(t.c_str(), &end, 10);
      const int w = Leaf<T>::width;
      const unsigned long long hi = w >= 64 ? std::numeric_limits<unsigned long long>::max() : (1ULL << w) - 1;
      if (t.empty() || t[0] == '-' || *end != '\0' || errno != 0 || v > hi)
        return fail("'" + t + "' is not an unsigned " + std::to_string(w) + "-bit value");
      Leaf<T>::set(x, v);
    }
  }
  void expect(const char* what) {
    const std::string* t = next();
    if (t && *t != what) fail("expected '" + std::string(what) + "', found '" + *t + "'");
  }
  template <class E, std::size_t N>
  void read_array(E (&a)[N]) {
    expect("[");
    std::size_t i = 0;
    while (i < N && error_.empty()) {
      read(a[i++]);
      if (at_ < tokens_.size() && tokens_[at_][0] == '*') {
        const std::string& t = tokens_[at_++];
        char* end = nullptr;
        const unsigned long long k = std::strtoull(t.c_str() + 1, &end, 10);
        if (t.size() < 2 || *end != '\0' || k < 2 || k > N - (i - 1)) return fail("bad repeat '" + t + "'");
        for (unsigned long long r = 1; r < k; ++r, ++i) copy_value(a[i], a[i - 1]);
      }
    }
    expect("]");
  }
  std::vector<std::string> tokens_;
  std::size_t at_ = 0;
  std::string error_;
};

// ---- Diagnostics: every leaf with its path ------------------------------------------------------
class PathWriter {
 public:
  template <class T>
  void operator()(const T& x, const char* name) {
    const std::size_t n = path_.size();
    path_ += path_.empty() ? "" : ".";
    path_ += name;
    write(x);
    path_.resize(n);
  }
  template <class T>
  void write(const T& x) {
    write(x, KindOf<T>{});
  }
  std::vector<std::pair<std::string, std::string>> leaves_;

 private:
  template <class E, std::size_t N>
  void write(const E (&x)[N], ArrayKind) {
    for (std::size_t k = 0; k < N; ++k) {
      const std::size_t n = path_.size();
      path_ += "[" + std::to_string(k) + "]";
      write(x[k]);
      path_.resize(n);
    }
  }
  template <class T>
  void write(const T& x, LeafKind) {
    leaves_.push_back({path_, leaf_token(x)});
  }
  template <class T>
  void write(const T& x, RecordKind) {
    Fields<T>::visit(*this, x);
  }
  std::string path_;
};

// "path: expected E, got G" for the first leaf in which two records differ ("" if none).
template <class T>
std::string first_difference(const T& expected, const T& got) {
  PathWriter e, g;
  e.write(expected);
  g.write(got);
  for (std::size_t k = 0; k < e.leaves_.size() && k < g.leaves_.size(); ++k)
    if (e.leaves_[k].second != g.leaves_[k].second)
      return e.leaves_[k].first + ": expected " + e.leaves_[k].second + ", got " + g.leaves_[k].second;
  return "";
}

// ---- Widths: the bits of a port, and its fields ---------------------------------------------------
// Bits of a value of type T (arrays: count x element), from the same field lists.
class WidthCounter {
 public:
  template <class T>
  void operator()(const T& x, const char*) {
    write(x);
  }
  template <class T>
  void write(const T& x) {
    write(x, KindOf<T>{});
  }
  long long bits = 0;

 private:
  template <class E, std::size_t N>
  void write(const E (&x)[N], ArrayKind) {
    WidthCounter element;
    element.write(x[0]);
    bits += element.bits * static_cast<long long>(N);
  }
  template <class T>
  void write(const T&, LeafKind) {
    bits += Leaf<T>::width;
  }
  template <class T>
  void write(const T& x, RecordKind) {
    Fields<T>::visit(*this, x);
  }
};

template <class T>
long long bits_of(const T& x) {
  WidthCounter w;
  w.write(x);
  return w.bits;
}

// A record's fields, one level deep: name, elements, bits per element.
struct FieldWidth {
  std::string name;
  long long count, element_bits;
};
class FieldLister {
 public:
  template <class T>
  void operator()(const T& x, const char* name) {
    const long long count = std::is_array<T>::value ? (long long)(sizeof(T) / sizeof(std::remove_all_extents_t<T>)) : 1;
    fields.push_back({name, count, bits_of(x) / count});
  }
  std::vector<FieldWidth> fields;
};

}  // namespace hls_tb
}  // namespace cig
