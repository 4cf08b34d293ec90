#include "import/apt_dat.hpp"

#include <zlib.h>

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <sstream>

#include "common/error.hpp"

namespace cig {

namespace {

// Reads a plain or gzip-compressed text file line by line (zlib reads plain files through).
class GzLines {
 public:
  explicit GzLines(const std::string& file) : file_(file), gz_(gzopen(file.c_str(), "rb"), &gzclose) {
    if (!gz_) throw InputError(file, "", std::string("cannot open: ") + std::strerror(errno));
  }
  bool next(std::string& line) {
    line.clear();
    char buf[1 << 14];
    while (gzgets(gz_.get(), buf, sizeof buf)) {
      line += buf;
      if (!line.empty() && line.back() == '\n') break;
    }
    ++number_;
    if (line.empty()) {
      int code = 0;
      const char* msg = gzerror(gz_.get(), &code);
      if (code != Z_OK && code != Z_STREAM_END) throw InputError(file_, "line " + std::to_string(number_), msg);
      return false;
    }
    while (!line.empty() && (line.back() == '\n' || line.back() == '\r')) line.pop_back();
    return true;
  }
  int number() const { return number_; }

 private:
  std::string file_;
  std::unique_ptr<gzFile_s, int (*)(gzFile)> gz_;
  int number_ = 0;
};

// One row's fields with the checks every field needs: a number in range, an integer code.
struct Row {
  const std::string& file;
  int line;
  std::vector<std::string> f;

