// Strict, path-tracking access to a parsed JSON document. Every accessor checks type, range and
// finiteness, and every failure throws InputError naming the file, the JSON path
// (e.g. "objects[2].subobjects[0].polygons[7].indices") and the rule that was broken.
#pragma once

#include <cstddef>
#include <initializer_list>
#include <optional>
#include <string>

#include <glm/vec3.hpp>
#include <nlohmann/json.hpp>

#include "common/error.hpp"

namespace cig {

class JsonNode {
 public:
  JsonNode(const nlohmann::json& value, const std::string& file, std::string path)
      : value_(&value), file_(&file), prefix_(std::move(path)) {}

  [[noreturn]] void fail(const std::string& rule) const;
  std::string path() const;  // e.g. "objects[2].subobjects[0].polygons[7].indices"
  const std::string& file() const { return *file_; }
  const nlohmann::json& raw() const { return *value_; }

  // Objects.
  void expect_object() const;
  // Rejects any key not in `known` (catches typos such as "colur").
  void allow_only(std::initializer_list<const char*> known) const;
  bool has(const char* key) const;
  JsonNode at(const char* key) const;                   // required member
  std::optional<JsonNode> find(const char* key) const;  // optional member

  // Arrays.
  std::size_t array_size() const;  // fails unless an array
  std::size_t array_size(std::size_t min, std::size_t max) const;
  JsonNode operator[](std::size_t i) const;

  // Scalars.
  double number() const;                      // finite
  double number(double lo, double hi) const;  // finite, lo <= x <= hi
  double positive() const;                    // finite, > 0
  long long integer() const;
  long long integer(long long lo, long long hi) const;
  bool boolean() const;
  std::string string() const;

  // Fixed-length numeric arrays.
  glm::dvec3 vec3() const;
  glm::dvec3 vec3(double lo, double hi) const;  // each component in [lo, hi]
  glm::dvec3 colour() const;                    // three numbers in [0, 1]

  // Convenience for optional members with defaults.
  double number_or(const char* key, double fallback) const;
  bool boolean_or(const char* key, bool fallback) const;

 private:
  // The JSON path is kept as the steps from the constructor's node (member keys, which live in the
  // document, and array indices) and spelled out only when a rule fails: a path string built for
  // every node read cost more than the number it names (a fifth of a polygon list's load).
  struct Step {
    const std::string* key;  // a member's key; null: an array element
    std::size_t index;
  };
  static constexpr int kMaxSteps = 12;  // deeper: the steps above are spelled into prefix_
  JsonNode child(const nlohmann::json& value, const std::string* key, std::size_t index) const;

  const nlohmann::json* value_;
  const std::string* file_;
  std::string prefix_;  // the path to the first step
  int steps_ = 0;
  Step step_[kMaxSteps];
};

// The work of parsing one document: the values built and the keys the duplicate-key check compared
// (one lookup per key, O(log k) in an object of k keys), so that a test shows it grows with the
// input linearly (verif/unit/test_json_reader.cpp), never quadratically.
struct JsonParseWork {
  std::size_t values = 0;
  std::size_t keys_visited = 0;
};
// Parses `text` (the contents of `file`); malformed JSON throws InputError with line and column,
// a key repeated in an object InputError at its JSON path. `work`, if given, gets what it took.
nlohmann::json parse_json_text(const std::string& text, const std::string& file, JsonParseWork* work = nullptr);
// Reads and parses a file; a missing or unreadable file throws InputError.
nlohmann::json read_json_file(const std::string& file);
// The largest JSON input (scene, polygon list) read: its parsed document takes about ten times as
// much memory.
constexpr long long kMaxJsonFileBytes = 256ll << 20;
// Throws InputError naming `file` when it is missing, not a regular file (a directory, a device
// such as /dev/zero, a FIFO) or larger than `max_bytes`: the checks before any byte is read, shared
// by readers that open the file themselves (model files through assimp).
void check_input_file(const std::string& file, long long max_bytes, const char* limit_option = "");
// Reads a whole regular file as text, at most `max_bytes` of it (memory stays bounded whatever the
// path names); throws InputError naming `file` when it is missing, not a regular file (a
// directory, a device such as /dev/zero, a FIFO), larger than the limit, or cannot be read.
std::string read_text_file(const std::string& file, long long max_bytes = kMaxJsonFileBytes,
                           const char* limit_option = "");

}  // namespace cig
