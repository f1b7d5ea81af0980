// SPDX-License-Identifier: MIT
// Reads docs/recording-format.md version 1; every malformed file is an Error, never a crash.
#include <algorithm>
#include <cmath>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>

#include "io/recording_bytes.hpp"
#include "io/recording_json.hpp"
#include "sparsedyn/io/recording.hpp"

namespace sparsedyn {

using namespace recording;  // NOLINT(google-build-using-namespace): the format's constants

namespace {

// Printable form of the first bytes of a file that is not a recording, e.g. "PK\x03\x04".
std::string Escaped(std::string_view bytes) {
  std::string out;
  for (const char c : bytes) {
    const auto u = static_cast<unsigned char>(c);
    if (u >= 0x20 && u < 0x7f && c != '\\' && c != '"') {
      out.push_back(c);
    } else {
      static constexpr char kHex[] = "0123456789abcdef";
      out += "\\x";
      out.push_back(kHex[u >> 4]);
      out.push_back(kHex[u & 0xf]);
    }
  }
  return out;
}

// Walks the record stream after the header and the body records.
class StreamParser {
 public:
  StreamParser(ByteCursor& in, std::string_view name, Recording& out)
      : in_(in), name_(name), out_(out), has_segment_(out.bodies.size(), false) {}

  Status Parse() {
    for (;;) {
      const std::size_t at = in_.Offset();
      if (in_.Left() == 0) {
        return Fail(at, "truncated file: no end record after record " + std::to_string(index_) +
                            " (the run did not finish writing)");
      }
      const std::uint8_t tag = in_.U8();
      Status status;
      if (tag == kTagSegment) {
        status = ParseSegment(at);
      } else if (tag == kTagCollision) {
        status = ParseCollision(at);
      } else if (tag == kTagEnd) {
        return ParseEnd(at);
      } else {
        return Fail(at, "record " + std::to_string(index_) + ": unknown tag " +
                            std::to_string(tag) + " (1 segment, 2 collision, 3 end)");
      }
      if (!status) return status;
      ++index_;
    }
  }

 private:
  Status Fail(std::size_t at, const std::string& what) const {
    return Error{std::string(name_) + ": byte " + std::to_string(at) + ": " + what};
  }

  // Checks that the record that starts at `at` has its `size` bytes (tag included).
  Status Need(std::size_t at, std::size_t size, const char* kind) const {
    const std::size_t left = in_.Left() + (in_.Offset() - at);
    if (left >= size) return Status::Ok();
    return Fail(at, "truncated file: record " + std::to_string(index_) + " (" + kind + ") needs " +
                        std::to_string(size) + " bytes, " + std::to_string(left) + " left");
  }

  Status CheckTime(std::size_t at, double t) {
    if (!std::isfinite(t))
      return Fail(at, "record " + std::to_string(index_) + ": time is not finite");
    if (t < last_time_) {
      return Fail(at, "record " + std::to_string(index_) + ": time " + std::to_string(t) +
                          " is before the previous record's " + std::to_string(last_time_));
    }
    last_time_ = t;
    return Status::Ok();
  }

  Status CheckBody(std::size_t at, std::uint32_t body, const char* field) const {
    if (body >= out_.bodies.size()) {
      return Fail(at, "record " + std::to_string(index_) + ": " + field + " = " +
                          std::to_string(body) + " but there are " +
                          std::to_string(out_.bodies.size()) + " bodies");
    }
    return Status::Ok();
  }

  // The first segment of every body comes before any other record.
  Status CheckAllStarted(std::size_t at) const {
    if (bodies_started_ == out_.bodies.size()) return Status::Ok();
    std::size_t missing = 0;
    while (has_segment_[missing]) ++missing;
    return Fail(at, "record " + std::to_string(index_) + ": body " + std::to_string(missing) +
                        " has no first segment (those come before any other record)");
  }

  Status ParseSegment(std::size_t at) {
    if (Status s = Need(at, 2, "segment"); !s) return s;
    const std::uint8_t flags = in_.U8();
    if ((flags & ~(kSegmentHasAcceleration | kSegmentHasRotation)) != 0) {
      return Fail(at, "record " + std::to_string(index_) + ": unknown segment flags " +
                          std::to_string(flags));
    }
    RecordedSegment s;
    s.has_acceleration = (flags & kSegmentHasAcceleration) != 0;
    s.has_rotation = (flags & kSegmentHasRotation) != 0;
    const std::size_t size =
        kSegmentBaseBytes + (s.has_acceleration ? 24 : 0) + (s.has_rotation ? 56 : 0);
    if (Status st = Need(at, size, "segment"); !st) return st;
    s.body = in_.U32();
    s.t0 = in_.F64();
    s.position = in_.Vector();
    s.velocity = in_.Vector();
    if (s.has_acceleration) s.acceleration = in_.Vector();
    if (s.has_rotation) {
      const double w = in_.F64(), x = in_.F64(), y = in_.F64(), z = in_.F64();
      s.orientation = Eigen::Quaterniond(w, x, y, z);
      s.angular_velocity = in_.Vector();
    }
    if (Status st = CheckBody(at, s.body, "body"); !st) return st;
    if (!has_segment_[s.body]) {
      has_segment_[s.body] = true;
      ++bodies_started_;
    } else if (Status st = CheckAllStarted(at); !st) {
      return st;
    }
    if (Status st = CheckTime(at, s.t0); !st) return st;
    out_.records.emplace_back(s);
    return Status::Ok();
  }

