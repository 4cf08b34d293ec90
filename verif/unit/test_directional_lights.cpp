// Directional light points (a light point's "beam" and "below", scenes/README.md), decided by the
// geometric processor (stage B) so that every engine gets them through the polygon list:
//  * stage B: a beamed light seen on its axis keeps its intensity (f = 1), at half the horizontal
//    half-width it has 3/4 of it, outside the lobe (past the ellipse inside its bounding rectangle,
//    past the rectangle, behind) it is not listed and is counted in the report; the same cases
//    around an object turned by a heading of 90 (and -135) degrees; omnidirectional lights beside
//    it are listed as before;
//  * a PAPI of four units (transitions 2.5, 2.833, 3.167 and 3.5 degrees) seen from 2, 3 and 4
//    degrees shows 0, 2 and 4 white units, unit by unit as the eye's elevation from each unit
//    (computed here from the geometry) says, also with the PAPI's object pitched (the transition
//    is measured against the world horizontal);
//  * scenes/small/papi.json: red PAPI at its first frame, white at its last;
//  * every engine that draws light points shows the PAPI's red and white units and the beamed
//    light at their centres, and background where the light whose beam points away would be, as
//    the float reference does.
#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "generator/image_generator.hpp"
#include "reference/sample_lattice.hpp"
#include "registry/engine_registry.hpp"
#include "scene/scene_loader.hpp"

