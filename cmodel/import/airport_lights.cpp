// Runway and light-object rows of apt.dat 1000 to light points (airport_lights.hpp). References:
// ICAO Annex 14 Vol. I, chapter 5 (5.3.4 approach lighting, 5.3.5 PAPI, 5.3.9 runway edge, 5.3.10
// threshold, 5.3.11 runway end, 5.3.12 centre line, 5.3.13 touchdown zone lights) and Appendix 2
// (isocandela figures A2-1 to A2-10); FAA AC 150/5340-30 for the US approach systems (ALSF, SSALx,
// MALSx, ODALS, RAIL) and REIL; the X-Plane apt.dat 1000 specification for the codes.
#include "import/airport_lights.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>

#include <glm/geometric.hpp>

#include "common/error.hpp"

namespace cig {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kEps = 1e-6;  // metres: a station on a rule's boundary counts as inside it

// ---- Colours: linear-RGB stand-ins for the aeronautical ground light colours (Annex 14 App. 1).
const Rgb kWhite{1, 1, 1};
const Rgb kRed{1, 0, 0};
const Rgb kGreen{0, 0.9, 0.45};
const Rgb kYellow{1, 0.7, 0};

// ---- Heights above the surface: elevated fixtures (frangible, at most about 0.35 m: 5.3.1), inset
// lights flush with the pavement, PAPI/VASI lenses.
constexpr double kElevatedHeightM = 0.35;
constexpr double kInsetHeightM = 0.02;
constexpr double kFlasherAboveM = 0.5;  // a sequenced flasher above its barrette's centre light
constexpr double kPapiHeightM = 0.6;

// ---- Runway validity (not a standard: what the layout needs to be meaningful).
constexpr double kMinRunwayLengthM = 10;
constexpr double kMaxRunwayWidthM = 300;

// ---- Runway edge lights (5.3.9).
constexpr double kEdgeMaxSpacingM = 60;  // uniform, at most 60 m apart (instrument runways)
constexpr double kEdgeOffsetM = 2;       // at the edge or at most 3 m outside it
constexpr double kCautionZoneM = 600;    // yellow over the last 600 m or third of the runway, the lesser
constexpr double kEdgeIntensity[4] = {0, 0.3, 0.6, 1.0};  // apt.dat: none, LIRL, MIRL, HIRL
constexpr double kWideRunwayM = 52.5;                     // App. 2: Fig. A2-9 for 45 m wide runways, A2-10 for 60 m

// ---- Threshold (5.3.10) and runway end (5.3.11) lights.
constexpr double kThresholdSpacingPrecisionM = 3;  // precision approach runways: at most 3 m apart
constexpr double kThresholdSpacingOtherM = 6;      // other runways (chosen): uniform, at most 6 m apart
constexpr double kEndSpacingM = 6;                 // end lights: at most 6 m apart (Cat III)
constexpr int kMinBarLights = 6;                   // at least six threshold / end lights

// ---- Runway centre line lights (5.3.12): 15 m apart (Cat III; 30 m is allowed below); white,
// alternately red and white from 900 m to 300 m before the end, red over the last 300 m; runways
// shorter than 1800 m alternate from the midpoint of the length available for landing.
constexpr double kCentrelineSpacingM = 15;
constexpr double kCentrelineAlternateM = 900;
constexpr double kCentrelineRedM = 300;
constexpr double kCentrelineShortRunwayM = 1800;

// ---- Touchdown zone lights (5.3.13): pairs of barrettes from the threshold to 900 m (FAA: to the
// runway's midpoint at most, first row 100 ft = 30 m past the threshold); 30 m between rows; each
// barrette at least 3 lights at most 1.5 m apart; the inner lights of a pair the touchdown zone
// marking's gauge apart (18 to 22.5 m).
constexpr double kTdzExtentM = 900;
constexpr double kTdzRowSpacingM = 30;
constexpr int kTdzBarretteLights = 3;
constexpr double kTdzLightSpacingM = 1.5;
constexpr double kTdzInnerGapM = 18;

// ---- REIL (FAA AC 150/5340-30): two flashing white lights abeam the threshold, 40 ft (12 m)
// outside the runway edges; apt.dat 1 omnidirectional, 2 unidirectional.
constexpr double kReilOutsideEdgeM = 12;

// ---- Approach lighting (5.3.4; FAA AC 150/5340-30). Distances d are from the landing
// threshold outward, y across (+ left of the landing direction).
constexpr double kBarretteLightSpacingM = 1.0;                    // 5 lights: a barrette at least 4 m long (5.3.4)
constexpr double kAlsfLengthM = 900;                              // ICAO Cat II/III and FAA's 3000 ft ALSF
constexpr double kSalsLengthM = 450;                              // FAA SALS: the inner 1500 ft of ALSF-I
constexpr double kAlsfSpacingM = 30;                              // 100 ft between ALSF/Calvert centre line stations
constexpr double kSsalSpacingM = 60;                              // 200 ft between SSALx/MALSx stations ...
constexpr double kSsalLengthM = 420;                              // ... out to 1400 ft
constexpr double kRailFromM = 480, kRailToM = 720;                // RAIL flashers 1600 ft to 2400 ft, 200 ft apart
constexpr double kCrossbarM = 300, kCrossbarHalfM = 15;           // the 1000 ft crossbar, 30 m long (5.3.4 Cat I)
constexpr double kCrossbarInnerM = 4.5, kCrossbarStepM = 1.5;     // crossbar lights from 4.5 m out
constexpr double kAlsf2BarM = 150, kAlsf2BarHalfM = 9;            // ALSF-II 500 ft crossbar: 4 lights a side
constexpr double kTerminatingBarM = 60, kTerminatingHalfM = 7.5;  // ALSF-I/SALS 200 ft red bar: 3 a side
constexpr double kPreThresholdBarM = 30, kPreThresholdStepM = 1;  // 100 ft red bar: 5 a side from the edge
constexpr int kPreThresholdLights = 5;
constexpr double kSideRowToM = 270;      // ALSF-II red side rows, 100 ft to 900 ft
constexpr double kCalvertCodingM = 300;  // Calvert centre line: 1, 2, 3 sources per 300 m
constexpr double kCalvertSourceSpacingM = 1.5;
constexpr double kCalvertBarSpacingM = 150;   // five crossbars, 150 m to 750 m ...
constexpr double kCalvertBarHalfPerM = 0.05;  // ... their half-length 5 % of their distance
constexpr double kOdalsSpacingM = 90;         // ODALS: five flashers 300 ft apart from 300 ft
constexpr double kMediumIntensity = 0.6;      // MALS, MALSF, MALSR

// ---- PAPI (5.3.5, Figure 5-20): four units 9 m apart, the inner one 15 m outside the runway edge;
// transition angles from the runway outward: glide slope + 30', + 10', - 10', - 30'.
constexpr double kPapiUnitSpacingM = 9;
constexpr double kPapiInnerFromEdgeM = 15;
constexpr double kPapiSettingsDeg[4] = {0.5, 1.0 / 6, -1.0 / 6, -0.5};
// VASI (FAA two-bar): the downwind bar set 0.5 deg below the glide slope, the upwind bar 0.5 deg
// above, the bars about 700 ft apart along the runway, the apt.dat point midway.
constexpr double kVasiBarSpacingM = 213;
constexpr double kVasiSettingDeg = 0.5;

// apt.dat codes.
enum AlsCode {
  kNoAls,
  kAlsf1,
  kAlsf2,
  kCalvert,
  kCalvert2,
  kSsalr,
  kSsalf,
  kSals,
  kMalsr,
  kMalsf,
  kMals,
  kOdals,
  kRail
};
enum ObjectCode { kVasi = 1, kPapiLeft = 2, kPapiRight = 3 };

// ---- Beams. Half-widths: each Appendix 2 figure's outer (10 %) isocandela ellipse, where the
// model's f = 1 - r^2 reaches zero; elevations: the main beam's centre (edge 3.5, threshold 5.5,
// end 2.5 deg, as elevated fixtures build them in); toe-in toward the centre line.
struct BeamSpec {
  double elevation_deg, horizontal_deg, vertical_deg, toe_in_deg;
};
constexpr BeamSpec kEdgeBeam45{3.5, 9.0, 8.5, 3.5};     // Fig. A2-9: a 5.5/7.5/9.0, b 3.5/6.0/8.5
constexpr BeamSpec kEdgeBeam60{3.5, 10.0, 8.5, 4.5};    // Fig. A2-10: a 6.5/8.5/10.0, b 3.5/6.0/8.5
constexpr BeamSpec kThresholdBeam{5.5, 9.0, 8.5, 3.5};  // Fig. A2-3: a 5.5/7.5/9.0, b 4.5/6.0/8.5
constexpr BeamSpec kEndBeam{2.5, 9.0, 6.5, 0};          // Fig. A2-8: a 6.0/7.5/9.0, b 2.25/5.0/6.5
constexpr BeamSpec kCentrelineBeam{3.5, 9.0, 8.5, 0};   // Fig. A2-6/A2-7 (about 9 x 8.5 deg)
constexpr BeamSpec kTdzBeam{3.5, 8.5, 8.5, 4.0};        // Fig. A2-5: a 5.0/7.0/8.5, b 3.5/6.0/8.5
constexpr BeamSpec kReilBeam{10, 15, 10, -15};          // FAA: aimed 15 deg outward, 10 deg up (chosen widths)
constexpr BeamSpec kPapiBeam{0, 10, 5, 0};              // elevation: the glide slope (chosen widths)
// Approach lights, Fig. A2-1 (a 10/14/15, b 5.5/6.5/8.5) and side rows, Fig. A2-2 (a 7/11.5/16.5,
// b 5/6/8, toe-in 2): the main beam's vertical coverage rises with the distance from the threshold.
constexpr double kApproachHalfWidthDeg[2] = {15, 8.5}, kSideRowHalfWidthDeg[2] = {16.5, 8.0};
constexpr double kSideRowToeInDeg = 2, kCrossbarToeInDeg = 2, kCrossbarToeInBeyondM = 22.5;

double approach_elevation_deg(double d) {  // Fig. A2-1 note: 0-11, 0.5-11.5, 1.5-12.5, 2.5-13.5 deg
  return d <= 315 ? 5.5 : d <= 475 ? 6.0 : d <= 640 ? 7.0 : 8.0;
}
double side_row_elevation_deg(double d) {  // Fig. A2-2 note: 0.5-10.5, 1-11, 1.5-11.5 deg
  return d <= 115 ? 5.5 : d <= 215 ? 6.0 : 6.5;
}

// One landing direction: toward the other end, threshold at `threshold` past `origin`.
struct Approach {
  const RunwayEnd* end = nullptr;       // the end landed on: its approach, markings, lights
  glm::dvec2 origin{0, 0};              // its apt.dat point (the runway's physical end)
  glm::dvec2 along{0, 1}, left{-1, 0};  // unit landing direction and the pilot's left
  double length = 0, threshold = 0;     // end to end; the displaced threshold from origin
  bool precision = false, instrument = false;
  glm::dvec2 at(double s, double y) const { return origin + s * along + y * left; }
  glm::dvec2 inward(double y) const { return y > kEps ? -left : y < -kEps ? left : glm::dvec2(0, 0); }
};

double heading_of(glm::dvec2 d) {
  const double h = std::atan2(d.x, d.y) * 180 / kPi;
  return h < 0 ? h + 360 : h;
}

glm::dvec2 unit_of_heading(double heading_deg) {
  const double h = heading_deg * kPi / 180;
  return {std::sin(h), std::cos(h)};
}

// A beam along `axis` (horizontal), turned by the spec's toe-in toward `inward` (zero: none).
AirportLightBeam aim(glm::dvec2 axis, glm::dvec2 inward, const BeamSpec& s, double elevation_deg) {
  const double t = s.toe_in_deg * kPi / 180;
  AirportLightBeam b;
  b.directional = true;
  b.heading_deg = heading_of(axis * std::cos(t) + inward * std::sin(t));
  b.elevation_deg = elevation_deg;
  b.horizontal_deg = s.horizontal_deg;
  b.vertical_deg = s.vertical_deg;
  return b;
}
AirportLightBeam aim(glm::dvec2 axis, glm::dvec2 inward, const BeamSpec& s) {
  return aim(axis, inward, s, s.elevation_deg);
}

AirportLight make_light(AirportLightType type, const std::string& end, glm::dvec2 p, double z, const Rgb& colour,
                        double intensity, const AirportLightBeam& beam) {
  AirportLight l;
  l.type = type;
  l.runway_end = end;
  l.position = {p.x, p.y, z};
  l.colour = colour;
  l.intensity = intensity;
  l.beam = beam;
  return l;
}

std::string number(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", v);
  return buf;
}

void validate(const Runway& r) {
  const std::string where = "runway " + r.ends[0].id + "/" + r.ends[1].id;
  auto require = [&](bool ok, const std::string& rule) {
    if (!ok) throw InputError("", where, rule);
  };
  require(std::isfinite(r.width_m) && r.width_m > 0 && r.width_m <= kMaxRunwayWidthM,
          "width " + number(r.width_m) + " m is not in (0, " + number(kMaxRunwayWidthM) + "] m");
  require(r.edge_lights >= 0 && r.edge_lights <= 3,
          "edge lighting code " + std::to_string(r.edge_lights) + " is not one of apt.dat's 0..3");
  require(r.centreline_lights == 0 || r.centreline_lights == 1,
          "centre line lighting code " + std::to_string(r.centreline_lights) + " is not 0 or 1");
  for (const RunwayEnd& e : r.ends) {
    const std::string at = "end " + e.id + ": ";
    require(std::isfinite(e.point.x) && std::isfinite(e.point.y), at + "its point is not finite");
    require(std::isfinite(e.displaced_threshold_m) && e.displaced_threshold_m >= 0,
            at + "displaced threshold " + number(e.displaced_threshold_m) + " m is not a length");
    require(std::isfinite(e.blast_pad_m) && e.blast_pad_m >= 0,
            at + "blast pad " + number(e.blast_pad_m) + " m is not a length");
    require(e.approach_lights >= kNoAls && e.approach_lights <= kRail,
            at + "approach lighting code " + std::to_string(e.approach_lights) + " is not one of apt.dat's 0..12");
    require(e.touchdown_zone_lights == 0 || e.touchdown_zone_lights == 1,
            at + "touchdown zone lighting code " + std::to_string(e.touchdown_zone_lights) + " is not 0 or 1");
    require(e.reil >= 0 && e.reil <= 2, at + "REIL code " + std::to_string(e.reil) + " is not one of apt.dat's 0..2");
  }
  const double length = glm::length(r.ends[1].point - r.ends[0].point);
  require(length >= kMinRunwayLengthM, "length " + number(length) + " m is below " + number(kMinRunwayLengthM) +
                                           " m (are its two ends' points the same?)");
  const double displaced = r.ends[0].displaced_threshold_m + r.ends[1].displaced_threshold_m;
  require(displaced < length, "displaced thresholds (" + number(displaced) + " m together) leave none of its " +
                                  number(length) + " m to land on");
}

std::array<Approach, 2> approaches(const Runway& r) {
  validate(r);
  std::array<Approach, 2> a;
  const glm::dvec2 d = r.ends[1].point - r.ends[0].point;
  for (int k : {0, 1}) {
    Approach& ak = a[k];
    ak.end = &r.ends[k];
    ak.origin = r.ends[k].point;
    ak.length = glm::length(d);
    ak.along = (k == 0 ? d : -d) / ak.length;
    ak.left = {-ak.along.y, ak.along.x};
    ak.threshold = r.ends[k].displaced_threshold_m;
    ak.precision = r.ends[k].markings == 3 || r.ends[k].markings == 5;  // precision, UK precision
    ak.instrument = r.ends[k].markings >= 2 && r.ends[k].markings <= 5;
  }
  return a;
}

// ---- Edge lights.

// The rows' stations, metres from end 0's point: each stretch between the runway's ends and its
// thresholds divided uniformly, at most kEdgeMaxSpacingM apart. The two end stations are left out:
// there the end/threshold bars' outermost fixtures stand in line with the rows (FAA AC
// 150/5340-30); a displaced threshold's station is a row light (its threshold bar lies inside).
std::vector<double> edge_stations(const std::array<Approach, 2>& a) {
  const double length = a[0].length;
  std::vector<double> breaks{0};
  for (double b : {a[0].threshold, length - a[1].threshold, length})
    if (b > breaks.back() + kEps) breaks.push_back(b);
  std::vector<double> s;
  for (size_t i = 0; i + 1 < breaks.size(); ++i) {
    const double stretch = breaks[i + 1] - breaks[i];
    const int n = std::max(1, int(std::ceil(stretch / kEdgeMaxSpacingM - 1e-9)));
    for (int j = 1; j <= n; ++j) s.push_back(breaks[i] + stretch * j / n);
  }
  s.pop_back();  // the far end
  return s;
}

// Seen landing along `a`, `s` metres from its runway end: red before a displaced threshold, yellow in
// the caution zone of an instrument runway, white elsewhere.
Rgb edge_colour(const Approach& a, double s) {
  if (s < a.threshold - kEps) return kRed;
  const double caution = a.instrument ? std::min(kCautionZoneM, a.length / 3) : 0;
  return a.length - s <= caution + kEps ? kYellow : kWhite;
}

void add_edge_lights(const Runway& r, const std::array<Approach, 2>& a, std::vector<AirportLight>& out) {
  if (r.edge_lights == 0) return;
  const BeamSpec& spec = r.width_m < kWideRunwayM ? kEdgeBeam45 : kEdgeBeam60;
  const double half = r.width_m / 2 + kEdgeOffsetM;
  for (double s : edge_stations(a))
    for (int side : {1, -1}) {
      const glm::dvec2 p = a[0].at(s, side * half);
      const glm::dvec2 inward = -double(side) * a[0].left;
      for (int k : {0, 1}) {  // one light per direction, its beam toward that direction's approach
        const double sk = k == 0 ? s : a[0].length - s;
        out.push_back(make_light(AirportLightType::runway_edge, a[k].end->id, p, kElevatedHeightM,
                                 edge_colour(a[k], sk), kEdgeIntensity[r.edge_lights], aim(-a[k].along, inward, spec)));
      }
    }
}

// ---- Threshold and end lights.

// A bar across the runway from -half to +half: uniformly at most `spacing` apart, at least
// kMinBarLights lights.
std::vector<double> bar_offsets(double half, double spacing) {
  const int n = std::max(kMinBarLights - 1, int(std::ceil(2 * half / spacing - 1e-9)));
  std::vector<double> y;
  for (int i = 0; i <= n; ++i) y.push_back(-half + 2 * half * i / n);
  return y;
}

// Per end: the threshold bar at the landing threshold, green toward the approach; the end bar at
// the runway's end, red toward the runway (seen by traffic landing on the other end). An
// undisplaced threshold's bar spans the edge rows and its fixtures carry both; a displaced one's lies
// between the rows (inset lights) and the end bar stands alone at the runway's end.
void add_threshold_and_end_lights(const Runway& r, const std::array<Approach, 2>& a, std::vector<AirportLight>& out) {
  if (r.edge_lights == 0) return;  // 5.3.10, 5.3.11: provided on runways with edge lights
  const double intensity = kEdgeIntensity[r.edge_lights];
  for (int k : {0, 1}) {
    const Approach& ak = a[k];
    const bool displaced = ak.threshold > kEps;
    const double spacing = ak.precision ? kThresholdSpacingPrecisionM : kThresholdSpacingOtherM;
    const std::vector<double> threshold_bar = bar_offsets(r.width_m / 2 + (displaced ? 0 : kEdgeOffsetM), spacing);
    for (double y : threshold_bar)
      out.push_back(make_light(AirportLightType::threshold, ak.end->id, ak.at(ak.threshold, y),
                               displaced ? kInsetHeightM : kElevatedHeightM, kGreen, intensity,
                               aim(-ak.along, ak.inward(y), kThresholdBeam)));
    const std::vector<double> end_bar =
        displaced ? bar_offsets(r.width_m / 2 + kEdgeOffsetM, kEndSpacingM) : threshold_bar;
    for (double y : end_bar)
      out.push_back(make_light(AirportLightType::runway_end, a[1 - k].end->id, ak.at(0, y), kElevatedHeightM, kRed,
                               intensity, aim(ak.along, {0, 0}, kEndBeam)));
  }
}

// ---- Centre line lights.

// Seen landing along `a`, `to_end_m` (fixture number `index` counted from 0 at the far end) before
// the far end.
Rgb centreline_colour(const Approach& a, double to_end_m, int index) {
  if (to_end_m <= kCentrelineRedM + kEps) return kRed;
  const double landing = a.length - a.threshold;
  const double alternate = landing < kCentrelineShortRunwayM ? landing / 2 : kCentrelineAlternateM;
  if (to_end_m <= alternate + kEps) return index % 2 == 0 ? kRed : kWhite;
  return kWhite;
}

// Fixtures uniformly at most kCentrelineSpacingM apart between the runway's ends (the ends
// themselves left to the threshold/end bars), each showing toward both directions from the
// landing threshold on.
void add_centreline_lights(const Runway& r, const std::array<Approach, 2>& a, std::vector<AirportLight>& out) {
  if (r.centreline_lights == 0) return;
  const double length = a[0].length;
  const int n = std::max(2, int(std::ceil(length / kCentrelineSpacingM - 1e-9)));
  for (int i = 1; i < n; ++i) {
    const glm::dvec2 p = a[0].at(length * i / n, 0);
    for (int k : {0, 1}) {
      const int to_end = k == 0 ? n - i : i;                            // stations between this fixture and the far end
      if (length * (n - to_end) / n < a[k].threshold - kEps) continue;  // before the landing threshold
      out.push_back(make_light(AirportLightType::centreline, a[k].end->id, p, kInsetHeightM,
                               centreline_colour(a[k], length * to_end / n, to_end), 1.0,
                               aim(-a[k].along, {0, 0}, kCentrelineBeam)));
    }
  }
}

// ---- Touchdown zone lights and REIL, per end.

void add_touchdown_zone_lights(const Approach& a, std::vector<AirportLight>& out) {
  if (a.end->touchdown_zone_lights == 0) return;
  const double extent = std::min(kTdzExtentM, (a.length - a.threshold) / 2);
  for (int row = 1; row * kTdzRowSpacingM <= extent + kEps; ++row)
    for (int side : {1, -1})
      for (int j = 0; j < kTdzBarretteLights; ++j) {
        const double y = side * (kTdzInnerGapM / 2 + j * kTdzLightSpacingM);
        out.push_back(make_light(AirportLightType::touchdown_zone, a.end->id,
                                 a.at(a.threshold + row * kTdzRowSpacingM, y), kInsetHeightM, kWhite, 1.0,
                                 aim(-a.along, a.inward(y), kTdzBeam)));
      }
}

void add_reil(const Runway& r, const Approach& a, std::vector<AirportLight>& out) {
  if (a.end->reil == 0) return;
  for (int side : {1, -1}) {
    const double y = side * (r.width_m / 2 + kReilOutsideEdgeM);
    AirportLightBeam beam;                                               // omnidirectional (code 1)
    if (a.end->reil == 2) beam = aim(-a.along, a.inward(y), kReilBeam);  // toe-in -15: 15 deg outward
    out.push_back(
        make_light(AirportLightType::reil, a.end->id, a.at(a.threshold, y), kElevatedHeightM, kWhite, 1.0, beam));
    out.back().flashing = true;
  }
}

// ---- Approach lighting systems: each a list of lights at (d, y) in the approach's frame.

enum class AlsPart { centre, crossbar, side_row, flasher, omni_flasher };
struct AlsLight {
  double d, y;
  Rgb colour;
  AlsPart part;
};
using AlsLayout = std::vector<AlsLight>;

// A row across the approach at d: lights at |y| = inner, inner + step, ... up to outer, both sides.
void als_row(AlsLayout& v, double d, double inner, double outer, double step, const Rgb& c, AlsPart part) {
  for (int i = 0; inner + i * step <= outer + kEps; ++i) {
    v.push_back({d, inner + i * step, c, part});
    v.push_back({d, -(inner + i * step), c, part});
  }
}

// White five-light centre line barrettes (and flashers) at from, from + step, ... up to `to`.
void als_barrettes(AlsLayout& v, double from, double to, double step) {
  for (int i = 0; from + i * step <= to + kEps; ++i)
    for (int j = -2; j <= 2; ++j) v.push_back({from + i * step, j * kBarretteLightSpacingM, kWhite, AlsPart::centre});
}
void als_flashers(AlsLayout& v, double from, double to, double step, AlsPart part = AlsPart::flasher) {
  for (int i = 0; from + i * step <= to + kEps; ++i) v.push_back({from + i * step, 0, kWhite, part});
}

// ICAO Cat II/III side rows (ALSF-II): red three-light barrettes every 30 m to 270 m, in line
// with the touchdown zone lights.
void als_side_rows(AlsLayout& v) {
  for (double d = kAlsfSpacingM; d <= kSideRowToM + kEps; d += kAlsfSpacingM)
    als_row(v, d, kTdzInnerGapM / 2, kTdzInnerGapM / 2 + 2 * kTdzLightSpacingM, kTdzLightSpacingM, kRed,
            AlsPart::side_row);
}

// ALSF-I, ALSF-II, SALS (FAA AC 150/5340-30): barrettes every 100 ft, the 1000 ft crossbar,
// sequenced flashers from 1000 ft outward (not SALS); ALSF-II: the 500 ft crossbar and red side
// rows; ALSF-I and SALS: the red terminating bar at 200 ft and pre-threshold bar at 100 ft (from
// the runway edge outward). Simplified: the bars' lateral spacing is 1.5 m (1 m pre-threshold).
AlsLayout alsf(int code, double width) {
  AlsLayout v;
  const double length = code == kSals ? kSalsLengthM : kAlsfLengthM;
  als_barrettes(v, kAlsfSpacingM, length, kAlsfSpacingM);
  als_row(v, kCrossbarM, kCrossbarInnerM, kCrossbarHalfM, kCrossbarStepM, kWhite, AlsPart::crossbar);
  if (code != kSals) als_flashers(v, kCrossbarM, length, kAlsfSpacingM);
  if (code == kAlsf2) {
    als_row(v, kAlsf2BarM, kCrossbarInnerM, kAlsf2BarHalfM, kCrossbarStepM, kWhite, AlsPart::crossbar);
    als_side_rows(v);
  } else {
    als_row(v, kTerminatingBarM, kCrossbarInnerM, kTerminatingHalfM, kCrossbarStepM, kRed, AlsPart::crossbar);
    als_row(v, kPreThresholdBarM, width / 2, width / 2 + (kPreThresholdLights - 1) * kPreThresholdStepM,
            kPreThresholdStepM, kRed, AlsPart::crossbar);
  }
  return v;
}

// SSALR, SSALF, MALSR, MALSF, MALS: barrettes every 200 ft to 1400 ft, the 1000 ft crossbar (5
// lights a side); F: flashers on the outer three barrettes; R: RAIL flashers beyond (to 2400 ft).
AlsLayout ssal(int code) {
  AlsLayout v;
  als_barrettes(v, kSsalSpacingM, kSsalLengthM, kSsalSpacingM);
  als_row(v, kCrossbarM, kCrossbarInnerM, kCrossbarInnerM + 4 * kCrossbarStepM, kCrossbarStepM, kWhite,
          AlsPart::crossbar);
  if (code == kSsalf || code == kMalsf) als_flashers(v, kCrossbarM, kSsalLengthM, kSsalSpacingM);
  if (code == kSsalr || code == kMalsr) als_flashers(v, kRailFromM, kRailToM, kSsalSpacingM);
  return v;
}

// Calvert (ICAO Cat I, 5.3.4): a 900 m centre line of single, double and triple light sources per
// 300 m and five crossbars 150 m apart, 30 m long at 300 m, others in proportion to their distance
// (simplified). Cat II/III (code 4): in the inner 300 m, barrettes and red side rows instead.
AlsLayout calvert(int code) {
  AlsLayout v;
  double coded_from = 0;
  if (code == kCalvert2) {
    als_barrettes(v, kAlsfSpacingM, kCalvertCodingM, kAlsfSpacingM);
    als_side_rows(v);
    coded_from = kCalvertCodingM;
  }
  for (double d = kAlsfSpacingM; d <= kAlsfLengthM + kEps; d += kAlsfSpacingM) {
    if (d <= coded_from + kEps) continue;
    const int sources = int(std::ceil(d / kCalvertCodingM - 1e-9));
    for (int j = 0; j < sources; ++j)
      v.push_back({d, (j - (sources - 1) / 2.0) * kCalvertSourceSpacingM, kWhite, AlsPart::centre});
  }
  for (int bar = 1; bar <= 5; ++bar) {
    const double d = bar * kCalvertBarSpacingM;
    als_row(v, d, kCrossbarInnerM, d * kCalvertBarHalfPerM, kCrossbarStepM, kWhite, AlsPart::crossbar);
  }
  return v;
}

AlsLayout als_layout(int code, double width) {
  switch (code) {
    case kAlsf1:
    case kAlsf2:
    case kSals:
      return alsf(code, width);
    case kCalvert:
    case kCalvert2:
      return calvert(code);
    case kSsalr:
    case kSsalf:
    case kMalsr:
    case kMalsf:
    case kMals:
      return ssal(code);
    case kOdals: {  // five omnidirectional flashers on the centre line, two abeam the threshold
      AlsLayout v;
      als_flashers(v, kOdalsSpacingM, 5 * kOdalsSpacingM, kOdalsSpacingM, AlsPart::omni_flasher);
      for (double y : {1.0, -1.0}) v.push_back({0, y * (width / 2 + kReilOutsideEdgeM), kWhite, AlsPart::omni_flasher});
      return v;
    }
    case kRail: {
      AlsLayout v;
      als_flashers(v, kRailFromM, kRailToM, kSsalSpacingM);
      return v;
    }
    default:
      return {};
  }
}

AirportLightBeam als_beam(const Approach& a, const AlsLight& l) {
  if (l.part == AlsPart::omni_flasher) return AirportLightBeam{};
  if (l.part == AlsPart::side_row) {
    const BeamSpec s{0, kSideRowHalfWidthDeg[0], kSideRowHalfWidthDeg[1], kSideRowToeInDeg};
    return aim(-a.along, a.inward(l.y), s, side_row_elevation_deg(l.d));
  }
  const bool toe_in = l.part == AlsPart::crossbar && std::abs(l.y) > kCrossbarToeInBeyondM;
  const BeamSpec s{0, kApproachHalfWidthDeg[0], kApproachHalfWidthDeg[1], toe_in ? kCrossbarToeInDeg : 0};
  return aim(-a.along, a.inward(l.y), s, approach_elevation_deg(l.d));
}

// The end's approach lighting system from its landing threshold outward; the lights a displaced
// threshold puts on the runway are inset.
void add_approach_lights(const Runway& r, const Approach& a, std::vector<AirportLight>& out) {
  const int code = a.end->approach_lights;
  const double intensity = code == kMalsr || code == kMalsf || code == kMals ? kMediumIntensity : 1.0;
  for (const AlsLight& l : als_layout(code, r.width_m)) {
    const bool flasher = l.part == AlsPart::flasher || l.part == AlsPart::omni_flasher;
    double z = l.d < a.threshold - kEps ? kInsetHeightM : kElevatedHeightM;
    if (l.part == AlsPart::flasher) z += kFlasherAboveM;
    out.push_back(make_light(AirportLightType::approach, a.end->id, a.at(a.threshold - l.d, l.y), z, l.colour,
                             intensity, als_beam(a, l)));
    out.back().flashing = flasher;
  }
}

// ---- PAPI and VASI.

void validate(const LightObject& o) {
  const std::string where = "light object (type " + std::to_string(o.type) + ", runway end " + o.runway_end + ")";
  if (!std::isfinite(o.point.x) || !std::isfinite(o.point.y) || !std::isfinite(o.heading_deg))
    throw InputError("", where, "its point or heading is not finite");
  if (!std::isfinite(o.glideslope_deg) || o.glideslope_deg <= 0 || o.glideslope_deg >= 10)
    throw InputError("", where, "glide slope " + number(o.glideslope_deg) + " deg is not in (0, 10) deg");
}

AirportLight slope_unit(AirportLightType type, const LightObject& o, glm::dvec2 p, double setting_deg) {
  AirportLight l = make_light(type, o.runway_end, p, kPapiHeightM, kWhite, 1.0,
                              aim(-unit_of_heading(o.heading_deg), {0, 0}, kPapiBeam, o.glideslope_deg));
  l.has_below = true;
  l.below_elevation_deg = setting_deg;
  l.below_colour = kRed;
  return l;
}

}  // namespace

