// Airport light points from apt.dat rows (cmodel/import/airport_lights.hpp): counts, spacings,
// colours by direction and PAPI settings against ICAO Annex 14 / FAA rules, the expected figures
// derived here from the rules, not from the generator.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <string>
#include <vector>

#include <glm/geometric.hpp>

#include "common/error.hpp"
#include "import/airport_lights.hpp"

namespace cig {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kHeading = 110;  // runway 11/29's true heading from end 11 to end 29

glm::dvec2 unit(double heading_deg) { return {std::sin(heading_deg * kPi / 180), std::cos(heading_deg * kPi / 180)}; }

// A length x 60 m precision runway 11/29: HIRL, centre line lights, TDZ and ALSF-II on 11.
Runway precision_runway(double length = 3054) {
  Runway r;
  r.width_m = 60;
  r.edge_lights = 3;
  r.centreline_lights = 1;
  r.ends[0].id = "11";
  r.ends[0].point = {1000, -500};
  r.ends[0].markings = 3;
  r.ends[0].approach_lights = 2;
  r.ends[0].touchdown_zone_lights = 1;
  r.ends[1].id = "29";
  r.ends[1].point = r.ends[0].point + length * unit(kHeading);
  r.ends[1].markings = 3;
  return r;
}

std::vector<AirportLight> select(const std::vector<AirportLight>& v, AirportLightType t, const std::string& end = "") {
  std::vector<AirportLight> out;
  for (const AirportLight& l : v)
    if (l.type == t && (end.empty() || l.runway_end == end)) out.push_back(l);
  return out;
}

// A light's place seen landing from end `from`: s metres past that end's point, y to the left.
struct Station {
  double s, y;
};
Station station(const Runway& r, int from, const glm::dvec3& p) {
  const glm::dvec2 o = r.ends[from].point, d = glm::normalize(r.ends[1 - from].point - o), left{-d.y, d.x};
  const glm::dvec2 q = glm::dvec2(p) - o;
  return {glm::dot(q, d), glm::dot(q, left)};
}

std::string colour_name(const Rgb& c) {
  if (c.r > 0.9 && c.g > 0.9 && c.b > 0.9) return "white";
  if (c.r > 0.9 && c.g < 0.1 && c.b < 0.1) return "red";
  if (c.r > 0.9 && c.g > 0.3 && c.b < 0.1) return "yellow";
  if (c.r < 0.1 && c.g > 0.5) return "green";
  return "other";
}

double heading_difference(double a, double b) { return std::fmod(a - b + 540.0, 360.0) - 180.0; }

TEST(AirportLights, CountsPerTypeOnAPrecisionRunway) {
  const double length = 3054, width = 60;
  const auto lights = runway_lights(precision_runway(length));
  // Edge: the runway in ceil(L / 60) equal intervals; the inner stations of each row carry edge
  // lights (the end stations are the threshold/end bars' outermost fixtures); 2 rows, 2 directions.
  const int edge_intervals = int(std::ceil(length / 60));  // 51
  EXPECT_EQ(select(lights, AirportLightType::runway_edge).size(), size_t(2 * 2 * (edge_intervals - 1)));
  // Threshold and end bars: across the edge rows (2 m outside the edges) at most 3 m apart on a
  // precision runway; at each undisplaced end the same fixtures show green and red.
  const int bar_lights = int(std::ceil((width + 2 * 2) / 3)) + 1;  // 23
  EXPECT_EQ(select(lights, AirportLightType::threshold).size(), size_t(2 * bar_lights));
  EXPECT_EQ(select(lights, AirportLightType::runway_end).size(), size_t(2 * bar_lights));
  // Centre line: ceil(L / 15) intervals, the inner stations, both directions.
  EXPECT_EQ(select(lights, AirportLightType::centreline).size(), size_t(2 * (int(std::ceil(length / 15)) - 1)));
  // TDZ on 11: rows every 30 m from 30 m to 900 m, two barrettes of three.
  EXPECT_EQ(select(lights, AirportLightType::touchdown_zone, "11").size(), size_t(900 / 30 * 2 * 3));
  EXPECT_TRUE(select(lights, AirportLightType::touchdown_zone, "29").empty());
  // ALSF-II on 11: 5-light barrettes every 30 m to 900 m, flashers every 30 m from 300 m, the 300 m
  // crossbar (8 a side), the 150 m crossbar (4 a side), red side rows (3 a side every 30 m to 270 m).
  const int alsf2 = 900 / 30 * 5 + (900 - 300) / 30 + 1 + 2 * 8 + 2 * 4 + 270 / 30 * 2 * 3;
  EXPECT_EQ(select(lights, AirportLightType::approach, "11").size(), size_t(alsf2));
  EXPECT_TRUE(select(lights, AirportLightType::approach, "29").empty());
  EXPECT_TRUE(select(lights, AirportLightType::reil).empty());
  for (const AirportLight& l : lights) {
    EXPECT_TRUE(l.runway_end == "11" || l.runway_end == "29") << l.runway_end;
    EXPECT_TRUE(l.intensity > 0 && l.intensity <= 1) << to_string(l.type);
  }
}

TEST(AirportLights, EdgeLightsAreUniformAtMost60mApartAtTheEdge) {
  const double length = 3054, width = 60;
  const Runway r = precision_runway(length);
  const auto lights = runway_lights(r);
  for (int side : {1, -1}) {
    std::vector<double> s;
    for (const AirportLight& l : select(lights, AirportLightType::runway_edge, "11")) {
      const Station st = station(r, 0, l.position);
      if (st.y * side < 0) continue;
      EXPECT_GE(std::abs(st.y), width / 2);  // 5.3.9: at the edge or at most 3 m outside
      EXPECT_LE(std::abs(st.y), width / 2 + 3);
      s.push_back(st.s);
    }
    std::sort(s.begin(), s.end());
    ASSERT_FALSE(s.empty());
    s.insert(s.begin(), 0);  // the bars' fixtures at the two ends, in line with the row
    s.push_back(length);
    const double step = s[1] - s[0];
    EXPECT_LE(step, 60);
    for (size_t i = 1; i < s.size(); ++i) EXPECT_NEAR(s[i] - s[i - 1], step, 1e-6) << "station " << i;
  }
  // The outermost bar fixtures stand in the rows.
  double outer = 0;
  for (const AirportLight& l : select(lights, AirportLightType::threshold, "11"))
    outer = std::max(outer, std::abs(station(r, 0, l.position).y));
  const double row = std::abs(station(r, 0, select(lights, AirportLightType::runway_edge)[0].position).y);
  EXPECT_NEAR(outer, row, 1e-6);
  // Beams toward the approach, toed in 4.5 deg on a 60 m runway (Annex 14 App. 2 Fig. A2-10).
  for (const AirportLight& l : select(lights, AirportLightType::runway_edge, "11")) {
    ASSERT_TRUE(l.beam.directional);
    const double toe = heading_difference(l.beam.heading_deg, kHeading + 180);
    const bool left = station(r, 0, l.position).y > 0;
    EXPECT_NEAR(toe, left ? -4.5 : 4.5, 1e-9) << "toward the centre line";
    EXPECT_DOUBLE_EQ(l.beam.elevation_deg, 3.5);
  }
}

TEST(AirportLights, CautionZoneIsTheLast600mOrAThird) {
  for (double length : {3054.0, 1200.0}) {
    const Runway r = precision_runway(length);
    const double zone = std::min(600.0, length / 3);
    int yellow = 0;
    for (int k : {0, 1})
      for (const AirportLight& l : select(runway_lights(r), AirportLightType::runway_edge, r.ends[k].id)) {
        const double to_end = length - station(r, k, l.position).s;
        const std::string c = colour_name(l.colour);
        EXPECT_EQ(c, to_end <= zone + 1e-6 ? "yellow" : "white") << "length " << length << " to end " << to_end;
        yellow += c == "yellow";
      }
    EXPECT_GT(yellow, 0);
  }
  // A visual runway (markings 1) has no caution zone.
  Runway visual = precision_runway(1200);
  visual.ends[0].markings = visual.ends[1].markings = 1;
  for (const AirportLight& l : select(runway_lights(visual), AirportLightType::runway_edge))
    EXPECT_EQ(colour_name(l.colour), "white");
}

TEST(AirportLights, DisplacedThresholdShowsRedTowardTheApproach) {
  const double length = 3054, displaced = 300;
  Runway r = precision_runway(length);
  r.ends[0].displaced_threshold_m = displaced;
  const auto lights = runway_lights(r);
  std::vector<double> stations;
  for (const AirportLight& l : select(lights, AirportLightType::runway_edge, "11")) {
    const double s = station(r, 0, l.position).s;
    const char* expected = s < displaced - 1e-6 ? "red" : length - s <= 600 + 1e-6 ? "yellow" : "white";
    EXPECT_EQ(colour_name(l.colour), expected) << s;
    if (station(r, 0, l.position).y > 0) stations.push_back(s);
  }
  // The same fixtures seen landing on 29: the displaced part is runway, in its caution zone.
  for (const AirportLight& l : select(lights, AirportLightType::runway_edge, "29")) {
    if (station(r, 0, l.position).s < displaced) { EXPECT_EQ(colour_name(l.colour), "yellow"); }
  }
  std::sort(stations.begin(), stations.end());
  EXPECT_TRUE(std::any_of(stations.begin(), stations.end(), [&](double s) { return std::abs(s - displaced) < 1e-6; }));
  for (size_t i = 1; i < stations.size(); ++i) EXPECT_LE(stations[i] - stations[i - 1], 60 + 1e-9);
  // Green threshold bar at the displaced threshold, red end bar at the runway's end.
  for (const AirportLight& l : select(lights, AirportLightType::threshold, "11"))
    EXPECT_NEAR(station(r, 0, l.position).s, displaced, 1e-6);
  for (const AirportLight& l : select(lights, AirportLightType::runway_end, "29"))
    EXPECT_NEAR(station(r, 0, l.position).s, 0, 1e-6);
  // TDZ and approach lights count from the landing threshold.
  double first_tdz = 1e9, nearest_als = 1e9;
  for (const AirportLight& l : select(lights, AirportLightType::touchdown_zone, "11"))
    first_tdz = std::min(first_tdz, station(r, 0, l.position).s);
  for (const AirportLight& l : select(lights, AirportLightType::approach, "11"))
    nearest_als = std::min(nearest_als, displaced - station(r, 0, l.position).s);
  EXPECT_NEAR(first_tdz, displaced + 30, 1e-6);
  EXPECT_NEAR(nearest_als, 30, 1e-6);
}

TEST(AirportLights, ThresholdGreenTowardTheApproachEndRedTowardTheRunway) {
  const Runway r = precision_runway();
  const auto lights = runway_lights(r);
  for (int k : {0, 1}) {
    const double approach_heading = k == 0 ? kHeading : kHeading + 180;  // landing direction on end k
    const auto green = select(lights, AirportLightType::threshold, r.ends[k].id);
    const auto red = select(lights, AirportLightType::runway_end, r.ends[1 - k].id);  // seen landing on the other end
    ASSERT_EQ(green.size(), red.size());
    ASSERT_GE(green.size(), 6u);
    for (size_t i = 0; i < green.size(); ++i) {
      EXPECT_EQ(colour_name(green[i].colour), "green");
      EXPECT_EQ(colour_name(red[i].colour), "red");
      EXPECT_NEAR(glm::length(glm::dvec2(green[i].position - red[i].position)), 0, 1e-6) << "one fixture";
      EXPECT_NEAR(station(r, k, green[i].position).s, 0, 1e-6);
      // Beams opposite: green back toward the approach (toed in at most 3.5 deg), red down the runway.
      EXPECT_LE(std::abs(heading_difference(green[i].beam.heading_deg, approach_heading + 180)), 3.5 + 1e-9);
      EXPECT_NEAR(heading_difference(red[i].beam.heading_deg, approach_heading), 0, 1e-9);
    }
    // At most 3 m apart (precision runway), uniformly.
    std::vector<double> y;
    for (const AirportLight& l : green) y.push_back(station(r, k, l.position).y);
    std::sort(y.begin(), y.end());
    for (size_t i = 1; i < y.size(); ++i) {
      EXPECT_LE(y[i] - y[i - 1], 3 + 1e-9);
      EXPECT_NEAR(y[i] - y[i - 1], y[1] - y[0], 1e-6);
    }
  }
}

// The colours of one direction's centre line, ordered from its threshold to the far end, with
// their distances to the far end.
std::vector<std::pair<double, std::string>> centreline(const Runway& r, int k) {
  std::vector<std::pair<double, std::string>> v;
  const double length = glm::length(r.ends[1].point - r.ends[0].point);
  for (const AirportLight& l : select(runway_lights(r), AirportLightType::centreline, r.ends[k].id))
    v.push_back({length - station(r, k, l.position).s, colour_name(l.colour)});
  std::sort(v.begin(), v.end(), [](const auto& a, const auto& b) { return a.first > b.first; });
  return v;
}

TEST(AirportLights, CentrelineIsWhiteThenAlternatesFrom900mThenRedFrom300m) {
  const Runway r = precision_runway(3054);
  for (int k : {0, 1}) {
    const auto v = centreline(r, k);
    ASSERT_FALSE(v.empty());
    int reds = 0, whites = 0;
    for (size_t i = 0; i < v.size(); ++i) {
      const double to_end = v[i].first;
      const std::string& c = v[i].second;
      if (to_end > 900 + 1e-6) {
        EXPECT_EQ(c, "white") << to_end;
      } else if (to_end > 300 + 1e-6) {
        if (i > 0 && v[i - 1].first <= 900 + 1e-6) { EXPECT_NE(c, v[i - 1].second) << "alternate at " << to_end; }
        reds += c == "red";
        whites += c == "white";
      } else {
        EXPECT_EQ(c, "red") << to_end;
      }
    }
    EXPECT_LE(std::abs(reds - whites), 1);
    EXPECT_GT(reds, 15);
    for (size_t i = 1; i < v.size(); ++i) EXPECT_LE(v[i - 1].first - v[i].first, 15 + 1e-9);
  }
  // Shorter than 1800 m: alternating from the midpoint (750 m) to 300 m.
  const auto v = centreline(precision_runway(1500), 0);
  for (size_t i = 1; i < v.size(); ++i) {
    if (v[i].first > 300 + 1e-6 && v[i].first <= 750 + 1e-6 && v[i - 1].first <= 750 + 1e-6) {
      EXPECT_NE(v[i].second, v[i - 1].second) << v[i].first;
    }
  }
  for (const auto& [to_end, c] : v) {
    if (to_end > 750 + 1e-6) { EXPECT_EQ(c, "white") << to_end; }
  }
}

TEST(AirportLights, TouchdownZoneBarrettes) {
  const Runway r = precision_runway();
  std::map<long, std::vector<double>> rows;  // station (m) -> lateral offsets
  for (const AirportLight& l : select(runway_lights(r), AirportLightType::touchdown_zone, "11")) {
    const Station st = station(r, 0, l.position);
    rows[std::lround(st.s)].push_back(st.y);
    EXPECT_EQ(colour_name(l.colour), "white");
    EXPECT_LE(std::abs(heading_difference(l.beam.heading_deg, kHeading + 180)), 4 + 1e-9);
  }
  ASSERT_EQ(rows.size(), 30u);
  EXPECT_EQ(rows.begin()->first, 30);
  EXPECT_EQ(rows.rbegin()->first, 900);
  for (auto& [s, y] : rows) {
    std::sort(y.begin(), y.end());
    const std::vector<double> expected{-12, -10.5, -9, 9, 10.5, 12};  // inner gap 18 m, 1.5 m apart
    ASSERT_EQ(y.size(), expected.size());
    for (size_t i = 0; i < y.size(); ++i) EXPECT_NEAR(y[i], expected[i], 1e-6) << "row " << s;
  }
}

TEST(AirportLights, ApproachSystemsByCode) {
  // Expected counts from each system's layout (see the comments of airport_lights.cpp's ALS part).
  const int barrettes30 = 900 / 30 * 5, flashers30 = (900 - 300) / 30 + 1;
  const int calvert_bars = 2 * (3 + 8 + 13 + 18 + 23);  // half-lengths 7.5 .. 37.5 m, from 4.5 m 1.5 m apart
  const std::map<int, std::pair<int, int>> expected{    // code -> lights, flashing
                                                    {1, {barrettes30 + flashers30 + 16 + 6 + 10, flashers30}},
                                                    {2, {barrettes30 + flashers30 + 16 + 8 + 54, flashers30}},
                                                    {3, {10 * 1 + 10 * 2 + 10 * 3 + calvert_bars, 0}},
                                                    {4, {10 * 5 + 54 + 10 * 2 + 10 * 3 + calvert_bars, 0}},
                                                    {5, {7 * 5 + 10 + 5, 5}},
                                                    {6, {7 * 5 + 10 + 3, 3}},
                                                    {7, {15 * 5 + 16 + 6 + 10, 0}},
                                                    {8, {7 * 5 + 10 + 5, 5}},
                                                    {9, {7 * 5 + 10 + 3, 3}},
                                                    {10, {7 * 5 + 10, 0}},
                                                    {11, {7, 7}},
                                                    {12, {5, 5}}};
  for (const auto& [code, counts] : expected) {
    Runway r = precision_runway();
    r.ends[1].approach_lights = code;  // on 29
    const auto als = select(runway_lights(r), AirportLightType::approach, "29");
    EXPECT_EQ(int(als.size()), counts.first) << "code " << code;
    int flashing = 0;
    for (const AirportLight& l : als) {
      flashing += l.flashing;
      const Station st = station(r, 1, l.position);
      EXPECT_LE(st.s, 1e-6) << "code " << code << ": before the threshold";
      EXPECT_GE(st.s, -900 - 1e-6) << "code " << code;
      if (!l.beam.directional) continue;  // ODALS
      EXPECT_LE(std::abs(heading_difference(l.beam.heading_deg, kHeading)), 2 + 1e-9) << "toward the approach";
      EXPECT_GE(l.beam.elevation_deg, 5.5);
      EXPECT_LE(l.beam.elevation_deg, 8);
    }
    EXPECT_EQ(flashing, counts.second) << "code " << code;
  }
}

TEST(AirportLights, ReilAbeamTheThreshold12mOutsideTheEdges) {
  Runway r = precision_runway();
  r.ends[0].reil = 1;
  r.ends[1].reil = 2;
  const auto lights = runway_lights(r);
  for (int k : {0, 1}) {
    const auto reil = select(lights, AirportLightType::reil, r.ends[k].id);
    ASSERT_EQ(reil.size(), 2u);
    for (const AirportLight& l : reil) {
      const Station st = station(r, k, l.position);
      EXPECT_NEAR(st.s, 0, 1e-6);
      EXPECT_NEAR(std::abs(st.y), 30 + 12, 1e-6);
      EXPECT_TRUE(l.flashing);
      EXPECT_EQ(l.beam.directional, k == 1);
    }
  }
}

TEST(AirportLights, PapiUnitsAt9mFrom15mOutsideTheEdgeOnTheirSide) {
  const Runway r = precision_runway();
  for (int k : {0, 1})
    for (bool left : {true, false}) {
      const LightObject o = standard_papi(r, k, left, 300, 3.0);
      EXPECT_EQ(o.type, left ? 2 : 3);
      const auto units = light_object_lights(o);
      ASSERT_EQ(units.size(), 4u);
      const double settings[4] = {3.5, 3 + 1.0 / 6, 3 - 1.0 / 6, 2.5};  // from the runway outward
      for (int i = 0; i < 4; ++i) {
        const AirportLight& u = units[i];
        const Station st = station(r, k, u.position);
        EXPECT_EQ(u.type, AirportLightType::papi);
        EXPECT_EQ(u.runway_end, r.ends[k].id);
        EXPECT_NEAR(st.s, 300, 1e-6) << "on a line across the runway";
        EXPECT_NEAR(std::abs(st.y), 30 + 15 + 9 * i, 1e-6) << "unit " << i;
        EXPECT_GT(left ? st.y : -st.y, 0) << "on the pilot's " << (left ? "left" : "right");
        EXPECT_TRUE(u.has_below);
        EXPECT_NEAR(u.below_elevation_deg, settings[i], 1e-9);
        EXPECT_EQ(colour_name(u.colour), "white");
        EXPECT_EQ(colour_name(u.below_colour), "red");
        EXPECT_NEAR(heading_difference(u.beam.heading_deg, (k == 0 ? kHeading : kHeading + 180) + 180), 0, 1e-9);
      }
    }
}

TEST(AirportLights, PapiFromAnAptDatRow) {
  // BIKF's "21 63.98559030 -022.64803812 2 89.97 3.00 11 PAPI-4L": heading about east, so the bar
  // is north of runway 11 and its unit nearest the runway 13.5 m south of the point.
  LightObject o;
  o.point = {100, 200};
  o.type = 2;
  o.heading_deg = 89.97;
  o.glideslope_deg = 3;
  o.runway_end = "11";
  auto units = light_object_lights(o);
  ASSERT_EQ(units.size(), 4u);
  const glm::dvec2 right = unit(89.97 + 90);
  for (int i = 0; i < 4; ++i) {
    EXPECT_NEAR(glm::dot(glm::dvec2(units[i].position) - o.point, right), 13.5 - 9 * i, 1e-6);
    EXPECT_NEAR(units[i].beam.heading_deg, 269.97, 1e-9);
    EXPECT_NEAR(units[i].beam.elevation_deg, 3, 1e-9);
  }
  o.type = 3;  // PAPI-4R: the runway to the bar's left
  units = light_object_lights(o);
  ASSERT_EQ(units.size(), 4u);
  EXPECT_NEAR(glm::dot(glm::dvec2(units[0].position) - o.point, right), -13.5, 1e-6);
}

TEST(AirportLights, VasiTwoBars) {
  LightObject o;
  o.point = {0, 0};
  o.type = 1;
  o.heading_deg = 0;
  o.glideslope_deg = 3;
  const auto bars = light_object_lights(o);
  ASSERT_EQ(bars.size(), 2u);
  EXPECT_LT(bars[0].position.y, bars[1].position.y) << "downwind bar first";
  EXPECT_NEAR(bars[0].below_elevation_deg, 2.5, 1e-9);
  EXPECT_NEAR(bars[1].below_elevation_deg, 3.5, 1e-9);
  for (const AirportLight& b : bars) EXPECT_EQ(b.type, AirportLightType::vasi);
}

TEST(AirportLights, OtherLightObjectsGiveNothing) {
  for (int type : {0, 4, 5, 6, 7}) {
    LightObject o;
    o.type = type;
    o.glideslope_deg = 0;  // not read for them
    EXPECT_TRUE(light_object_lights(o).empty()) << type;
  }
  EXPECT_STREQ(to_string(AirportLightType::runway_edge), "runway_edge");
  EXPECT_STREQ(to_string(AirportLightType::touchdown_zone), "touchdown_zone");
  EXPECT_STREQ(to_string(AirportLightType::vasi), "vasi");
}

TEST(AirportLights, CrossingRunwayRemovesTheEdgeLightsOnItsPavement) {
  // 09/27: 3000 m east from (0, 0), edge stations every 60 m; 18/36 60 m wide crossing at x = 2400:
  // one station per row (x = 2400) lies on it, the next ones (2340, 2460) 30 m beyond its edges.
  Runway r;
  r.width_m = 45;
  r.edge_lights = 2;
  r.ends[0].id = "09";
  r.ends[0].point = {0, 0};
  r.ends[1].id = "27";
  r.ends[1].point = {3000, 0};
  Runway crossing;
  crossing.width_m = 60;
  crossing.ends[0].id = "18";
  crossing.ends[0].point = {2400, 1000};
  crossing.ends[1].id = "36";
  crossing.ends[1].point = {2400, -1000};
  auto lights = runway_lights(r);
  const size_t edge = select(lights, AirportLightType::runway_edge).size();
  EXPECT_EQ(remove_edge_lights_on(lights, crossing), 2u * 2u);  // 2 rows, 2 directions
  EXPECT_EQ(select(lights, AirportLightType::runway_edge).size(), edge - 4);
  for (const AirportLight& l : select(lights, AirportLightType::runway_edge))
    EXPECT_GT(std::abs(l.position.x - 2400), 30);
  EXPECT_EQ(select(lights, AirportLightType::threshold).size(),
            select(runway_lights(r), AirportLightType::threshold).size());
}

std::string error_of(const Runway& r) {
  try {
    runway_lights(r);
  } catch (const InputError& e) { return e.what(); }
  return "";
}

TEST(AirportLights, DegenerateRunwaysAreInputErrors) {
  Runway r = precision_runway();
  r.ends[1].point = r.ends[0].point;
  EXPECT_EQ(error_of(r), "runway 11/29: length 0 m is below 10 m (are its two ends' points the same?)");
  r = precision_runway();
  r.width_m = 0;
  EXPECT_NE(error_of(r).find("width 0 m"), std::string::npos) << error_of(r);
  r = precision_runway();
  r.ends[0].point.x = std::nan("");
  EXPECT_NE(error_of(r).find("end 11: its point is not finite"), std::string::npos) << error_of(r);
  r = precision_runway(1000);
  r.ends[0].displaced_threshold_m = 600;
  r.ends[1].displaced_threshold_m = 400;
  EXPECT_NE(error_of(r).find("leave none of its 1000 m"), std::string::npos) << error_of(r);
  r = precision_runway();
  r.ends[1].approach_lights = 13;
  EXPECT_NE(error_of(r).find("end 29: approach lighting code 13"), std::string::npos) << error_of(r);
  LightObject o;
  o.type = 2;
  o.glideslope_deg = 0;
  EXPECT_THROW(light_object_lights(o), InputError);
  EXPECT_THROW(standard_papi(precision_runway(), 2, true, 300), InputError);
}

}  // namespace
}  // namespace cig
