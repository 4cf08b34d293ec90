// Records of plain values in native byte order, written and read back by the same binary: the
// model loader's answer from its child process (scene/model_loader.cpp) and the priority
// compiler's cache files (scene/priority_compiler.cpp). The reader checks every length against
// what is left, so a truncated or foreign record is refused, never read past its end.
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <string>

namespace cig {

class ByteWriter {
 public:
  template <class T>
  void pod(const T& v) {
    bytes.append(reinterpret_cast<const char*>(&v), sizeof v);
  }
  void str(const std::string& s) {
    pod(std::uint64_t(s.size()));
    bytes += s;
  }
  std::string bytes;
};

class ByteReader {
 public:
  ByteReader(const std::string& b, std::size_t start = 0) : b_(b), pos_(start) {}
  template <class T>
  bool pod(T& v) {
    if (pos_ > b_.size() || sizeof v > b_.size() - pos_) return false;
    std::memcpy(&v, b_.data() + pos_, sizeof v);
    pos_ += sizeof v;
    return true;
  }
  // A count of items of at least `each` bytes that the rest of the record can hold.
  bool count(std::uint64_t& n, std::size_t each) { return pod(n) && n <= (b_.size() - pos_) / each; }
  bool str(std::string& s) {
    std::uint64_t n = 0;
    if (!count(n, 1)) return false;
    s = b_.substr(pos_, n);
    pos_ += n;
    return true;
  }
  bool done() const { return pos_ == b_.size(); }

 private:
  const std::string& b_;
  std::size_t pos_;
};

}  // namespace cig
