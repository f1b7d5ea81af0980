// SPDX-License-Identifier: MIT
#pragma once

#include <Eigen/Geometry>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <ostream>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "sparsedyn/geometry/polygon_mesh.hpp"
#include "sparsedyn/io/scene_file.hpp"
#include "sparsedyn/result.hpp"
#include "sparsedyn/types.hpp"
#include "sparsedyn/world.hpp"

namespace sparsedyn {

/// The version of docs/recording-format.md that this library writes and reads.
inline constexpr std::uint32_t kRecordingVersion = 1;
/// The 8 bytes every recording starts with.
inline constexpr std::string_view kRecordingMagic{"SDREC\r\n\x1a", 8};

/// A shape of the recording header's `shapes` table.
struct RecordingShape {
  /// A sphere of `radius`, or the polyhedron `mesh`.
  enum class Kind { kSphere, kPolyhedron };
  /// Which of the two.
  Kind kind = Kind::kSphere;
  double radius = 0.0;  ///< sphere radius, m
  /// Polyhedron in its body frame (centroid at the origin), faces counter-clockwise from outside.
  PolygonMesh mesh;
};

/// The recording header (its JSON part, docs/recording-format.md "Header JSON").
struct RecordingHeader {
  /// The program and version that wrote the recording.
  std::string generator = "sparsedyn 0.1.0";
  std::string scene;  ///< preset name or scene file name
  /// The scene's seed.
  std::uint64_t seed = 0;
  std::uint32_t bodies = 0;  ///< number of body records that follow the header
  /// The World's container.
  Container container;
  /// The World's gravity, m/s^2.
  Vec3 gravity = Vec3::Zero();
  /// The distinct shapes; bodies refer to them by index.
  std::vector<RecordingShape> shapes;
  /// The time of the first segments, s.
  double start_time = 0.0;
  double end_time = 0.0;  ///< the time the run was asked to reach
};

/// RecordedBody::flags bit 0: a static body (it never moves).
inline constexpr std::uint32_t kBodyStatic = 1;
/// RecordedBody::flags bit 1: a god object (driven from outside, infinite mass).
inline constexpr std::uint32_t kBodyGod = 2;

/// A body record: static data of one body.
struct RecordedBody {
  std::uint32_t shape = 0;       ///< index into RecordingHeader::shapes
  std::uint32_t flags = 0;       ///< kBodyStatic, kBodyGod; other bits reserved, 0
  double mass = 1.0;             ///< kg
  double bounding_radius = 0.0;  ///< radius of the element's sphere, m
};

/// A motion segment (tag 1): from t0 on, `body` follows
/// position + velocity (t - t0) + acceleration (t - t0)^2 / 2, rotating at angular_velocity
/// (world frame) from `orientation` at t0.
struct RecordedSegment {
  /// The body's index (its RecordedBody).
  std::uint32_t body = 0;
  /// When the segment starts, s.
  double t0 = 0.0;
  Vec3 position = Vec3::Zero();  ///< world frame; in a periodic box not wrapped into the box
  /// At t0, m/s.
  Vec3 velocity = Vec3::Zero();
  /// Constant over the segment, m/s^2.
  Vec3 acceleration = Vec3::Zero();
  Eigen::Quaterniond orientation = Eigen::Quaterniond::Identity();  ///< (w, x, y, z)
  /// rad/s, world frame, constant over the segment.
  Vec3 angular_velocity = Vec3::Zero();
  bool has_acceleration = false;  ///< flags bit 0: acceleration is stored
  bool has_rotation = false;      ///< flags bit 1: orientation and angular velocity are stored

