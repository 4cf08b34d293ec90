#include "common/json_reader.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <vector>

namespace cig {

namespace {

const char* type_name(const nlohmann::json& v) {
  if (v.is_null()) return "null";
  if (v.is_boolean()) return "a boolean";
  if (v.is_number()) return "a number";
  if (v.is_string()) return "a string";
  if (v.is_array()) return "an array";
  return "an object";
}

std::string format_number(double x) {
  std::ostringstream s;
  s << x;
  return s.str();
}

}  // namespace

std::string JsonNode::path() const {
  std::string p = prefix_;
  for (int i = 0; i < steps_; ++i) {
    if (step_[i].key) p += (p.empty() ? "" : ".") + *step_[i].key;
    else p += "[" + std::to_string(step_[i].index) + "]";
  }
  return p;
}

JsonNode JsonNode::child(const nlohmann::json& value, const std::string* key, std::size_t index) const {
  JsonNode c(*this);
  c.value_ = &value;
  if (c.steps_ == kMaxSteps) {
    c.prefix_ = path();
    c.steps_ = 0;
  }
  c.step_[c.steps_++] = {key, index};
  return c;
}

void JsonNode::fail(const std::string& rule) const {
  const std::string p = path();
  throw InputError(*file_, p.empty() ? "(top level)" : p, rule);
}

void JsonNode::expect_object() const {
  if (!value_->is_object()) fail(std::string("must be a JSON object, found ") + type_name(*value_));
}

void JsonNode::allow_only(std::initializer_list<const char*> known) const {
  expect_object();
  for (auto it = value_->begin(); it != value_->end(); ++it) {
    bool ok = false;
    for (const char* k : known) ok = ok || it.key() == k;
    if (!ok) {
      std::string list;
      for (const char* k : known) list += (list.empty() ? "" : ", ") + std::string(k);
      child(*it, &it.key(), 0).fail("unknown field '" + it.key() + "' (known fields: " + list + ")");
    }
  }
}

bool JsonNode::has(const char* key) const {
  expect_object();
  return value_->contains(key);
}

JsonNode JsonNode::at(const char* key) const {
  expect_object();
  auto it = value_->find(key);
  if (it == value_->end()) fail(std::string("missing required field '") + key + "'");
  return child(*it, &it.key(), 0);
}

std::optional<JsonNode> JsonNode::find(const char* key) const {
  expect_object();
  auto it = value_->find(key);
  if (it == value_->end()) return std::nullopt;
  return child(*it, &it.key(), 0);
}

std::size_t JsonNode::array_size() const {
  if (!value_->is_array()) fail(std::string("must be an array, found ") + type_name(*value_));
  return value_->size();
}

std::size_t JsonNode::array_size(std::size_t min, std::size_t max) const {
  std::size_t n = array_size();
  if (n < min || n > max) {
    if (min == max) fail("must have exactly " + std::to_string(min) + " elements, has " + std::to_string(n));
    fail("must have " + std::to_string(min) + " to " + std::to_string(max) + " elements, has " + std::to_string(n));
  }
  return n;
}

JsonNode JsonNode::operator[](std::size_t i) const { return child((*value_)[i], nullptr, i); }

double JsonNode::number() const {
  if (!value_->is_number()) fail(std::string("must be a number, found ") + type_name(*value_));
  double x = value_->get<double>();
  if (!std::isfinite(x)) fail("must be a finite number (NaN and infinity are not allowed)");
  return x;
}

double JsonNode::number(double lo, double hi) const {
  double x = number();
  if (!(x >= lo && x <= hi))
    fail("must lie in [" + format_number(lo) + ", " + format_number(hi) + "], is " + format_number(x));
  return x;
}

double JsonNode::positive() const {
  double x = number();
  if (!(x > 0)) fail("must be positive, is " + format_number(x));
  return x;
}

long long JsonNode::integer() const {
  if (!value_->is_number_integer())
    fail(std::string("must be an integer, found ") +
         (value_->is_number() ? "a fractional number" : type_name(*value_)));
  if (value_->is_number_unsigned() && value_->get<unsigned long long>() > 1ull << 62) fail("integer is too large");
  return value_->get<long long>();
}

long long JsonNode::integer(long long lo, long long hi) const {
  long long x = integer();
  if (x < lo || x > hi)
    fail("must lie in [" + std::to_string(lo) + ", " + std::to_string(hi) + "], is " + std::to_string(x));
  return x;
}

bool JsonNode::boolean() const {
  if (!value_->is_boolean()) fail(std::string("must be true or false, found ") + type_name(*value_));
  return value_->get<bool>();
}

std::string JsonNode::string() const {
  if (!value_->is_string()) fail(std::string("must be a string, found ") + type_name(*value_));
  return value_->get<std::string>();
}

glm::dvec3 JsonNode::vec3() const {
  array_size(3, 3);
  return {(*this)[0].number(), (*this)[1].number(), (*this)[2].number()};
}

glm::dvec3 JsonNode::vec3(double lo, double hi) const {
  array_size(3, 3);
  return {(*this)[0].number(lo, hi), (*this)[1].number(lo, hi), (*this)[2].number(lo, hi)};
}

glm::dvec3 JsonNode::colour() const {
  array_size(3, 3);
  return {(*this)[0].number(0, 1), (*this)[1].number(0, 1), (*this)[2].number(0, 1)};
}

double JsonNode::number_or(const char* key, double fallback) const {
  auto n = find(key);
  return n ? n->number() : fallback;
}

bool JsonNode::boolean_or(const char* key, bool fallback) const {
  auto n = find(key);
  return n ? n->boolean() : fallback;
}

namespace {

// A key looked up in an object, counting the keys it is compared with: the duplicate check's work.
struct CountedKey {
  const std::string& key;
  std::size_t& visited;
};
bool operator<(const CountedKey& a, const std::string& b) {
  ++a.visited;
  return a.key < b;
}
bool operator<(const std::string& a, const CountedKey& b) {
  ++b.visited;
  return a < b.key;
}

// Builds the document from the parser's SAX events and rejects a repeated key where it occurs
// (nlohmann keeps the last one silently, and `"raster": 4096, ..., "raster": 512` would render at
// 512), naming its JSON path. Each event costs O(1) (a key O(log k) in an object of k keys): the
// callback form of nlohmann::json::parse scans an array's elements after each object in it ends,
// O(n^2) for a list of n polygons, and copies every scalar once more.
class CheckedDomBuilder {
 public:
  using json = nlohmann::json;
  CheckedDomBuilder(json& root, const std::string& file) : root_(root), file_(file) {}

