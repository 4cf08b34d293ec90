// The scene database (stage A's input): objects made of subobjects made of convex planar
// polygons, light points, the observer path, the channels and the environment. Loaded from the
// JSON format documented in scenes/README.md. World axes: x east, y north, z up (metres).
#pragma once

#include <cstdint>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include <glm/mat3x3.hpp>
#include <glm/vec3.hpp>

namespace cig {

using Rgb = glm::dvec3;  // linear colour, each component in [0, 1]

// Limits shared by every stage. The geometric processor clips a polygon against five planes
// (near + four pyramid sides), each adding at most one vertex, so a scene polygon of at most
// kMaxSceneVertices reaches the raster engines with at most kMaxScreenVertices vertices.
constexpr int kMaxScreenVertices = 16;
constexpr int kClipPlanes = 5;
constexpr int kMaxSceneVertices = kMaxScreenVertices - kClipPlanes;
// Raster sizes 2^n accepted by the whole pipeline.
constexpr int kMinRaster = 16;
constexpr int kMaxRaster = 4096;

// The valid range of every number the loaders accept (scenes/README.md, "Valid ranges"), checked
// at load with the JSON path. Inside them no arithmetic of the pipeline can overflow a double:
// world points differ by at most 2 kMaxWorldCoordinate, their squares stay below 1e17, and the
// projection divides by depths of at least kMinNear. Denormal inputs are valid numbers: they are
// taken as the tiny values they are (0 for every purpose here), never as "not finite".
constexpr double kMaxWorldCoordinate = 1e8;                    // metres: positions, vertices, light points, offsets
constexpr double kMinModelScale = 1e-6, kMaxModelScale = 1e6;  // OBJ subobject scale
constexpr double kMaxAngleDeg = 360;                           // heading, roll and channel yaw lie in [-360, 360]
constexpr double kMinNear = 1e-3, kMaxNear = 1e4;              // near plane distance, metres
constexpr double kMaxDistance = 1e9;                           // fog start and end, bounding-sphere radius, metres
constexpr double kMaxLightDiameter = 1e5;                      // light-point diameter, metres
constexpr double kMaxLobeHalfWidthDeg = 180;                   // a directional light's lobe half-widths, (0, 180]
// Screen depths of a polygon list: what the geometric processor can produce from the ranges above.
constexpr double kMinScreenDepth = kMinNear, kMaxScreenDepth = kMaxDistance;
// Polygon lists (cig-polys) may hold any depth the formatter can meet and more: from below the
// e8m7 range (2^-127 = 5.9e-39) to beyond it (6.8e38), so stress lists reach both saturations.
constexpr double kMinListDepth = 1e-40, kMaxListDepth = 1e41;
// A model file larger than this is rejected before it is read (a setting: --max-model-mb).
constexpr long long kDefaultMaxModelBytes = 64ll << 20;
constexpr double kDefaultMaxModelSeconds = 60;

struct Polygon {
  std::vector<std::uint32_t> indices;  // into Subobject::vertices, counter-clockwise seen from the front
  Rgb colour{1, 1, 1};
  bool opaque = true;    // false: screen-door transparent (covers half the sub-pixel samples)
  bool protect = false;  // protected from overload culling (area code 0 in the segment processor)
  // Self-lit polygons (sky, lit windows) carry their own vertex intensities instead of sun lighting.
  bool self_lit = false;
  std::vector<double> self_intensity;  // one per vertex when self_lit
};

// A model face in its file: the assimp mesh (scene order) and the face's index in it, as the file
// gives it (before triangulation).
struct ModelFaceRef {
  std::uint32_t mesh = 0, face = 0;
};

// What loading a model did, for the report: faces triangulated (concave, non-planar, or more than
// kMaxSceneVertices corners) and the triangles they became, zero-area faces skipped, points and
// lines skipped (the pipeline draws polygons).
struct ModelSummary {
  std::size_t meshes = 0, faces = 0, triangulated_faces = 0, triangles = 0, degenerate_faces = 0, other_primitives = 0;
  double load_ms = 0;
};

// What the priority compiler (scene/priority_compiler.hpp) did at load, for the report: per
// subobject (Subobject::priority) and for the whole scene (Scene::priority).
struct PriorityCompileSummary {
  std::size_t subobjects = 0;                           // subobjects examined
  std::size_t ordered = 0;                              // the modeller's order is valid: kept
  std::size_t kept_not_valid = 0;                       // "priority_order": "modeller", though not valid from every eye
  std::size_t compiled = 0;                             // given a tree
  std::size_t too_large = 0;                            // splitting grew beyond max_growth: modeller's order kept
  std::size_t polygons_before = 0, polygons_after = 0;  // of the compiled subobjects
  std::size_t splits = 0, nodes = 0, slivers_dropped = 0;
  std::size_t cache_hits = 0, cache_writes = 0;
  // Objects that interpenetrate a model (bounding spheres overlapping, one layer) merged into one
  // object with one tree per group; subobjects whose crease angle gave way to the group's.
  std::size_t groups = 0, grouped_objects = 0, group_crease_changed = 0;
  double ms = 0;
};

// A node of a subobject's priority tree, made by the priority compiler
// (scene/priority_compiler.hpp). A partition node's polygons [first, first + count) lie in the
// plane of polygon `first`, and front and back are the chains on either side of it (-1: none); a
// run (front = back = -1) is polygons in an order valid from every eye. `next` continues the
// chain: it is drawn after this node and its subtrees. Node 0 starts the root chain. Walking it
// with the eye's side at each partition gives a visibility order from every eye position.
struct BspNode {
  std::uint32_t first = 0, count = 0;
  std::int32_t front = -1, back = -1, next = -1;
};

struct Subobject {
  std::string name;
  std::vector<glm::dvec3> vertices;  // object coordinates
  std::vector<Polygon> polygons;
  double crease_angle_deg = 50;  // vertex normals average only faces within this angle
  glm::dvec3 centre{0};          // object coordinates; used for depth sorting of subobjects
  // A model subobject's file (as the scene names it), the JSON field that named it ("model" or its
  // alias "obj"), its meshes' names and each polygon's mesh and face in the file, so that errors
  // found after loading (the polyhedron checks) can name them; empty for inline geometry.
  std::string model, model_field;
  std::vector<std::string> model_meshes;
  std::vector<ModelFaceRef> model_faces;
  ModelSummary model_summary;
  // The priority tree over the polygons (empty: the modeller's order is a visibility order from
  // every eye position, and is kept).
  // "priority_order": "tree" (the default for models): compiled when its order is not a visibility
  // order from every eye position; "modeller" (the default for inline polygons): kept as listed.
  bool priority_tree = false;
  std::vector<BspNode> bsp;
  PriorityCompileSummary priority;
};

// "mesh 'name' face F" (or "mesh M face F" for an unnamed mesh): where a model subobject's polygon
// comes from in its file.
std::string model_face_place(const Subobject& s, std::size_t polygon);

// One face plane of a convex polyhedron (stage F's input, SPEC F): n.r = offset in object
// coordinates, n the outward unit normal, so the interior is n.r < offset. Coplanar polygons
// (a triangulated box side) share one face.
struct PolyhedronFace {
  glm::dvec3 normal{0, 0, 1};
  double offset = 0;
};

struct Polyhedron {
  std::vector<PolyhedronFace> faces;
  // face_of[subobject][polygon]: the face each polygon lies on.
  std::vector<std::vector<std::int32_t>> face_of;
  bool reoriented = false;  // the polygons wound inward and were reversed at load
};

// A directional light's lobe ("beam"): seen from the eye at azimuth da and elevation de off the
// beam axis (both measured in the object's horizontal frame), the light's intensity is multiplied
// by f = max(0, 1 - (da/h)^2 - (de/v)^2), an elliptical lobe as the isocandela ellipses of ICAO
// Annex 14 Vol I, Appendix 2 give runway edge, threshold, end and approach lights.
struct LightBeam {
  // The axis' azimuth frame in object coordinates, as columns: x to the right of the axis' azimuth,
  // y along it (horizontal), z the object's up. Built from `heading` at load; objects merged into
  // an occlusion group and the world database rotate it with the object's pose.
  glm::dmat3 frame{1.0};
  double heading_deg = 0;     // the axis' azimuth, clockwise from the object's +y (as given)
  double elevation_deg = 0;   // the axis' elevation above the object's horizontal, [-90, 90]
  double horizontal_deg = 1;  // half-widths of the lobe, (0, 180]
  double vertical_deg = 1;
};

// A light whose colour changes with the eye's elevation seen from it (a PAPI or VASI unit: white
// above its transition angle, red below): `colour` below `elevation_deg` (world horizontal).
struct LightBelow {
  double elevation_deg = 0;  // [-90, 90]
  Rgb colour{1, 0, 0};
};

struct LightPoint {
  glm::dvec3 position{0};  // object coordinates
  double diameter = 1;     // metres
  Rgb colour{1, 1, 1};
  double intensity = 1;  // [0, 1]
  // Directional lights (both optional, independent): without them the light is omnidirectional.
  std::optional<LightBeam> beam;
  std::optional<LightBelow> below;
};

struct Pose {
  glm::dvec3 position{0};
  double heading_deg = 0, pitch_deg = 0, roll_deg = 0;
};

struct Object {
  std::string name;
  Pose pose;
  // Priority class: the scene manager orders visible objects by layer (higher first) and within a
  // layer by distance. Surfaces everything stands on (terrain, runways) go below the objects on
  // them, the sky below everything, because an object's centre distance alone cannot order a
  // building before the ground polygon that extends behind it.
  int layer = 0;
  // Subobject priority within the object (SPEC A.5): database order (decals before the surface
  // they lie on), or by distance from the observer to each subobject's centre (objects made of
  // separate parts, such as a row of tanks, whose order depends on the viewpoint).
  bool subobjects_by_distance = false;
  std::vector<Subobject> subobjects;
  std::vector<LightPoint> light_points;
  glm::dvec3 sphere_centre{0};  // object coordinates
  double sphere_radius = 0;
  bool sphere_given = false;
  // A closed convex polyhedron ("polyhedron": true), checked at load: its faces go to stage F.
  bool polyhedron = false;
  Polyhedron hull;
};

struct Keyframe {
  int frame = 0;
  Pose pose;
};

struct Channel {
  std::string name;
  double yaw_deg = 0, pitch_deg = 0;  // offsets from the observer's orientation
  double fov_deg = 40;                // full field of view, horizontal = vertical (square raster)
};

struct Lighting {
  glm::dvec3 sun_direction{0, 0, 1};  // unit vector pointing towards the sun
  double sun_intensity = 0.7;
  double ambient = 0.3;
};

struct Fog {
  Rgb colour{0.5, 0.5, 0.5};
  double start = 1e30, end = 2e30;  // eye depth (metres) where fog begins and becomes total
};

struct LightPointRendering {
  // Projected light diameters are raised to at least this many formatter grid units, so that a
  // distant runway light still covers sub-pixel samples (real CIGs draw a minimum spot size).
  double min_diameter_units = 3;
};

struct Scene {
  std::string file;  // where it was loaded from; relative model paths resolve against it
  std::string name;
  int raster = 512;
  double near = 1.0;
  // Visibility range (eye depth, metres): objects whose bounding sphere lies wholly beyond it are
  // not drawn (the scene manager culls them); unlimited by default.
  double range = std::numeric_limits<double>::infinity();
  std::vector<Channel> channels;
  Lighting lighting;
  Fog fog;
  Rgb background{0.5, 0.5, 0.5};
  LightPointRendering light_rendering;
  std::vector<Keyframe> keyframes;  // strictly increasing frames, the first at frame 0
  std::vector<Object> objects;
  PriorityCompileSummary priority;

  int frame_count() const { return keyframes.empty() ? 0 : keyframes.back().frame + 1; }
  std::size_t polygon_count() const;
  std::size_t light_point_count() const;
};

// Rotation from body axes (x right, y forward, z up) to world axes for a heading (clockwise from
// north), pitch (nose up) and roll (right wing down), all in degrees.
glm::dmat3 body_to_world(double heading_deg, double pitch_deg, double roll_deg);

// Observer pose at `frame` by linear interpolation between keyframes (heading along the shorter arc).
Pose observer_pose(const Scene& scene, int frame);

}  // namespace cig