  /// The centre at time t (>= t0), evaluated exactly as the World evaluates its paths, so that
  /// a replay matches World::StateAt bit for bit (before periodic wrapping).
  Vec3 PositionAt(double t) const {
    const double dt = t - t0;
    return position + dt * (velocity + (0.5 * dt) * acceleration);
  }
  /// The velocity at time t (>= t0).
  Vec3 VelocityAt(double t) const { return velocity + (t - t0) * acceleration; }
};

/// A resolved collision (tag 2).
struct RecordedCollision {
  /// When the bodies touched, s.
  double time = 0.0;
  std::uint32_t a = 0;         ///< body index
  std::uint32_t b = 0;         ///< body index, or wall index 0..5 (-x,+x,-y,+y,-z,+z) if b_is_wall
  bool b_is_wall = false;      ///< flags bit 0
  Vec3 point = Vec3::Zero();   ///< contact point, world frame
  Vec3 normal = Vec3::Zero();  ///< unit, from a towards b
  double impulse = 0.0;        ///< N s along the normal
};

/// One tagged record of the stream, in file order.
using RecordingRecord = std::variant<RecordedSegment, RecordedCollision>;

/// A whole recording as read from a file.
struct Recording {
  /// The header.
  RecordingHeader header;
  /// One record per body, in body order.
  std::vector<RecordedBody> bodies;
  std::vector<RecordingRecord> records;  ///< segments and collisions, in file (= event) order
  double end_time = 0.0;                 ///< from the end record
};

/// The header and body records that describe `world` as it is now: one sphere shape per
/// distinct radius, each body's mass and bounding radius. For worlds built in code.
std::pair<RecordingHeader, std::vector<RecordedBody>> DescribeForRecording(const World& world,
                                                                           std::string scene,
                                                                           std::uint64_t seed,
                                                                           double end_time);

/// The header and body records of a scene before it runs (from its start time): its shapes table
/// as it is (polyhedra as their meshes in the body frame, centroid at the origin) and every
/// body's mass and bounding radius. The segments of polyhedra carry their orientation and angular
/// velocity (RecordedSegment::has_rotation).
std::pair<RecordingHeader, std::vector<RecordedBody>> DescribeForRecording(
    const SceneDescription& scene, double end_time);

/// Writes a recording file as the World runs (docs/recording-format.md). Usage:
///   auto writer = RecordingWriter::Open(path, header, bodies);   // header + body records
///   writer->Attach(world);          // first segment of every body, then hooks the callbacks
///   world.AdvanceTo(t);             // segments and collisions are written as they happen
///   writer->Finish(world.Time());   // end record; the file is complete only after this
/// Writes are buffered; I/O errors are reported by Finish.
class RecordingWriter {
 public:
  /// Creates (truncates) `path` and writes the header and the body records. An Error names the
  /// path when it cannot be opened, or when `bodies.size() != header.bodies` or a body names a
  /// shape that is not in the header.
  static Result<RecordingWriter> Open(const std::filesystem::path& path,
                                      const RecordingHeader& header,
                                      const std::vector<RecordedBody>& bodies);

  /// Moves the open file.
  RecordingWriter(RecordingWriter&&) noexcept;
  /// Moves the open file.
  RecordingWriter& operator=(RecordingWriter&&) noexcept;
  ~RecordingWriter();

  /// Writes the first segment of every body of `world` (its state at world.Time()) and installs
  /// OnSegment and OnCollision callbacks on `world` that write every later record. This
  /// replaces callbacks the world had: a caller that needs its own calls Write() from them.
  /// The writer must outlive the world's use of the callbacks (until Finish).
  void Attach(World& world);

  /// Appends one record. Records must come in event order (non-decreasing time).
  void Write(const RecordedSegment& segment);
  /// Appends the World's segment as a RecordedSegment.
  void Write(const MotionSegment& segment);
  /// Appends the World's collision as a RecordedCollision.
  void Write(const CollisionEvent& collision);

  /// Writes the end record and closes the file; an Error names the path on any I/O failure.
  Status Finish(double end_time);

  /// Bytes written so far (header included).
  std::uint64_t BytesWritten() const;

 private:
  class Impl;
  explicit RecordingWriter(std::unique_ptr<Impl> impl);
  std::unique_ptr<Impl> impl_;
};

/// Reads a whole recording. Every malformed file is an Error that names the file and says what
/// is wrong: bad magic, an unknown version (naming it and the version this reader knows), a
/// truncated file (at which record and byte), an unknown tag, an index out of range, time going
/// backwards, bytes after the end record. Counts in the file are checked against the bytes that
/// are left before anything is reserved.
Result<Recording> ReadRecording(const std::filesystem::path& path);

/// ReadRecording on the bytes of a file; `name` stands for the file name in error messages.
Result<Recording> ParseRecording(std::string_view bytes, std::string_view name);

/// Writes `recording` as JSON lines: one object per record ({"record": "header", ...},
/// {"record": "body", ...}, {"record": "segment", ...}, {"record": "collision", ...},
/// {"record": "end", ...}) with the field names of docs/recording-format.md.
void WriteJsonLines(const Recording& recording, std::ostream& out);

}  // namespace sparsedyn
