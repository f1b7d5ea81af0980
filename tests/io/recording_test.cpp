// SPDX-License-Identifier: MIT
// The recording (docs/recording-format.md): what is written reads back bit for bit, replaying
// its paths gives the World's own positions, and every class of malformed file is a clear error.
#include "sparsedyn/io/recording.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "scenes/gas.hpp"

namespace sparsedyn {
namespace {

// Replayed and World positions are evaluated by the same formula from the same doubles; the
// only difference allowed is the periodic wrap (one rounding of a multiple of the box side).
constexpr double kReplayTolerance = 1e-12;

std::filesystem::path TempPath(const std::string& name) {
  return std::filesystem::temp_directory_path() /
         ("sparsedyn_rec_" + std::to_string(::getpid()) + "_" + name);
}

std::string FileBytes(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream content;
  content << in.rdbuf();
  return content.str();
}

// The gas of the replay tests: periodic, or walled with gravity (accelerated segments).
World MakeScene(bool periodic) {
  scenes::GasOptions options;
  options.n = 200;
  options.packing = 0.10;
  options.seed = 7;
  options.periodic = periodic;
  WorldSettings settings;
  if (!periodic) settings.gravity = Vec3(0, 0, -2);
  Result<World> world = scenes::MakeGas(options, settings);
  SPARSEDYN_ASSERT(world.ok(), "test scene");
  return std::move(*world);
}

// Runs a fresh scene to `until` while recording it to `path`; returns what the World reported.
std::vector<RecordingRecord> RecordRun(bool periodic, double until,
                                       const std::filesystem::path& path) {
  World world = MakeScene(periodic);
  auto [header, bodies] = DescribeForRecording(world, "gas", 7, until);
  Result<RecordingWriter> writer = RecordingWriter::Open(path, header, bodies);
  EXPECT_TRUE(writer.ok());
  writer->Attach(world);
  // What the writer was given, collected beside it.
  std::vector<RecordingRecord> seen;
  for (std::uint32_t i = 0; i < world.BodyCount(); ++i) {
    const BodyState s = world.StateAt(world.IdOf(i), 0.0);
    RecordedSegment segment{
        .body = i, .position = s.position, .velocity = s.velocity, .acceleration = s.acceleration};
    segment.has_acceleration = !s.acceleration.isZero(0.0);
    seen.emplace_back(segment);
  }
  world.OnSegment([&](const MotionSegment& m) {
    writer->Write(m);
    RecordedSegment segment{.body = m.body.index,
                            .t0 = m.t0,
                            .position = m.position,
                            .velocity = m.velocity,
                            .acceleration = m.acceleration};
    segment.has_acceleration = !m.acceleration.isZero(0.0);
    seen.emplace_back(segment);
  });
  world.OnCollision([&](const CollisionEvent& c) {
    writer->Write(c);
    const bool wall = !c.b.valid();
    seen.emplace_back(RecordedCollision{c.time, c.a.index,
                                        wall ? static_cast<std::uint32_t>(c.wall) : c.b.index, wall,
                                        c.point, c.normal, c.impulse});
  });
  EXPECT_TRUE(world.AdvanceTo(until));
  EXPECT_TRUE(writer->Finish(world.Time()));
  EXPECT_EQ(writer->BytesWritten(), std::filesystem::file_size(path));
  return seen;
}

bool SameBits(const Vec3& a, const Vec3& b) { return std::memcmp(a.data(), b.data(), 24) == 0; }

TEST(Recording, RoundTripGivesBackEveryRecordBitForBit) {
  const std::filesystem::path path = TempPath("roundtrip.sdrec");
  const std::vector<RecordingRecord> seen = RecordRun(/*periodic=*/false, 5.0, path);
  Result<Recording> read = ReadRecording(path);
  ASSERT_TRUE(read.ok()) << read.error().message;
  EXPECT_EQ(read->header.bodies, 200u);
  EXPECT_EQ(read->header.container.kind, Container::Kind::kWalledBox);
  EXPECT_EQ(read->header.gravity, Vec3(0, 0, -2));
  ASSERT_EQ(read->header.shapes.size(), 1u);
  EXPECT_EQ(read->header.shapes[0].radius, 0.5);
  EXPECT_EQ(read->end_time, 5.0);
  ASSERT_EQ(read->records.size(), seen.size());
  std::size_t collisions = 0;
  for (std::size_t k = 0; k < seen.size(); ++k) {
    SCOPED_TRACE("record " + std::to_string(k));
    ASSERT_EQ(read->records[k].index(), seen[k].index());
    if (const auto* s = std::get_if<RecordedSegment>(&seen[k])) {
      const auto& r = std::get<RecordedSegment>(read->records[k]);
      EXPECT_EQ(r.body, s->body);
      EXPECT_EQ(r.t0, s->t0);
      EXPECT_TRUE(SameBits(r.position, s->position));
      EXPECT_TRUE(SameBits(r.velocity, s->velocity));
      EXPECT_TRUE(SameBits(r.acceleration, s->acceleration));
      EXPECT_TRUE(r.has_acceleration);  // gravity
      EXPECT_FALSE(r.has_rotation);
    } else {
      const auto& c = std::get<RecordedCollision>(seen[k]);
      const auto& r = std::get<RecordedCollision>(read->records[k]);
      EXPECT_EQ(r.time, c.time);
      EXPECT_EQ(r.a, c.a);
      EXPECT_EQ(r.b, c.b);
      EXPECT_EQ(r.b_is_wall, c.b_is_wall);
      EXPECT_TRUE(SameBits(r.point, c.point));
      EXPECT_TRUE(SameBits(r.normal, c.normal));
      EXPECT_EQ(r.impulse, c.impulse);
      ++collisions;
    }
  }
  EXPECT_GT(collisions, 100u);
  std::filesystem::remove(path);
}

// Positions from the recording's segments at any time (the viewer's job, done in C++).
class Replay {
 public:
  explicit Replay(const Recording& recording) : segments_(recording.bodies.size()) {
    for (const RecordingRecord& record : recording.records) {
      if (const auto* s = std::get_if<RecordedSegment>(&record)) segments_[s->body].push_back(*s);
    }
  }
  Vec3 PositionAt(std::uint32_t body, double t) const {
    const std::vector<RecordedSegment>& list = segments_[body];
    // The last segment that starts at or before t.
    auto it = std::upper_bound(list.begin(), list.end(), t,
                               [](double time, const RecordedSegment& s) { return time < s.t0; });
    SPARSEDYN_ASSERT(it != list.begin(), "a body's first segment starts the recording");
    return std::prev(it)->PositionAt(t);
  }

