// SPDX-License-Identifier: MIT
// Writes docs/recording-format.md version 1 as the World reports segments and collisions.
#include <fstream>
#include <map>
#include <string>

#include "io/recording_bytes.hpp"
#include "io/recording_json.hpp"
#include "sparsedyn/io/recording.hpp"

namespace sparsedyn {

using namespace recording;  // NOLINT(google-build-using-namespace): the format's constants

namespace {

// Flush the buffer to the file once it holds this many bytes.
constexpr std::size_t kFlushBytes = 1 << 20;

std::string EncodeSegment(const RecordedSegment& segment) {
  std::string bytes;
  PutU8(bytes, kTagSegment);
  PutU8(bytes, static_cast<std::uint8_t>((segment.has_acceleration ? kSegmentHasAcceleration : 0) |
                                         (segment.has_rotation ? kSegmentHasRotation : 0)));
  PutU32(bytes, segment.body);
  PutF64(bytes, segment.t0);
  PutVec3(bytes, segment.position);
  PutVec3(bytes, segment.velocity);
  if (segment.has_acceleration) PutVec3(bytes, segment.acceleration);
  if (segment.has_rotation) {
    const Eigen::Quaterniond& q = segment.orientation;
    for (const double c : {q.w(), q.x(), q.y(), q.z()}) PutF64(bytes, c);
    PutVec3(bytes, segment.angular_velocity);
  }
  return bytes;
}

// A segment of the World; the acceleration is stored only when it is not zero, the orientation
// and angular velocity only when the body is turned or turning (a sphere never is).
RecordedSegment FromWorld(const MotionSegment& segment) {
  RecordedSegment record;
  record.body = segment.body.index;
  record.t0 = segment.t0;
  record.position = segment.position;
  record.velocity = segment.velocity;
  record.acceleration = segment.acceleration;
  record.has_acceleration = !segment.acceleration.isZero(0.0);
  record.orientation = segment.orientation;
  record.angular_velocity = segment.angular_velocity;
  record.has_rotation = !segment.angular_velocity.isZero(0.0) ||
                        segment.orientation.coeffs() != Eigen::Quaterniond::Identity().coeffs();
  return record;
}

std::string EncodeCollision(const CollisionEvent& collision) {
  const bool wall = !collision.b.valid();
  std::string bytes;
  PutU8(bytes, kTagCollision);
  PutU8(bytes, wall ? kCollisionWithWall : 0);
  PutU32(bytes, collision.a.index);
  PutU32(bytes, wall ? static_cast<std::uint32_t>(collision.wall) : collision.b.index);
  PutF64(bytes, collision.time);
  PutVec3(bytes, collision.point);
  PutVec3(bytes, collision.normal);
  PutF64(bytes, collision.impulse);
  return bytes;
}

}  // namespace

class RecordingWriter::Impl {
 public:
  Impl(std::filesystem::path path, std::ofstream file)
      : path_(std::move(path)), file_(std::move(file)) {}

  void Append(const std::string& bytes) {
    buffer_ += bytes;
    if (buffer_.size() >= kFlushBytes) Flush();
  }

  void Flush() {
    file_.write(buffer_.data(), static_cast<std::streamsize>(buffer_.size()));
    written_ += buffer_.size();
    buffer_.clear();
  }

  std::uint64_t Bytes() const { return written_ + buffer_.size(); }