  bool null() { return add(nullptr); }
  bool boolean(bool x) { return add(x); }
  bool number_integer(json::number_integer_t x) { return add(x); }
  bool number_unsigned(json::number_unsigned_t x) { return add(x); }
  bool number_float(json::number_float_t x, const json::string_t& /*token*/) { return add(x); }
  bool string(json::string_t& x) { return add(std::move(x)); }
  bool binary(json::binary_t& x) { return add(std::move(x)); }
  bool start_object(std::size_t /*unknown*/) { return open(json::value_t::object); }
  bool start_array(std::size_t /*unknown*/) { return open(json::value_t::array); }
  bool end_object() { return close(); }
  bool end_array() { return close(); }
  bool key(json::string_t& k) {
    Scope& o = open_.back();
    json::object_t& members = o.value->get_ref<json::object_t&>();
    auto at = members.lower_bound(CountedKey{k, work_.keys_visited});
    if (at != members.end() && at->first == k) {
      o.key = &at->first;
      throw InputError(file_, path(), "duplicate key '" + k + "' (each key may appear once)");
    }
    at = members.emplace_hint(at, std::move(k), nullptr);
    o.key = &at->first;
    member_ = &at->second;
    return true;
  }
  // The parser's own error (malformed text, a number out of range), rethrown as its type.
  template <class Exception>
  bool parse_error(std::size_t /*byte*/, const std::string& /*token*/, const Exception& e) {
    throw e;
  }
  const JsonParseWork& work() const { return work_; }