 private:
  std::vector<std::vector<RecordedSegment>> segments_;
};

// Replays at 10^4 random times and compares every body with StateAt of a second, identical run.
void ExpectReplayMatchesWorld(bool periodic) {
  constexpr double kUntil = 20.0;
  const std::filesystem::path path = TempPath(periodic ? "periodic.sdrec" : "walled.sdrec");
  (void)RecordRun(periodic, kUntil, path);
  Result<Recording> recording = ReadRecording(path);
  ASSERT_TRUE(recording.ok()) << recording.error().message;
  std::filesystem::remove(path);
  const Replay replay(*recording);

  std::mt19937_64 random(20261122);
  std::vector<double> times(10000);
  for (double& t : times) t = kUntil * static_cast<double>(random() >> 11) * 0x1.0p-53;
  std::sort(times.begin(), times.end());

  World world = MakeScene(periodic);
  const Container& box = world.Settings().container;
  const Vec3 side = box.hi - box.lo;
  double max_error = 0;
  for (const double t : times) {
    ASSERT_TRUE(world.AdvanceTo(t));
    for (std::uint32_t i = 0; i < world.BodyCount(); ++i) {
      Vec3 d = replay.PositionAt(i, t) - world.StateAt(world.IdOf(i), t).position;
      if (periodic) {
        for (int k = 0; k < 3; ++k) d[k] -= side[k] * std::round(d[k] / side[k]);
      }
      max_error = std::max(max_error, d.lpNorm<Eigen::Infinity>());
    }
  }
  std::printf("replay vs StateAt (%s): max |error| %.3g m over 10^4 times x %zu bodies\n",
              periodic ? "periodic gas" : "walled gas with gravity", max_error, world.BodyCount());
  EXPECT_LE(max_error, kReplayTolerance * side.maxCoeff());
}

TEST(Recording, ReplayMatchesStateAtInAPeriodicGas) { ExpectReplayMatchesWorld(true); }
TEST(Recording, ReplayMatchesStateAtInAWalledGasWithGravity) { ExpectReplayMatchesWorld(false); }

TEST(Recording, PolyhedralScenesAreDescribedWithTheirMeshesAndRotatingSegments) {
  // What issue #4 will write: a scene's polyhedra in the header, rotating segments.
  Result<SceneDescription> scene = ParseScene(
      R"({"bodies": [{"shape": {"sphere": {"radius": 0.5}}},)"
      R"( {"shape": {"generator": "random_convex", "faces": 24, "seed": 5}, "position": [4, 0, 0],)"
      R"( "density": 3}]})",
      "poly.json", ".");
  ASSERT_TRUE(scene.ok()) << scene.error().message;
  auto [header, bodies] = DescribeForRecording(*scene, 1.0);
  const std::filesystem::path path = TempPath("poly.sdrec");
  Result<RecordingWriter> writer = RecordingWriter::Open(path, header, bodies);
  ASSERT_TRUE(writer.ok());
  RecordedSegment spinning{.body = 1,
                           .position = Vec3(4, 0, 0),
                           .velocity = Vec3(-1, 0, 0),
                           .orientation = Eigen::Quaterniond(0.5, 0.5, 0.5, 0.5),
                           .angular_velocity = Vec3(0, 0, 2)};
  spinning.has_rotation = true;
  writer->Write(RecordedSegment{.body = 0});
  const std::uint64_t before = writer->BytesWritten();
  writer->Write(spinning);
  EXPECT_EQ(writer->BytesWritten() - before, 118u);  // docs/recording-format.md
  ASSERT_TRUE(writer->Finish(1.0));

  Result<Recording> read = ReadRecording(path);
  std::filesystem::remove(path);
  ASSERT_TRUE(read.ok()) << read.error().message;
  ASSERT_EQ(read->header.shapes.size(), 2u);
  const RecordingShape& shape = read->header.shapes[1];
  EXPECT_EQ(shape.kind, RecordingShape::Kind::kPolyhedron);
  const PolygonMesh mesh = scene->shapes[1].polyhedron->ToMesh();
  EXPECT_EQ(shape.mesh.faces, mesh.faces);
  ASSERT_EQ(shape.mesh.vertices.size(), mesh.vertices.size());
  for (std::size_t v = 0; v < mesh.vertices.size(); ++v) {
    EXPECT_TRUE(SameBits(shape.mesh.vertices[v], mesh.vertices[v]));
  }
  EXPECT_EQ(read->bodies[1].mass, scene->bodies[1].mass);
  EXPECT_EQ(read->bodies[1].bounding_radius, scene->shapes[1].radius);
  const auto& segment = std::get<RecordedSegment>(read->records[1]);
  EXPECT_TRUE(segment.has_rotation);
  EXPECT_EQ(segment.orientation.coeffs(), spinning.orientation.coeffs());
  EXPECT_EQ(segment.angular_velocity, Vec3(0, 0, 2));
}

// --- malformed files --------------------------------------------------------------------------

// A small valid recording's bytes (two bodies, one collision).
std::string SmallRecording() {
  const std::filesystem::path path = TempPath("small.sdrec");
  World world({.container = Container::WalledBox(Vec3::Zero(), Vec3::Constant(10))});
  (void)world.AddBody({.radius = 0.5, .position = {3, 5, 5}, .velocity = {1, 0, 0}});
  (void)world.AddBody({.radius = 0.5, .position = {7, 5, 5}, .velocity = {-1, 0, 0}});
  auto [header, bodies] = DescribeForRecording(world, "two", 0, 2.5);
  Result<RecordingWriter> writer = RecordingWriter::Open(path, header, bodies);
  writer->Attach(world);
  EXPECT_TRUE(world.AdvanceTo(2.5));
  EXPECT_TRUE(writer->Finish(2.5));
  std::string bytes = FileBytes(path);
  std::filesystem::remove(path);
  return bytes;
}

std::string ErrorOf(const std::string& bytes) {
  Result<Recording> r = ParseRecording(bytes, "x.sdrec");
  return r ? std::string("<parsed>") : r.error().message;
}

bool Contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

// Offset of the first tagged record: after the preamble, the header JSON and the body records.
std::size_t StreamStart(const std::string& bytes) {
  std::uint32_t header_bytes = 0;
  std::memcpy(&header_bytes, bytes.data() + 12, 4);
  return 16 + header_bytes + 2 * 24;
}

TEST(MalformedRecording, SmallRecordingParses) {
  const std::string bytes = SmallRecording();
  EXPECT_EQ(ErrorOf(bytes), "<parsed>");
  // Two first segments, two segments and one collision at t = 1.5, the end record.
  EXPECT_EQ(bytes.size(), StreamStart(bytes) + 4 * 62 + 74 + 9);
}

TEST(MalformedRecording, BadMagicSaysWhatWasFound) {
  std::string bytes = SmallRecording();
  bytes.replace(0, 4, "PK\x03\x04");
  const std::string error = ErrorOf(bytes);
  EXPECT_TRUE(Contains(error, "x.sdrec: not a sparsedyn recording (bad magic")) << error;
  EXPECT_TRUE(Contains(error, "found \"PK\\x03\\x04")) << error;
  EXPECT_TRUE(Contains(ErrorOf(""), "bad magic")) << ErrorOf("");
  EXPECT_TRUE(Contains(ErrorOf("{\"bodies\": 1}"), "bad magic"));
}

TEST(MalformedRecording, UnknownVersionNamesBothVersions) {
  std::string bytes = SmallRecording();
  bytes[8] = 7;
  EXPECT_EQ(ErrorOf(bytes),
            "x.sdrec: recording version 7 is not supported (this reader knows version 1)");
}

TEST(MalformedRecording, EveryTruncationIsAnErrorThatSaysTruncated) {
  const std::string bytes = SmallRecording();
  const std::size_t stream = StreamStart(bytes);
  for (std::size_t size = 0; size < bytes.size(); ++size) {
    SCOPED_TRACE("cut at " + std::to_string(size));
    const std::string error = ErrorOf(bytes.substr(0, size));
    ASSERT_NE(error, "<parsed>");
    // A cut inside the magic is a bad magic; anywhere later it is a truncated file.
    EXPECT_TRUE(Contains(error, size < 8 ? "bad magic" : "truncated file")) << error;
  }
  // Inside the stream the message names the record and the byte.
  EXPECT_EQ(ErrorOf(bytes.substr(0, stream + 62 + 30)),
            "x.sdrec: byte " + std::to_string(stream + 62) +
                ": truncated file: record 1 (segment) needs 62 bytes, 30 left");
  EXPECT_EQ(ErrorOf(bytes.substr(0, bytes.size() - 9)),
            "x.sdrec: byte " + std::to_string(bytes.size() - 9) +
                ": truncated file: no end record after record 5 (the run did not finish writing)");
}

TEST(MalformedRecording, DamagedStreamNamesRecordAndByte) {
  const std::string good = SmallRecording();
  const std::size_t stream = StreamStart(good);
  std::string bytes = good;
  bytes[stream + 62] = 9;  // tag of record 1
  EXPECT_EQ(ErrorOf(bytes), "x.sdrec: byte " + std::to_string(stream + 62) +
                                ": record 1: unknown tag 9 (1 segment, 2 collision, 3 end)");
  bytes = good;
  bytes[stream + 2] = 5;  // body index of record 0
  EXPECT_EQ(ErrorOf(bytes), "x.sdrec: byte " + std::to_string(stream) +
                                ": record 0: body = 5 but there are 2 bodies");
  // The first segment of every body comes before any other record.
  bytes = good;
  bytes[stream + 62 + 2] = 0;  // record 1: a second segment of body 0, none yet for body 1
  EXPECT_EQ(ErrorOf(bytes), "x.sdrec: byte " + std::to_string(stream + 62) +
                                ": record 1: body 1 has no first segment (those come before "
                                "any other record)");
  bytes = good + "xyz";
  EXPECT_EQ(ErrorOf(bytes),
            "x.sdrec: byte " + std::to_string(good.size()) + ": 3 bytes after the end record");
  // Time going backwards: the end record at t = -1.
  bytes = good;
  const double minus_one = -1.0;
  std::memcpy(bytes.data() + bytes.size() - 8, &minus_one, 8);
  EXPECT_TRUE(Contains(ErrorOf(bytes), "is before the previous record's")) << ErrorOf(bytes);
}

TEST(MalformedRecording, BadHeaderJsonNamesTheKey) {
  auto with_header = [](const std::string& json) {
    std::string bytes(kRecordingMagic);
    const std::uint32_t version = 1, size = static_cast<std::uint32_t>(json.size());
    bytes.append(reinterpret_cast<const char*>(&version), 4);
    bytes.append(reinterpret_cast<const char*>(&size), 4);
    return bytes + json;
  };
  EXPECT_EQ(ErrorOf(with_header("{not json")),
            "x.sdrec: the header is not valid JSON (bytes 16..25)");
  EXPECT_EQ(ErrorOf(with_header("{}")), "x.sdrec: header: bodies is missing");
  EXPECT_EQ(ErrorOf(with_header(R"({"bodies": -1})")),
            "x.sdrec: header: bodies must be an integer in [0, 4294967295]");
  const std::string base =
      R"({"bodies": 0, "container": {"kind": "walled", "lo": [0,0,0], "hi": [1,1,"x"]},)"
      R"( "shapes": [], "start_time": 0, "end_time": 1})";
  EXPECT_EQ(ErrorOf(with_header(base)), "x.sdrec: header: container.hi[2] must be a number");
  // A hostile body count is refused from the size of the file, before anything is reserved.
  const std::string hostile =
      R"({"bodies": 2147483648, "container": {"kind": "open"}, "shapes": [{"type": "sphere",)"
      R"( "radius": 1}], "start_time": 0, "end_time": 1})";
  EXPECT_TRUE(Contains(ErrorOf(with_header(hostile)),
                       "truncated file: 2147483648 body records need 51539607552 bytes"))
      << ErrorOf(with_header(hostile));
}

TEST(MalformedRecording, MissingFileIsAnError) {
  Result<Recording> r = ReadRecording(TempPath("does-not-exist.sdrec"));
  ASSERT_FALSE(r.ok());
  EXPECT_TRUE(Contains(r.error().message, "does-not-exist.sdrec: cannot open"));
}

TEST(RecordingJsonLines, OneObjectPerRecord) {
  Result<Recording> r = ParseRecording(SmallRecording(), "small.sdrec");
  ASSERT_TRUE(r.ok());
  std::ostringstream out;
  WriteJsonLines(*r, out);
  std::istringstream lines(out.str());
  std::vector<std::string> all;
  for (std::string line; std::getline(lines, line);) all.push_back(line);
  ASSERT_EQ(all.size(), 1 + 2 + 5 + 1u);
  EXPECT_TRUE(Contains(all[0], R"("record":"header")"));
  EXPECT_TRUE(Contains(all[1], R"("record":"body")"));
  EXPECT_TRUE(Contains(all[3], R"("record":"segment")"));
  EXPECT_TRUE(Contains(all[7], R"("record":"collision")"));
  EXPECT_TRUE(Contains(all[7], R"("impulse":2.0)")) << all[7];
  EXPECT_TRUE(Contains(all[8], R"({"end_time":2.5,"record":"end"})")) << all[8];
}

}  // namespace
}  // namespace sparsedyn
