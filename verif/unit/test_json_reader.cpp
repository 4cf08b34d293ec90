// The JSON reader's work grows with its input linearly (issue 34: loading a polygon list was
// quadratic, 1 M polygons more than 120 s): the values it builds and the keys its duplicate-key
// check compares, counted (JsonParseWork) on two sizes of wide, deep and list-shaped documents.
// Counts, not times: the same on any machine. And the duplicate-key rule itself, at its path.
#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "common/error.hpp"
#include "common/json_reader.hpp"
#include "frame/screen_frame.hpp"

namespace cig {
namespace {

JsonParseWork work_of(const std::string& text) {
  JsonParseWork w;
  parse_json_text(text, "work.json", &w);
  return w;
}

// An array of n objects of three keys: the shape of a polygon list.
std::string wide_array(int n) {
  std::string t = "[";
  for (int i = 0; i < n; ++i) t += std::string(i ? "," : "") + R"({"x": 1, "y": [2, 3], "z": {"w": 4}})";
  return t + "]";
}

// n nested objects, then n nested arrays.
std::string deep(int n) {
  std::string t;
  for (int i = 0; i < n; ++i) t += R"({"a": )";
  for (int i = 0; i < n; ++i) t += "[";
  t += "0";
  for (int i = 0; i < n; ++i) t += "]";
  for (int i = 0; i < n; ++i) t += "}";
  return t;
}

// One object of n keys.
std::string wide_object(int n) {
  std::string t = "{";
  for (int i = 0; i < n; ++i) t += std::string(i ? "," : "") + "\"k" + std::to_string(i) + "\": " + std::to_string(i);
  return t + "}";
}

// A polygon list of n triangles, as cig polys writes it.
std::string polygon_list(int n) {
  ScreenFrame f;
  for (int i = 0; i < n; ++i) {
    ScreenPolygon p;
    p.vertices = {{0, 0, 1, 1}, {0.5, 0, 1, 1}, {0, 0.5, 1, 1}};
    f.polygons.push_back(p);
  }
  return polygon_list_json(f);
}

TEST(JsonReader, WorkOfAListOfObjectsIsProportionalToItsLength) {
  const JsonParseWork a = work_of(wide_array(1000)), b = work_of(wide_array(4000));
  EXPECT_EQ(a.values, 1u + 1000u * 7u);  // the array, then per element the object and its 6 values
  EXPECT_EQ(b.values - 1, 4 * (a.values - 1));
  EXPECT_GT(a.keys_visited, 0u);
  EXPECT_EQ(b.keys_visited, 4 * a.keys_visited);
}

TEST(JsonReader, WorkOfADeepDocumentIsProportionalToItsDepth) {
  const JsonParseWork a = work_of(deep(500)), b = work_of(deep(2000));
  EXPECT_EQ(a.values, 1001u);
  EXPECT_EQ(b.values - 1, 4 * (a.values - 1));
  EXPECT_EQ(b.keys_visited, 4 * a.keys_visited);
}

TEST(JsonReader, DuplicateCheckOfAWideObjectIsNLogN) {
  // Each key is looked up once in the object's ordered map (a red-black tree, at most 2 log2(k + 1)
  // deep): at most 2 log2(n) + 2 keys compared each, where a scan of the keys seen so far would
  // compare n^2 / 2 in all (12.5 M here).
  const int n = 5000;
  const JsonParseWork w = work_of(wide_object(n));
  EXPECT_EQ(w.values, std::size_t(n) + 1);
  EXPECT_LE(double(w.keys_visited), n * (2 * std::log2(double(n)) + 2));
}

TEST(JsonReader, WorkOfAPolygonListIsProportionalToItsPolygons) {
  const JsonParseWork a = work_of(polygon_list(1000)), b = work_of(polygon_list(4000));
  const JsonParseWork none = work_of(polygon_list(0));  // the header
  EXPECT_EQ(b.values - none.values, 4 * (a.values - none.values));
  EXPECT_EQ(b.keys_visited - none.keys_visited, 4 * (a.keys_visited - none.keys_visited));
  EXPECT_EQ(parse_polygon_list(polygon_list(4000), "list.polys.json").polygons.size(), 4000u);
}

std::string duplicate_rule(const std::string& text) {
  try {
    parse_json_text(text, "dup.json");
  } catch (const InputError& e) { return e.where() + ": " + e.rule(); }
  return "accepted";
}

TEST(JsonReader, DuplicateKeyIsRefusedAtItsPath) {
  EXPECT_EQ(duplicate_rule(R"({"a": 1, "a": 2})"), "a: duplicate key 'a' (each key may appear once)");
  EXPECT_EQ(duplicate_rule(R"({"p": [{"x": 1}, {"x": 1, "y": 2, "x": 3}]})"),
            "p[1].x: duplicate key 'x' (each key may appear once)");
  EXPECT_EQ(duplicate_rule(R"([[0], [{"b": {"c": 0, "c": 0}}]])"),
            "[1][0].b.c: duplicate key 'c' (each key may appear once)");
  EXPECT_EQ(duplicate_rule(R"({"a": {"x": 1}, "b": {"x": 1}})"), "accepted");  // per object
}

}  // namespace
}  // namespace cig
