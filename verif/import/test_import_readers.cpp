// The importer's readers: WGS-84 geodesy against SimGear's own (SGGeodesy: FlightGear's code, not
// ours), the local frame's axes, and the apt.dat reader on well-formed and broken rows.
#include <gtest/gtest.h>
#include <simgear/math/SGMath.hxx>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

#include "common/error.hpp"
#include "import/apt_dat.hpp"
#include "import/geodesy.hpp"

namespace cig {
namespace {

// Double rounding only: both evaluate the same closed form; 1e-6 m is 2^-3 ulp-scale slack at the
// earth's radius (6.4e6 m, ulp 9.3e-10 m) times the ~20 operations of the formula, with margin.
TEST(Geodesy, EcefMatchesSimGear) {
  for (double lat : {-89.9, -45.0, 0.0, 12.5, 63.985, 89.9})
    for (double lon : {-179.0, -22.6, 0.0, 90.0, 179.5})
      for (double h : {-400.0, 0.0, 52.0, 12000.0}) {
        SGVec3d ref;
        SGGeodesy::SGGeodToCart(SGGeod::fromDegM(lon, lat, h), ref);
        const glm::dvec3 p = geodetic_to_ecef({lat, lon, h});
        EXPECT_NEAR(p.x, ref.x(), 1e-6) << lat << " " << lon << " " << h;
        EXPECT_NEAR(p.y, ref.y(), 1e-6);
        EXPECT_NEAR(p.z, ref.z(), 1e-6);
      }
}

TEST(Geodesy, LocalFrameAxes) {
  const LocalFrame f({63.985, -22.6054, 51.8});
  const glm::dvec3 o = f.from_geodetic({63.985, -22.6054, 51.8});
  EXPECT_NEAR(glm::length(o), 0, 1e-6);
  // 100 m up is +z; a point due north is +y, due east +x (to first order).
  EXPECT_NEAR(f.from_geodetic({63.985, -22.6054, 151.8}).z, 100, 1e-6);
  const glm::dvec3 n = f.from_geodetic({63.995, -22.6054, 51.8});
  EXPECT_GT(n.y, 1000);
  EXPECT_NEAR(n.x, 0, 1e-6);
  const glm::dvec3 e = f.from_geodetic({63.985, -22.5854, 51.8});
  EXPECT_GT(e.x, 900);
  EXPECT_LT(std::fabs(e.y), 1);
  // The earth curves away: 20 km east the ellipsoid lies d^2 / 2R = 31 m below the tangent plane
  // (R the radius of curvature there, 6.39e6 m east-west at 64 N: 31.3 m).
  const glm::dvec3 far =
      f.from_geodetic({63.985, -22.6054 + 20000 / (6.39e6 * std::cos(63.985 * M_PI / 180)) * 180 / M_PI, 51.8});
  EXPECT_NEAR(far.z, -20000.0 * 20000 / (2 * 6.39e6), 0.5);
}

class AptDat : public ::testing::Test {
 protected:
  std::string write(const std::string& body) {
    const std::string path =
        (std::filesystem::temp_directory_path() / ("cig_apt_" + std::to_string(::getpid()) + ".dat")).string();
    std::ofstream(path) << "I\n1000 Version - test\n\n" << body << "99\n";
    files_.push_back(path);
    return path;
  }
  void TearDown() override {
    for (const std::string& f : files_) std::filesystem::remove(f);
  }
  std::vector<std::string> files_;
};

const char* const kRunway =
    "100   60.05   1   0 0.00 1 2 0 11   63.98504094 -022.65499831    0.00   74.98 3  1 1 0 29   63.98504419 -022.59238152    0.00   "
    "60.05 3 11 0 0\n";

TEST_F(AptDat, ReadsTheAirportsRows) {
  const std::string f = write("1 10 0 0 XXXX Other\n" + std::string(kRunway) + "1 170 1 0 BIKF Keflavik\n" + kRunway +
                              "21   63.98559030 -022.64803812  2  89.97   3.00 11  PAPI-4L\n110 2 0.25 0.00 Taxiway\n"
                              "1 20 0 0 YYYY Next\n" +
                              kRunway);
  const AptAirport a = read_apt_dat(f, "BIKF");
  EXPECT_EQ(a.name, "Keflavik");
  EXPECT_EQ(a.elevation_ft, 170);
  ASSERT_EQ(a.runways.size(), 1u);
  EXPECT_EQ(a.runways[0].ends[0].id, "11");
  EXPECT_EQ(a.runways[0].ends[1].approach_lights, 11);
  EXPECT_EQ(a.runways[0].edge_lights, 2);
  EXPECT_DOUBLE_EQ(a.runways[0].ends[0].blast_pad_m, 74.98);
  ASSERT_EQ(a.lights.size(), 1u);
  EXPECT_EQ(a.lights[0].type, 2);
  EXPECT_EQ(a.lights[0].runway, "11");
  EXPECT_EQ(a.rows_skipped, 1u);
}

// Each broken row is refused with the file, its line and the rule.
TEST_F(AptDat, BrokenRowsNameFileLineAndRule) {
  struct Case {
    std::string row, rule;
  } cases[] = {
      {"100 60 1 0 0 1 2 0 11 63.98 -22.65\n", "land runway (100) row needs 26 fields, has 11"},
      {std::string(kRunway).replace(0, 11, "100   abc  "), "runway width (field 2) 'abc' is not a number"},
      {std::string(kRunway).replace(std::string(kRunway).find("63.98504094"), 11, "93.98504094"),
       "latitude (field 10) 93.98504094 is outside [-90, 90]"},
      {"21 63.98 -22.64 9 89.97 3.00 11 X\n", "lighting object type (field 4) 9 is outside [1, 6]"},
      {"100 60 1 0 0 1 2 0 11 63.9 -22.6 0 0 3 1 1 0 29 63.9 -22.6 0 0 3 11 0 0\n",
       "runway 11/29 has both ends at one point"},
  };
  for (const Case& c : cases) {
    const std::string f = write("1 170 1 0 BIKF Keflavik\n" + c.row);
    try {
      read_apt_dat(f, "BIKF");
      ADD_FAILURE() << "accepted: " << c.row;
    } catch (const InputError& e) {
      EXPECT_EQ(e.file(), f);
      EXPECT_EQ(e.where(), "line 5");
      EXPECT_EQ(e.rule(), c.rule);
    }
  }
}

TEST_F(AptDat, MissingAirportAndWrongFiles) {
  const std::string f = write("1 170 1 0 BIKF Keflavik\n" + std::string(kRunway));
  EXPECT_THROW(read_apt_dat(f, "EGLL"), InputError);
  EXPECT_THROW(read_apt_dat(f + ".absent", "BIKF"), InputError);
  const std::string g =
      (std::filesystem::temp_directory_path() / ("cig_apt_bad_" + std::to_string(::getpid()))).string();
  std::ofstream(g) << "{\"format\": \"cig-scene\"}\n";
  files_.push_back(g);
  try {
    read_apt_dat(g, "BIKF");
    ADD_FAILURE();
  } catch (const InputError& e) { EXPECT_EQ(e.where(), "line 1"); }
}

}  // namespace
}  // namespace cig