  Status ParseCollision(std::size_t at) {
    if (Status s = Need(at, kCollisionBytes, "collision"); !s) return s;
    RecordedCollision c;
    const std::uint8_t flags = in_.U8();
    c.b_is_wall = (flags & kCollisionWithWall) != 0;
    c.a = in_.U32();
    c.b = in_.U32();
    c.time = in_.F64();
    c.point = in_.Vector();
    c.normal = in_.Vector();
    c.impulse = in_.F64();
    if ((flags & ~kCollisionWithWall) != 0) {
      return Fail(at, "record " + std::to_string(index_) + ": unknown collision flags " +
                          std::to_string(flags));
    }
    if (Status st = CheckBody(at, c.a, "a"); !st) return st;
    if (Status st = CheckAllStarted(at); !st) return st;
    if (c.b_is_wall && c.b > 5) {
      return Fail(at, "record " + std::to_string(index_) + ": wall index " + std::to_string(c.b) +
                          " is not in 0..5");
    }
    if (!c.b_is_wall) {
      if (Status st = CheckBody(at, c.b, "b"); !st) return st;
    }
    if (Status st = CheckTime(at, c.time); !st) return st;
    out_.records.emplace_back(c);
    return Status::Ok();
  }

  Status ParseEnd(std::size_t at) {
    if (Status s = Need(at, kEndBytes, "end"); !s) return s;
    out_.end_time = in_.F64();
    if (Status st = CheckTime(at, out_.end_time); !st) return st;
    if (Status st = CheckAllStarted(at); !st) return st;
    if (in_.Left() != 0) {
      return Fail(in_.Offset(), std::to_string(in_.Left()) + " bytes after the end record");
    }
    return Status::Ok();
  }

  ByteCursor& in_;
  std::string_view name_;
  Recording& out_;
  std::size_t index_ = 0;
  double last_time_ = -kInfinity;
  std::vector<bool> has_segment_;  // per body: its first segment has been read
  std::size_t bodies_started_ = 0;
};

// Magic, version and header JSON.
Result<RecordingHeader> ParseHeader(ByteCursor& in, std::string_view name) {
  const std::string file(name);
  const std::string_view magic = in.Take(std::min(in.Left(), kRecordingMagic.size()));
  if (magic != kRecordingMagic) {
    return Error{file + ": not a sparsedyn recording (bad magic: expected \"" +
                 Escaped(kRecordingMagic) + "\", found \"" + Escaped(magic) + "\")"};
  }
  if (in.Left() < 8)
    return Error{file + ": truncated file: the header ends at byte " +
                 std::to_string(in.Offset() + in.Left()) + " (need 16)"};
  const std::uint32_t version = in.U32();
  if (version != kRecordingVersion) {
    return Error{file + ": recording version " + std::to_string(version) +
                 " is not supported (this reader knows version " +
                 std::to_string(kRecordingVersion) + ")"};
  }
  const std::uint32_t header_bytes = in.U32();
  if (in.Left() < header_bytes) {
    return Error{file + ": truncated file: the header JSON needs " + std::to_string(header_bytes) +
                 " bytes from byte 16, " + std::to_string(in.Left()) + " left"};
  }
  const nlohmann::json json =
      nlohmann::json::parse(in.Take(header_bytes), nullptr, /*allow_exceptions=*/false);
  if (json.is_discarded())
    return Error{file + ": the header is not valid JSON (bytes 16.." +
                 std::to_string(16 + header_bytes) + ")"};
  return HeaderFromJson(json, name);
}

// The fixed-size body records.
Status ParseBodies(ByteCursor& in, std::string_view name, Recording& out) {
  const std::string file(name);
  const std::uint64_t count = out.header.bodies;
  if (count * kBodyRecordBytes > in.Left()) {
    return Error{file + ": truncated file: " + std::to_string(count) + " body records need " +
                 std::to_string(count * kBodyRecordBytes) + " bytes from byte " +
                 std::to_string(in.Offset()) + ", " + std::to_string(in.Left()) + " left"};
  }
  out.bodies.reserve(count);
  for (std::uint64_t i = 0; i < count; ++i) {
    const std::size_t at = in.Offset();
    RecordedBody body;
    body.shape = in.U32();
    body.flags = in.U32();
    body.mass = in.F64();
    body.bounding_radius = in.F64();
    if (body.shape >= out.header.shapes.size()) {
      return Error{file + ": byte " + std::to_string(at) + ": body " + std::to_string(i) +
                   " names shape " + std::to_string(body.shape) + " but the header has " +
                   std::to_string(out.header.shapes.size())};
    }
    out.bodies.push_back(body);
  }
  return Status::Ok();
}

}  // namespace

Result<Recording> ParseRecording(std::string_view bytes, std::string_view name) {
  ByteCursor in(bytes);
  Recording recording;
  Result<RecordingHeader> header = ParseHeader(in, name);
  if (!header) return header.error();
  recording.header = std::move(*header);
  if (Status s = ParseBodies(in, name, recording); !s) return s.error();
  if (Status s = StreamParser(in, name, recording).Parse(); !s) return s.error();
  return recording;
}

Result<Recording> ReadRecording(const std::filesystem::path& path) {
  std::ifstream file(path, std::ios::binary);
  if (!file) return Error{path.string() + ": cannot open"};
  std::ostringstream content;
  content << file.rdbuf();
  if (file.bad()) return Error{path.string() + ": read error"};
  return ParseRecording(content.str(), path.string());
}

}  // namespace sparsedyn