 private:
  struct Scope {
    json* value;             // the open object or array
    const std::string* key;  // an object's member being read (its key in the map: stable)
  };
  // A value starts: the document, the next element of an array, or the member just keyed.
  template <class T>
  json* place(T&& x) {
    ++work_.values;
    if (open_.empty()) return &(root_ = json(std::forward<T>(x)));
    json& c = *open_.back().value;
    if (c.is_array()) return &c.get_ref<json::array_t&>().emplace_back(std::forward<T>(x));
    *member_ = json(std::forward<T>(x));
    return member_;
  }
  template <class T>
  bool add(T&& x) {
    place(std::forward<T>(x));
    return true;
  }
  bool open(json::value_t kind) {
    open_.push_back({place(kind), nullptr});
    return true;
  }
  bool close() {
    open_.pop_back();
    return true;
  }
  // The JSON path of the member being read, e.g. "channels[0].fov"; built only for an error.
  std::string path() const {
    std::string p;
    for (const Scope& s : open_) {
      if (s.value->is_array()) p += "[" + std::to_string(s.value->size() - 1) + "]";
      else p += (p.empty() ? "" : ".") + *s.key;
    }
    return p;
  }
  json& root_;
  const std::string& file_;
  std::vector<Scope> open_;
  json* member_ = nullptr;
  JsonParseWork work_;
};

}  // namespace

nlohmann::json parse_json_text(const std::string& text, const std::string& file, JsonParseWork* work) {
  try {
    nlohmann::json doc;
    CheckedDomBuilder builder(doc, file);
    nlohmann::json::sax_parse(text, &builder);
    if (work) *work = builder.work();
    return doc;
  } catch (const nlohmann::json::parse_error& e) {
    // nlohmann reports "parse error at line L, column C: <what>"; keep its position, reword the rest.
    std::string what = e.what();
    std::string where = "byte " + std::to_string(e.byte);
    auto at = what.find(" at line ");
    auto colon = what.find(": ", at == std::string::npos ? 0 : at);
    if (at != std::string::npos && colon != std::string::npos) {
      where = what.substr(at + 4, colon - at - 4);
      what = what.substr(colon + 2);
    } else if (auto p = what.find("parse error"); p != std::string::npos) {
      what = what.substr(p);
    }
    throw InputError(file, where, "malformed JSON (" + what + ")");
  } catch (const nlohmann::json::out_of_range& e) {
    // Number overflow (e.g. 1e999): nlohmann names the token but not its place; find it.
    std::string what = e.what();
    std::string token;
    auto q0 = what.find('\''), q1 = what.rfind('\'');
    if (q0 != std::string::npos && q1 > q0) token = what.substr(q0 + 1, q1 - q0 - 1);
    std::string where;
    if (auto p = token.empty() ? std::string::npos : text.find(token); p != std::string::npos) {
      std::size_t line = 1, col = 1;
      for (std::size_t i = 0; i < p; ++i) {
        if (text[i] == '\n') {
          ++line;
          col = 1;
        } else {
          ++col;
        }
      }
      where = "line " + std::to_string(line) + ", column " + std::to_string(col);
    }
    throw InputError(file, where, "number '" + token + "' is not a finite number (overflow)");
  }
}

void check_input_file(const std::string& file, long long max_bytes, const char* limit_option) {
  if (file.empty()) throw InputError(file, "", "the path is empty");
  if (file.find('\0') != std::string::npos) throw InputError(file, "", "the path contains a NUL character");
  std::error_code ec;
  const auto status = std::filesystem::status(file, ec);
  if (ec || !std::filesystem::exists(status)) throw InputError(file, "", "cannot open file (missing or unreadable)");
  if (std::filesystem::is_directory(status)) throw InputError(file, "", "is a directory, not a file");
  if (!std::filesystem::is_regular_file(status))
    throw InputError(file, "", "is not a regular file (a device, FIFO or socket cannot be read as input)");
  const auto size = std::filesystem::file_size(file, ec);
  const std::string limit =
      std::to_string(max_bytes) + " bytes" + (*limit_option ? std::string(" (") + limit_option + ")" : std::string());
  if (!ec && (long long)size > max_bytes)
    throw InputError(file, "", "file is " + std::to_string(size) + " bytes, more than the limit of " + limit);
}

std::string read_text_file(const std::string& file, long long max_bytes, const char* limit_option) {
  check_input_file(file, max_bytes, limit_option);
  std::error_code ec;
  const auto size = std::filesystem::file_size(file, ec);
  const std::string limit =
      std::to_string(max_bytes) + " bytes" + (*limit_option ? std::string(" (") + limit_option + ")" : std::string());
  std::ifstream in(file, std::ios::binary);
  if (!in) throw InputError(file, "", "cannot open file (missing or unreadable)");
  // Read in chunks up to one byte past the limit, so a file that grows while it is read is caught.
  std::string text;
  text.reserve(std::size_t(std::min<long long>(ec ? 0 : (long long)size, max_bytes)));
  char chunk[1 << 16];
  while (in && (long long)text.size() <= max_bytes) {
    in.read(chunk, sizeof chunk);
    text.append(chunk, std::size_t(in.gcount()));
  }
  if (in.bad()) throw InputError(file, "", "error while reading file");
  if ((long long)text.size() > max_bytes)
    throw InputError(file, "", "file grew beyond the limit of " + limit + " while it was read");
  return text;
}

nlohmann::json read_json_file(const std::string& file) { return parse_json_text(read_text_file(file), file); }

}  // namespace cig