  [[noreturn]] void fail(const std::string& rule) const {
    throw InputError(file, "line " + std::to_string(line), rule);
  }
  void need(std::size_t n, const char* what) const {
    if (f.size() < n)
      fail(std::string(what) + " row needs " + std::to_string(n) + " fields, has " + std::to_string(f.size()));
  }
  double number(std::size_t i, double lo, double hi, const char* what) const {
    char* end = nullptr;
    const double v = std::strtod(f[i].c_str(), &end);
    if (end == f[i].c_str() || *end != '\0' || !std::isfinite(v))
      fail(std::string(what) + " (field " + std::to_string(i + 1) + ") '" + f[i] + "' is not a number");
    if (v < lo || v > hi) {
      std::ostringstream s;
      s << what << " (field " << i + 1 << ") " << f[i] << " is outside [" << lo << ", " << hi << "]";
      fail(s.str());
    }
    return v;
  }
  int code(std::size_t i, int lo, int hi, const char* what) const {
    const double v = number(i, lo, hi, what);
    if (v != std::floor(v)) fail(std::string(what) + " (field " + std::to_string(i + 1) + ") must be an integer code");
    return int(v);
  }
};

std::vector<std::string> split(const std::string& s) {
  std::vector<std::string> out;
  std::istringstream in(s);
  std::string w;
  while (in >> w) out.push_back(w);
  return out;
}

// Row 100, land runway (apt.dat 1000 spec): width, surface, shoulder, smoothness, centreline lights,
// edge lights, distance signs, then per end: number, lat, lon, displaced threshold, blast pad,
// markings, approach lights, touchdown zone lights, REIL.
AptRunway read_runway(const Row& r) {
  r.need(26, "land runway (100)");
  AptRunway rw;
  rw.line = r.line;
  rw.width_m = r.number(1, 0, 1000, "runway width");
  if (!(rw.width_m > 0)) r.fail("runway width must be positive");
  rw.surface = r.code(2, 1, 99, "surface");
  rw.shoulder = r.code(3, 0, 99, "shoulder");
  rw.centreline_lights = r.code(5, 0, 1, "centreline lights");
  rw.edge_lights = r.code(6, 0, 3, "edge lights");
  for (int k = 0; k < 2; ++k) {
    const std::size_t b = 8 + 9 * std::size_t(k);
    AptRunwayEnd& e = rw.ends[k];
    e.id = r.f[b];
    e.lat_deg = r.number(b + 1, -90, 90, "latitude");
    e.lon_deg = r.number(b + 2, -180, 180, "longitude");
    e.displaced_threshold_m = r.number(b + 3, 0, 1e4, "displaced threshold");
    e.blast_pad_m = r.number(b + 4, 0, 1e4, "blast pad");
    e.markings = r.code(b + 5, 0, 9, "runway markings");
    e.approach_lights = r.code(b + 6, 0, 12, "approach lighting");
    e.touchdown_zone_lights = r.code(b + 7, 0, 1, "touchdown zone lights");
    e.reil = r.code(b + 8, 0, 2, "REIL");
  }
  if (rw.ends[0].lat_deg == rw.ends[1].lat_deg && rw.ends[0].lon_deg == rw.ends[1].lon_deg)
    r.fail("runway " + rw.ends[0].id + "/" + rw.ends[1].id + " has both ends at one point");
  return rw;
}

// Row 21, lighting object: lat, lon, type, orientation, glide slope, runway, description.
AptLightObject read_light_object(const Row& r) {
  r.need(6, "lighting object (21)");
  AptLightObject l;
  l.line = r.line;
  l.lat_deg = r.number(1, -90, 90, "latitude");
  l.lon_deg = r.number(2, -180, 180, "longitude");
  l.type = r.code(3, 1, 6, "lighting object type");
  l.heading_deg = r.number(4, -360, 360, "orientation");
  l.glideslope_deg = r.number(5, 0, 10, "glide slope");
  l.runway = r.f.size() > 6 ? r.f[6] : "";
  return l;
}

bool is_header(const std::vector<std::string>& f) {
  return !f.empty() && (f[0] == "1" || f[0] == "16" || f[0] == "17");
}

// Reads the airport's rows up to the next airport header or the end marker (99).
void read_airport_rows(GzLines& in, const std::string& file, AptAirport& a) {
  std::string line;
  while (in.next(line)) {
    Row r{file, in.number(), split(line)};
    if (r.f.empty()) continue;
    if (is_header(r.f) || r.f[0] == "99") return;
    ++a.rows;
    if (r.f[0] == "100") {
      a.runways.push_back(read_runway(r));
    } else if (r.f[0] == "21") {
      a.lights.push_back(read_light_object(r));
    } else if (r.f[0] == "1302" && r.f.size() >= 3 && (r.f[1] == "datum_lat" || r.f[1] == "datum_lon")) {
      const double v = r.number(2, -180, 180, r.f[1].c_str());
      (r.f[1] == "datum_lat" ? a.datum_lat_deg : a.datum_lon_deg) = v;
      a.has_datum = true;
    } else {
      ++a.rows_skipped;
    }
  }
}

}  // namespace

AptAirport read_apt_dat(const std::string& file, const std::string& icao) {
  GzLines in(file);
  AptAirport a;
  std::string line;
  // Line 1: "I" or "A" (byte order, unused); line 2: the version number and the copyright.
  if (!in.next(line) || (line != "I" && line != "A"))
    throw InputError(file, "line 1", "not an apt.dat file (want 'I' or 'A')");
  if (!in.next(line)) throw InputError(file, "line 2", "the version line is missing");
  const std::vector<std::string> v = split(line);
  a.version = v.empty() ? "" : v[0];
  if (a.version != "850" && a.version != "1000" && a.version != "1050" && a.version != "1100")
    throw InputError(file, "line 2", "apt.dat version '" + a.version + "' is not one of 850, 1000, 1050, 1100");
  while (in.next(line)) {
    // Cheap test first: the file holds some 30000 airports and millions of rows.
    if (line.size() < 2 || !(line[0] == '1' && (line[1] == ' ' || line[1] == '6' || line[1] == '7'))) continue;
    Row r{file, in.number(), split(line)};
    if (!is_header(r.f) || r.f.size() < 5 || r.f[4] != icao) continue;
    a.icao = icao;
    a.elevation_ft = r.number(1, -2000, 40000, "airport elevation (ft)");
    for (std::size_t i = 5; i < r.f.size(); ++i) a.name += (i > 5 ? " " : "") + r.f[i];
    read_airport_rows(in, file, a);
    if (a.runways.empty())
      throw InputError(file, "line " + std::to_string(r.line), "airport " + icao + " has no land runway (row 100)");
    return a;
  }
  throw InputError(file, "", "no airport '" + icao + "' (header rows 1, 16, 17)");
}

}  // namespace cig