const char* to_string(AirportLightType t) {
  switch (t) {
    case AirportLightType::runway_edge:
      return "runway_edge";
    case AirportLightType::threshold:
      return "threshold";
    case AirportLightType::runway_end:
      return "runway_end";
    case AirportLightType::centreline:
      return "centreline";
    case AirportLightType::touchdown_zone:
      return "touchdown_zone";
    case AirportLightType::approach:
      return "approach";
    case AirportLightType::reil:
      return "reil";
    case AirportLightType::papi:
      return "papi";
    case AirportLightType::vasi:
      return "vasi";
  }
  return "unknown";
}

std::vector<AirportLight> runway_lights(const Runway& r) {
  const std::array<Approach, 2> a = approaches(r);
  std::vector<AirportLight> out;
  add_edge_lights(r, a, out);
  add_threshold_and_end_lights(r, a, out);
  add_centreline_lights(r, a, out);
  for (const Approach& ak : a) {
    add_touchdown_zone_lights(ak, out);
    add_approach_lights(r, ak, out);
    add_reil(r, ak, out);
  }
  return out;
}

std::size_t remove_edge_lights_on(std::vector<AirportLight>& lights, const Runway& other) {
  const Approach a = approaches(other)[0];
  const auto on_other = [&](const AirportLight& l) {
    if (l.type != AirportLightType::runway_edge) return false;
    const glm::dvec2 q = glm::dvec2(l.position) - a.origin;
    const double s = glm::dot(q, a.along), y = glm::dot(q, a.left);
    return s >= 0 && s <= a.length && std::abs(y) <= other.width_m / 2;
  };
  const auto kept = std::remove_if(lights.begin(), lights.end(), on_other);
  const std::size_t removed = std::size_t(lights.end() - kept);
  lights.erase(kept, lights.end());
  return removed;
}

