// An engine's settings (--engine-opt KEY=VALUE) as one table per engine: each key's values, default
// and help. The engine's parser checks a setting against its table (parse_engine_options) and
// `cig engines` lists the same table (registry/engine_registry.hpp), so the listing cannot drift
// from what the parser accepts.
//
// And what an engine can leave out of an image (DropKind): each engine names the counts it may
// report under "dropped" (every key present, zeros included; RasterEngine::render fills them), with
// what each means; the commands warn with every nonzero count (cli::drop_warning), `cig engines`
// lists them.
#pragma once

#include <map>
#include <string>
#include <vector>

namespace cig {

struct EngineOptionSpec {
  enum class Kind {
    kChoice,   // one of `choices`
    kInteger,  // an integer in [min, max]
    kReal,     // a number in (min, max]
    kSyntax,   // a syntax `check` parses (InputError), described by `syntax`
  };
  std::string key;
  Kind kind = Kind::kChoice;
  std::vector<std::string> choices;
  double min = 0, max = 0;
  std::string syntax;
  void (*check)(const std::string& value) = nullptr;
  std::string default_value;  // what the engine takes without the key; "" when unset means more (help)
  std::string help;
  std::string shorthand;  // the command-line option that sets the key too ("--arch"), or ""

  // The values as `cig engines` lists them: "1|4|16|64", "24..80", "(0, 1e6]", the syntax.
  std::string range() const;
  // As an error says them: "1, 4, 16 or 64", "> 0 and <= 1e6".
  std::string range_in_words() const;
};

EngineOptionSpec choice_option(std::string key, std::vector<std::string> choices, std::string default_value,
                               std::string help, std::string shorthand = "");
EngineOptionSpec integer_option(std::string key, int min, int max, std::string default_value, std::string help);
EngineOptionSpec real_option(std::string key, double above, double max, std::string default_value, std::string help);
// The same with the default given as the engine's constant (written as the range is), so the two
// cannot differ.
EngineOptionSpec real_option(std::string key, double above, double max, double default_value, std::string help);
EngineOptionSpec syntax_option(std::string key, std::string syntax, void (*check)(const std::string&),
                               std::string default_value, std::string help, std::string shorthand = "");
// spp=1|4|16|64...: 4^t samples per pixel, t = 0..max_side_log2 (default 16).
EngineOptionSpec samples_per_pixel_option(int max_side_log2);
// subpixel=B: the formatter grid at 1/2^B pixel, B = 0..kMaxSubpixelBits (unset: eq. 1's grid),
// for the fixed engines' formatter or the grid the float reference snaps to.
constexpr int kMaxSubpixelBits = 8;
EngineOptionSpec subpixel_option(bool float_reference);

// An engine's settings, checked against its table, every key of the table present (its default
// when not given).
class EngineSettings {
 public:
  const std::string& text(const std::string& key) const { return values_.at(key); }
  int integer(const std::string& key) const;
  double real(const std::string& key) const;
  bool is(const std::string& key, const std::string& value) const { return text(key) == value; }
  // t of spp = 4^t (the key a samples_per_pixel_option checked).
  int side_log2() const;
  std::map<std::string, std::string>& values() { return values_; }

 private:
  std::map<std::string, std::string> values_;
};

// Every setting of `params` against `specs`: a key the table lacks, or a value outside its range,
// is an InputError naming the engine, the key and what it takes (at the key's shorthand, else at
// --engine-opt).
EngineSettings parse_engine_options(const std::string& engine, const std::vector<EngineOptionSpec>& specs,
                                    const std::map<std::string, std::string>& params);

// One count an engine reports under its report's "dropped".
struct DropKind {
  enum class Cause {
    kMemoryFull,  // a memory of the modelled hardware had no room (the seed's overload behaviour)
    kCannotDraw,  // the engine does not draw that kind of primitive, or that part of it
  };
  std::string key;  // in "dropped"
  Cause cause;
  std::string what;  // what the count counts, after the number: "polygon(s) dropped by ..."
};

}  // namespace cig