namespace cig {
namespace {

using json = nlohmann::ordered_json;

constexpr double kPi = 3.14159265358979323846;
double rad(double deg) { return deg * kPi / 180; }
double deg(double r) { return r * 180 / kPi; }

// A unit vector at azimuth az (clockwise from +y) and elevation el, degrees.
std::vector<double> direction(double az, double el) {
  return {std::sin(rad(az)) * std::cos(rad(el)), std::cos(rad(az)) * std::cos(rad(el)), std::sin(rad(el))};
}

// A heading in [-180, 180), as a keyframe takes it.
double wrapped(double h) { return h - 360 * std::floor((h + 180) / 360); }

// A keyframe at `eye` looking at `target`.
json keyframe_looking_at(int frame, const std::vector<double>& eye, const std::vector<double>& target) {
  const double dx = target[0] - eye[0], dy = target[1] - eye[1], dz = target[2] - eye[2];
  return {{"frame", frame},
          {"position", eye},
          {"heading", wrapped(deg(std::atan2(dx, dy)))},
          {"pitch", deg(std::atan2(dz, std::hypot(dx, dy)))}};
}

json scene_with(const json& objects, const json& keyframes, int raster, double fov) {
  return {{"format", "cig-scene"},
          {"version", 1},
          {"raster", raster},
          {"channels", json::array({{{"name", "c"}, {"fov", fov}}})},
          {"background", {0.0, 0.05, 0.15}},
          {"observer", {{"keyframes", keyframes}}},
          {"objects", objects}};
}

// ---- Stage B: the lobe ----

struct BeamCase {
  const char* name;
  double da, de;  // the eye's azimuth and elevation off the axis, degrees
  double f;       // the expected factor (0: not listed)
};

constexpr double kBeamHeading = 30, kBeamElevation = 5, kHalfH = 10, kHalfV = 7;

// f = 1 - (da/h)^2 - (de/v)^2 at the cases' angles, by hand: 1, 1 - 1/4, 0.64 + 0.51 > 1.
const BeamCase kBeamCases[] = {
    {"on the axis", 0, 0, 1},
    {"at half the horizontal half-width", kHalfH / 2, 0, 0.75},
    {"at half the vertical half-width, below", 0, -kHalfV / 2, 0.75},
    {"inside the rectangle, outside the ellipse", 8, 5, 0},
    {"past the horizontal half-width", 15, 0, 0},
    {"above the lobe", 0, 9, 0},
    {"behind", 180, 0, 0},
};

TEST(DirectionalLights, StageBScalesByTheLobeAndDropsWhatLiesOutside) {
  const std::vector<double> origin{120, -40, 3};
  for (double object_heading : {0.0, 90.0, -135.0}) {
    SCOPED_TRACE("object heading " + std::to_string(object_heading));
    // Plain lights (blue) before and after the beamed one (white), all at the object's origin.
    const json plain = {{"position", {0, 0, 0}}, {"diameter", 0.3}, {"colour", {0, 0, 1}}, {"intensity", 0.5}};
    json beamed = {
        {"position", {0, 0, 0}},
        {"diameter", 0.3},
        {"intensity", 0.8},
        {"beam",
         {{"heading", kBeamHeading}, {"elevation", kBeamElevation}, {"horizontal", kHalfH}, {"vertical", kHalfV}}}};
    const json object = {{"name", "beacon"},
                         {"position", origin},
                         {"heading", object_heading},
                         {"light_points", {plain, beamed, plain}}};
    // The eye 100 m from the light in the case's direction: the object's azimuths turned by its heading.
    json keyframes = json::array();
    int frame = 0;
    for (const BeamCase& c : kBeamCases) {
      const std::vector<double> d = direction(object_heading + kBeamHeading + c.da, kBeamElevation + c.de);
      keyframes.push_back(keyframe_looking_at(
          frame++, {origin[0] + 100 * d[0], origin[1] + 100 * d[1], origin[2] + 100 * d[2]}, origin));
    }
    const Scene scene = parse_scene(scene_with(json::array({object}), keyframes, 64, 30).dump(), "beam.json");
    const ImageGenerator generator(scene);
    frame = 0;
    for (const BeamCase& c : kBeamCases) {
      SCOPED_TRACE(c.name);
      json report;
      const ScreenFrame f = generator.geometry(frame++, 0, report);
      int plain_lights = 0, beamed_lights = 0;
      for (const ScreenLightPoint& l : f.light_points) {
        if (l.colour.b == 1 && l.colour.r == 0) {
          ++plain_lights;
          EXPECT_EQ(l.intensity, 0.5);
        } else {
          ++beamed_lights;
          EXPECT_NEAR(l.intensity, 0.8 * c.f, 1e-9);
          EXPECT_NEAR(l.xs, 0, 1e-9);  // the eye looks at it
        }
      }
      EXPECT_EQ(plain_lights, 2);
      EXPECT_EQ(beamed_lights, c.f > 0 ? 1 : 0);
      EXPECT_EQ(report["geometry"]["light_points_in"].get<int>(), 3);
      EXPECT_EQ(report["geometry"]["light_points_out"].get<int>(), 2 + beamed_lights);
      EXPECT_EQ(report["geometry"]["light_points_outside_beam"].get<int>(), c.f > 0 ? 0 : 1);
    }
  }
}

// ---- The PAPI ----

const double kTransitions[] = {2.5, 2.833, 3.167, 3.5};
constexpr double kUnitSpacing = 9;   // metres between units, across the approach
constexpr double kUnitHeight = 0.5;  // the object's origin: its pitch moves no unit

// Four units along x (west to east) at the object's origin, each white above its transition.
json papi_object(double pitch) {
  json units = json::array();
  for (int k = 0; k < 4; ++k)
    units.push_back({{"position", {k * kUnitSpacing, 0, 0}},
                     {"diameter", 0.5},
                     {"colour", {1, 1, 1}},
                     {"below", {{"elevation", kTransitions[k]}, {"colour", {1, 0, 0}}}}});
  return {{"name", "papi"}, {"position", {0, 0, kUnitHeight}}, {"pitch", pitch}, {"light_points", units}};
}

// The eye `distance` m south of the PAPI's centre, at `elevation` degrees above its units.
std::vector<double> papi_eye(double elevation, double distance) {
  const double cx = 1.5 * kUnitSpacing;
  return {cx, -distance, kUnitHeight + distance * std::tan(rad(elevation))};
}

TEST(DirectionalLights, PapiShowsWhiteAboveEachUnitsTransition) {
  const double elevations[] = {2.0, 3.0, 4.0};
  const int expected_white[] = {0, 2, 4};
  // Pitched by 2 degrees about x, along which the units lie: their positions stay, and the
  // transitions, measured against the world horizontal, must not follow the object's tilt.
  for (double pitch : {0.0, 2.0}) {
    SCOPED_TRACE("PAPI pitched " + std::to_string(pitch));
    json keyframes = json::array();
    for (int i = 0; i < 3; ++i)
      keyframes.push_back(keyframe_looking_at(i, papi_eye(elevations[i], 1000), {1.5 * kUnitSpacing, 0, kUnitHeight}));
    const Scene scene =
        parse_scene(scene_with(json::array({papi_object(pitch)}), keyframes, 64, 10).dump(), "papi.json");
    const ImageGenerator generator(scene);
    for (int i = 0; i < 3; ++i) {
      SCOPED_TRACE("eye at " + std::to_string(elevations[i]) + " degrees");
      const std::vector<double> eye = papi_eye(elevations[i], 1000);
      // The ground truth from the geometry: the eye's elevation seen from each unit.
      int truth_white = 0;
      std::vector<bool> white_truth;
      for (int k = 0; k < 4; ++k) {
        const double dx = eye[0] - k * kUnitSpacing, dy = eye[1], dz = eye[2] - kUnitHeight;
        const bool white = deg(std::atan2(dz, std::hypot(dx, dy))) >= kTransitions[k];
        white_truth.push_back(white);
        truth_white += white;
      }
      ASSERT_EQ(truth_white, expected_white[i]);  // the geometry is what the case says
      json report;
      ScreenFrame f = generator.geometry(i, 0, report);
      ASSERT_EQ(f.light_points.size(), 4u);
      // The units left to right on the screen are the units west to east.
      std::sort(f.light_points.begin(), f.light_points.end(),
                [](const ScreenLightPoint& a, const ScreenLightPoint& b) { return a.xs < b.xs; });
      int white = 0;
      for (int k = 0; k < 4; ++k) {
        const Rgb c = f.light_points[std::size_t(k)].colour;
        const bool is_white = c == Rgb(1, 1, 1);
        EXPECT_TRUE(is_white || c == Rgb(1, 0, 0)) << "unit " << k;
        EXPECT_EQ(is_white, white_truth[std::size_t(k)]) << "unit " << k;
        white += is_white;
      }
      EXPECT_EQ(white, expected_white[i]);
      EXPECT_EQ(report["geometry"]["light_points_outside_beam"].get<int>(), 0);
    }
  }
}

// scenes/small/papi.json as scenes/README.md describes it: the PAPI's four units red at frame 0
// (2.05 degrees) and white at frame 9 (4.1), and the other end's threshold and end lights and the
// edge lights aimed the other way (56) never listed.
TEST(DirectionalLights, ShippedPapiSceneIsWhatTheReadmeSays) {
  const Scene scene = load_scene(std::string(CIG_SOURCE_DIR) + "/scenes/small/papi.json");
  const ImageGenerator generator(scene);
  for (int frame : {0, 9}) {
    SCOPED_TRACE("frame " + std::to_string(frame));
    json report;
    const ScreenFrame f = generator.geometry(frame, 0, report);
    const auto count = [&](const Rgb& c) {
      return std::count_if(f.light_points.begin(), f.light_points.end(),
                           [&](const ScreenLightPoint& l) { return l.colour == c; });
    };
    EXPECT_EQ(count(Rgb(1, 1, 1)), frame == 0 ? 0 : 4);
    EXPECT_EQ(count(Rgb(1, 0.05, 0.02)), frame == 0 ? 4 : 0);
    EXPECT_EQ(report["geometry"]["light_points_outside_beam"].get<int>(), 56);
    EXPECT_EQ(report["geometry"]["light_points_out"].get<int>(), 60);
  }
}

// ---- Every engine ----

// The PAPI seen from 3 degrees at 300 m (two red units, two white), a white light whose beam is
// aimed at the eye (f = 1) west of it and one whose beam points away (north) further west.
json engines_scene(bool away_has_beam) {
  const std::vector<double> eye = papi_eye(3.0, 300), towards{-12, 0, kUnitHeight};
  const double dx = eye[0] - towards[0], dy = eye[1] - towards[1], dz = eye[2] - towards[2];
  const auto lobe = [](double heading, double elevation) {
    return json{{"heading", heading}, {"elevation", elevation}, {"horizontal", 10}, {"vertical", 7}};
  };
  json away = {{"position", {-24, 0, kUnitHeight}}, {"diameter", 0.5}, {"colour", {1, 1, 1}}};
  if (away_has_beam) away["beam"] = lobe(0, 3);
  const json aimed = {{"position", towards},
                      {"diameter", 0.5},
                      {"colour", {1, 1, 1}},
                      {"beam", lobe(deg(std::atan2(dx, dy)), deg(std::atan2(dz, std::hypot(dx, dy))))}};
  const json beams = {{"name", "beams"}, {"position", {0, 0, 0}}, {"light_points", {aimed, away}}};
  return scene_with(json::array({papi_object(0), beams}),
                    json::array({keyframe_looking_at(0, eye, {0, 0, kUnitHeight})}), 512, 20);
}

// Pixel of a screen position at 512 lines (pixel p spans grid units [8p - 1, 8p + 7)).
std::pair<int, int> pixel_of(double xs, double ys) { return {int((grid_x(xs) + 1) / 8), int((grid_x(ys) + 1) / 8)}; }

// The largest difference of a component between an engine's pixel and the reference's: one sample
// of the pixel's 16 (255/16, the engines format a light's centre to whole grid units, so their
// disc may take a sample more or less than the reference's) and a step of rounding. Measured: 16.
constexpr int kAgreement = 17;

enum class Seen { kBackground, kRed, kWhite, kOther };

// What a pixel shows over the background (0, 13, 38): a red light adds red alone, a white one all
// three components alike.
Seen classify(const std::uint8_t* p) {
  const int r = p[0], g = p[1] - 13, b = p[2] - 38;
  if (r == 0 && g == 0 && b == 0) return Seen::kBackground;
  if (r >= 12 && g <= 0 && b <= 0) return Seen::kRed;
  if (r >= 12 && g >= r / 2 && b >= r / 2) return Seen::kWhite;
  return Seen::kOther;
}

const char* name_of(Seen s) {
  switch (s) {
    case Seen::kBackground:
      return "background";
    case Seen::kRed:
      return "red";
    case Seen::kWhite:
      return "white";
    case Seen::kOther:
      break;
  }
  return "other";
}

struct Probe {
  std::pair<int, int> pixel;
  Seen expected;
};

// The probes: every listed light's centre (red or white as listed), and where the light whose beam
// points away would be (listed without its beam): background.
std::vector<Probe> probes(const ScreenFrame& with_beam, const ScreenFrame& without_beam) {
  std::vector<Probe> out;
  for (const ScreenLightPoint& l : with_beam.light_points)
    out.push_back({pixel_of(l.xs, l.ys), l.colour == Rgb(1, 0, 0) ? Seen::kRed : Seen::kWhite});
  for (const ScreenLightPoint& l : without_beam.light_points) {
    const bool listed = std::any_of(with_beam.light_points.begin(), with_beam.light_points.end(),
                                    [&](const ScreenLightPoint& k) { return k.xs == l.xs && k.ys == l.ys; });
    if (!listed) out.push_back({pixel_of(l.xs, l.ys), Seen::kBackground});
  }
  return out;
}

TEST(DirectionalLights, EveryEngineShowsWhatStageBDecided) {
  const Scene scene = parse_scene(engines_scene(true).dump(), "engines.json");
  const Scene unbeamed = parse_scene(engines_scene(false).dump(), "engines_unbeamed.json");
  const ImageGenerator generator(scene), reference_generator(unbeamed);
  json report;
  const ScreenFrame f = generator.geometry(0, 0, report);
  const ScreenFrame g = reference_generator.geometry(0, 0, report);
  ASSERT_EQ(f.light_points.size(), 5u);  // four units and the beam towards the eye
  ASSERT_EQ(g.light_points.size(), 6u);
  const std::vector<Probe> points = probes(f, g);
  ASSERT_EQ(points.size(), 6u);
  EXPECT_EQ(std::count_if(points.begin(), points.end(), [](const Probe& p) { return p.expected == Seen::kRed; }), 2);

  const std::string judge = reference_engine_name();
  const RasterImage reference = generator.render(0, {0}, judge, {}, 1)[0].out;
  std::vector<std::string> drawn;
  for (const EngineInfo& e : engine_infos()) {
    if (!e.light_points) continue;
    drawn.push_back(e.name);
    SCOPED_TRACE(e.name);
    const RasterImage out = generator.render(0, {0}, e.name, {}, 1)[0].out;
    for (const Probe& p : points) {
      const std::uint8_t* px = out.image.at(p.pixel.first, p.pixel.second);
      const std::uint8_t* rx = reference.image.at(p.pixel.first, p.pixel.second);
      SCOPED_TRACE("pixel (" + std::to_string(p.pixel.first) + ", " + std::to_string(p.pixel.second) + ")");
      EXPECT_STREQ(name_of(classify(rx)), name_of(p.expected)) << "the reference";
      EXPECT_STREQ(name_of(classify(px)), name_of(p.expected));
      for (int c = 0; c < 3; ++c) EXPECT_NEAR(px[c], rx[c], kAgreement) << "component " << c;
    }
  }
  for (const char* name : {"float", "segment", "segment-double", "quadtree", "quadtree-double"})
    EXPECT_NE(std::find(drawn.begin(), drawn.end(), name), drawn.end()) << name;
}

}  // namespace
}  // namespace cig