  std::filesystem::path path_;
  std::ofstream file_;
  std::string buffer_;
  std::uint64_t written_ = 0;
  bool finished_ = false;
};

std::pair<RecordingHeader, std::vector<RecordedBody>> DescribeForRecording(const World& world,
                                                                           std::string scene,
                                                                           std::uint64_t seed,
                                                                           double end_time) {
  RecordingHeader header;
  header.scene = std::move(scene);
  header.seed = seed;
  header.bodies = static_cast<std::uint32_t>(world.BodyCount());
  header.container = world.Settings().container;
  header.gravity = world.Settings().gravity;
  header.start_time = world.Time();
  header.end_time = end_time;

  // One sphere shape per distinct radius, in order of first use.
  std::map<double, std::uint32_t> shape_of_radius;
  std::vector<RecordedBody> bodies;
  bodies.reserve(world.BodyCount());
  for (std::uint32_t i = 0; i < header.bodies; ++i) {
    const BodyState state = world.StateAt(world.IdOf(i), world.Time());
    auto [it, inserted] =
        shape_of_radius.try_emplace(state.radius, static_cast<std::uint32_t>(header.shapes.size()));
    if (inserted) header.shapes.push_back({RecordingShape::Kind::kSphere, state.radius, {}});
    const std::uint32_t flags = (world.IsStatic(world.IdOf(i)) ? kBodyStatic : 0u) |
                                (world.IsGod(world.IdOf(i)) ? kBodyGod : 0u);
    bodies.push_back({it->second, flags, state.mass, state.radius});
  }
  return {std::move(header), std::move(bodies)};
}

std::pair<RecordingHeader, std::vector<RecordedBody>> DescribeForRecording(
    const SceneDescription& scene, double end_time) {
  RecordingHeader header;
  header.scene = scene.name;
  header.seed = scene.seed;
  header.bodies = static_cast<std::uint32_t>(scene.bodies.size());
  header.container = scene.settings.container;
  header.gravity = scene.settings.gravity;
  header.start_time = scene.settings.start_time;
  header.end_time = end_time;
  for (const SceneShape& shape : scene.shapes) {
    if (shape.kind == SceneShape::Kind::kSphere) {
      header.shapes.push_back({RecordingShape::Kind::kSphere, shape.radius, {}});
    } else {
      header.shapes.push_back(
          {RecordingShape::Kind::kPolyhedron, shape.radius, shape.polyhedron->ToMesh()});
    }
  }
  std::vector<RecordedBody> bodies;
  bodies.reserve(scene.bodies.size());
  for (const SceneBody& body : scene.bodies) {
    const std::uint32_t flags = (body.is_static ? kBodyStatic : 0u) | (body.god ? kBodyGod : 0u);
    bodies.push_back({body.shape, flags, body.mass, scene.shapes[body.shape].radius});
  }
  return {std::move(header), std::move(bodies)};
}

Result<RecordingWriter> RecordingWriter::Open(const std::filesystem::path& path,
                                              const RecordingHeader& header,
                                              const std::vector<RecordedBody>& bodies) {
  const std::string name = path.string();
  if (bodies.size() != header.bodies) {
    return Error{name + ": the header announces " + std::to_string(header.bodies) + " bodies but " +
                 std::to_string(bodies.size()) + " body records were given"};
  }
  for (std::size_t i = 0; i < bodies.size(); ++i) {
    if (bodies[i].shape >= header.shapes.size()) {
      return Error{name + ": body " + std::to_string(i) + " names shape " +
                   std::to_string(bodies[i].shape) + " but the header has " +
                   std::to_string(header.shapes.size()) + " shapes"};
    }
  }
  std::ofstream file(path, std::ios::binary | std::ios::trunc);
  if (!file) return Error{name + ": cannot open for writing"};

  // Header: magic, version, JSON length, JSON; then the fixed-size body records.
  auto impl = std::make_unique<Impl>(path, std::move(file));
  const std::string json = HeaderToJson(header).dump();
  std::string bytes(kRecordingMagic);
  PutU32(bytes, kRecordingVersion);
  PutU32(bytes, static_cast<std::uint32_t>(json.size()));
  bytes += json;
  for (const RecordedBody& body : bodies) {
    PutU32(bytes, body.shape);
    PutU32(bytes, body.flags);
    PutF64(bytes, body.mass);
    PutF64(bytes, body.bounding_radius);
  }
  impl->Append(bytes);
  return RecordingWriter(std::move(impl));
}

RecordingWriter::RecordingWriter(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
RecordingWriter::RecordingWriter(RecordingWriter&&) noexcept = default;
RecordingWriter& RecordingWriter::operator=(RecordingWriter&&) noexcept = default;
RecordingWriter::~RecordingWriter() = default;

void RecordingWriter::Attach(World& world) {
  const double t = world.Time();
  for (std::uint32_t i = 0; i < world.BodyCount(); ++i) {
    const BodyState state = world.StateAt(world.IdOf(i), t);
    MotionSegment segment{t, world.IdOf(i), state.position, state.velocity, state.acceleration,
                          state.version};
    segment.orientation = state.orientation;
    segment.angular_velocity = state.angular_velocity;
    Write(segment);
  }
  // The callbacks hold the Impl, whose address survives moves of the writer.
  Impl* impl = impl_.get();
  world.OnSegment(
      [impl](const MotionSegment& segment) { impl->Append(EncodeSegment(FromWorld(segment))); });
  world.OnCollision(
      [impl](const CollisionEvent& collision) { impl->Append(EncodeCollision(collision)); });
}

void RecordingWriter::Write(const RecordedSegment& segment) {
  impl_->Append(EncodeSegment(segment));
}

void RecordingWriter::Write(const MotionSegment& segment) {
  impl_->Append(EncodeSegment(FromWorld(segment)));
}

void RecordingWriter::Write(const CollisionEvent& collision) {
  impl_->Append(EncodeCollision(collision));
}

Status RecordingWriter::Finish(double end_time) {
  if (impl_->finished_) return Error{impl_->path_.string() + ": recording already finished"};
  std::string bytes;
  PutU8(bytes, kTagEnd);
  PutF64(bytes, end_time);
  impl_->Append(bytes);
  impl_->Flush();
  impl_->file_.close();
  impl_->finished_ = true;
  if (impl_->file_.fail()) return Error{impl_->path_.string() + ": write failed (disk full?)"};
  return Status::Ok();
}

std::uint64_t RecordingWriter::BytesWritten() const { return impl_->Bytes(); }

}  // namespace sparsedyn