std::vector<AirportLight> light_object_lights(const LightObject& o) {
  std::vector<AirportLight> out;
  if (o.type != kVasi && o.type != kPapiLeft && o.type != kPapiRight) return out;
  validate(o);
  const glm::dvec2 along = unit_of_heading(o.heading_deg), left{-along.y, along.x};
  if (o.type == kVasi) {  // downwind bar nearer the threshold, set lower
    out.push_back(slope_unit(AirportLightType::vasi, o, o.point - along * (kVasiBarSpacingM / 2),
                             o.glideslope_deg - kVasiSettingDeg));
    out.push_back(slope_unit(AirportLightType::vasi, o, o.point + along * (kVasiBarSpacingM / 2),
                             o.glideslope_deg + kVasiSettingDeg));
    return out;
  }
  // PAPI-4L stands on the pilot's left, so the runway is to its right; the point is the bar's centre.
  const glm::dvec2 to_runway = o.type == kPapiLeft ? -left : left;
  for (int i = 0; i < 4; ++i)  // from the runway outward
    out.push_back(slope_unit(AirportLightType::papi, o, o.point + to_runway * ((1.5 - i) * kPapiUnitSpacingM),
                             o.glideslope_deg + kPapiSettingsDeg[i]));
  return out;
}

LightObject standard_papi(const Runway& r, int end, bool left_side, double distance_m, double glideslope_deg) {
  const std::array<Approach, 2> a = approaches(r);
  if (end != 0 && end != 1)
    throw InputError("", "standard PAPI", "runway end index " + std::to_string(end) + " is not 0 or 1");
  const Approach& ak = a[end];
  LightObject o;
  o.type = left_side ? kPapiLeft : kPapiRight;
  o.heading_deg = heading_of(ak.along);
  o.glideslope_deg = glideslope_deg;
  o.runway_end = ak.end->id;
  const double centre_from_axis = r.width_m / 2 + kPapiInnerFromEdgeM + 1.5 * kPapiUnitSpacingM;
  o.point = ak.at(ak.threshold + distance_m, left_side ? centre_from_axis : -centre_from_axis);
  return o;
}

}  // namespace cig
