// SPDX-License-Identifier: MIT
// Parser of the binary recording format (.sdrec, docs/recording-format.md, version 1).
// It turns the record stream into per-body segment tables (body-major, sorted by time) so that
// playback looks a body's current segment up without touching the other records.

export const kMagic = [0x53, 0x44, 0x52, 0x45, 0x43, 0x0d, 0x0a, 0x1a]; // "SDREC\r\n\x1a"
export const kVersion = 1;
export const kTagSegment = 1;
export const kTagCollision = 2;
export const kTagEnd = 3;
export const kSegmentHasAcceleration = 1;
export const kSegmentHasRotation = 2;
export const kCollisionWithWall = 1;

const kBodyRecordBytes = 24;
// A collision record after its tag and flags: a, b (u32), time, point, normal, impulse (f64).
const kCollisionBytes = 4 + 4 + 8 + 24 + 24 + 8;

/** Error thrown for a file that is not a readable recording; `message` says why. */
export class RecordingError extends Error {}

// Reads little-endian fields from a DataView with a moving offset and reports running off the
// end as a truncation (the caller decides whether that is fatal).
class Reader {
  constructor(view) {
    this.view = view;
    this.at = 0;
  }
  remaining() {
    return this.view.byteLength - this.at;
  }
  need(bytes, what) {
    if (this.remaining() < bytes) throw new Truncated(what, this.at);
  }
  u8() {
    const v = this.view.getUint8(this.at);
    this.at += 1;
    return v;
  }
  u32() {
    const v = this.view.getUint32(this.at, true);
    this.at += 4;
    return v;
  }
  f64() {
    const v = this.view.getFloat64(this.at, true);
    this.at += 8;
    return v;
  }
}

class Truncated extends Error {
  constructor(what, offset) {
    super(`truncated ${what} at byte ${offset}`);
  }
}

function ReadHeader(reader) {
  reader.need(16, 'header');
  for (let i = 0; i < kMagic.length; ++i) {
    if (reader.u8() !== kMagic[i]) {
      throw new RecordingError('not a sparsedyn recording (bad magic bytes)');
    }
  }
  const version = reader.u32();
  if (version !== kVersion) {
    throw new RecordingError(
        `recording version ${version} is not supported (this viewer reads version ${kVersion})`);
  }
  const header_bytes = reader.u32();
  reader.need(header_bytes, 'header JSON');
  const bytes = new Uint8Array(reader.view.buffer, reader.view.byteOffset + reader.at,
                               header_bytes);
  reader.at += header_bytes;
  let header;
  try {
    header = JSON.parse(new TextDecoder().decode(bytes));
  } catch (e) {
    throw new RecordingError(`header JSON does not parse: ${e.message}`);
  }
  CheckHeader(header);
  return header;
}

function CheckHeader(header) {
  if (!Number.isInteger(header.bodies) || header.bodies < 0) {
    throw new RecordingError('header.bodies must be a non-negative integer');
  }
  if (!Array.isArray(header.shapes) || header.shapes.length === 0) {
    throw new RecordingError('header.shapes must be a non-empty array');
  }
  header.shapes.forEach((shape, i) => {
    if (shape.type === 'sphere') {
      if (!(shape.radius > 0)) throw new RecordingError(`header.shapes[${i}].radius must be > 0`);
    } else if (shape.type === 'polyhedron') {
      if (!Array.isArray(shape.vertices) || !Array.isArray(shape.faces)) {
        throw new RecordingError(`header.shapes[${i}] needs vertices and faces`);
      }
    } else {
      throw new RecordingError(`header.shapes[${i}].type '${shape.type}' is unknown`);
    }
  });
  header.container ??= {kind: 'open'};
  header.gravity ??= [0, 0, 0];
  header.start_time ??= 0;
}

/** RecordedBody flags (docs/recording-format.md): a static body, a god object. */
export const kBodyStatic = 1;
export const kBodyGod = 2;

function ReadBodies(reader, header) {
  const n = header.bodies;
  reader.need(n * kBodyRecordBytes, 'body records');
  const shape = new Uint32Array(n);
  const mass = new Float64Array(n);
  const bounding_radius = new Float64Array(n);
  const flags = new Uint32Array(n);
  for (let i = 0; i < n; ++i) {
    shape[i] = reader.u32();
    flags[i] = reader.u32(); // kBodyStatic, kBodyGod
    mass[i] = reader.f64();
    bounding_radius[i] = reader.f64();
    if (shape[i] >= header.shapes.length) {
      throw new RecordingError(`body ${i}: shape index ${shape[i]} is out of range`);
    }
  }
  return {shape, mass, bounding_radius, flags};
}

// One record's fixed size after its tag and flags, given the flags (format table).
function SegmentBytes(flags) {
  let bytes = 4 + 8 + 48;
  if (flags & kSegmentHasAcceleration) bytes += 24;
  if (flags & kSegmentHasRotation) bytes += 56;
  return bytes;
}

// First pass: validates the record stream, counts segments per body and collisions, and finds
// the end record. Returns where the stream stops being readable.
function ScanRecords(reader, n) {
  const per_body = new Uint32Array(n);
  let collisions = 0;
  let end_time = null;
  let truncated = null;
  let last_time = -Infinity;
  let complete = reader.at; // end of the last complete record
  try {
    while (reader.remaining() > 0) {
      complete = reader.at;
      const at = reader.at;
      const tag = reader.u8();
      if (tag === kTagEnd) {
        reader.need(8, 'end record');
        end_time = reader.f64();
        complete = reader.at;
        break;
      }
      reader.need(1, 'record');
      const flags = reader.u8();
      if (tag === kTagSegment) {
        reader.need(SegmentBytes(flags), 'segment record');
        const body = reader.u32();
        const t0 = reader.f64();
        if (body >= n) throw new RecordingError(`segment at byte ${at}: body ${body} >= ${n}`);
        if (t0 < last_time) throw new RecordingError(`segment at byte ${at}: time goes back`);
        last_time = t0;
        per_body[body]++;
        reader.at += SegmentBytes(flags) - 12;
      } else if (tag === kTagCollision) {
        reader.need(kCollisionBytes, 'collision record');
        reader.at += kCollisionBytes;
        collisions++;
      } else {
        throw new RecordingError(`unknown record tag ${tag} at byte ${at}`);
      }
      complete = reader.at;
    }
  } catch (e) {
    if (!(e instanceof Truncated)) throw e;
    truncated = e.message;
  }
  if (end_time === null && truncated === null) truncated = 'no end record';
  return {per_body, collisions, end_time, truncated, stop: complete};
}

function AllocateSegments(per_body, total) {
  const n = per_body.length;
  const start = new Uint32Array(n + 1);
  for (let i = 0; i < n; ++i) start[i + 1] = start[i] + per_body[i];
  return {
    start,                                 // body i's segments are start[i] .. start[i+1]-1
    t0: new Float64Array(total),
    position: new Float64Array(3 * total),
    velocity: new Float64Array(3 * total),
    acceleration: new Float64Array(3 * total),
    orientation: new Float64Array(4 * total), // w, x, y, z
    angular_velocity: new Float64Array(3 * total),
  };
}

function ReadVec(reader, out, index, count) {
  for (let k = 0; k < count; ++k) out[count * index + k] = reader.f64();
}

// Second pass: fills the body-major tables; a body's segments arrive in time order already.
function FillRecords(reader, stop, segments, collisions) {
  const fill = Uint32Array.from(segments.start.subarray(0, segments.start.length - 1));
  let c = 0;
  while (reader.at < stop) {
    const tag = reader.u8();
    if (tag === kTagEnd) break;
    const flags = reader.u8();
    if (tag === kTagSegment) {
      const body = reader.u32();
      const s = fill[body]++;
      segments.t0[s] = reader.f64();
      ReadVec(reader, segments.position, s, 3);
      ReadVec(reader, segments.velocity, s, 3);
      if (flags & kSegmentHasAcceleration) ReadVec(reader, segments.acceleration, s, 3);
      if (flags & kSegmentHasRotation) {
        ReadVec(reader, segments.orientation, s, 4);
        ReadVec(reader, segments.angular_velocity, s, 3);
      } else {
        segments.orientation[4 * s] = 1;
      }
    } else {
      collisions.wall[c] = flags & kCollisionWithWall;
      collisions.a[c] = reader.u32();
      collisions.b[c] = reader.u32();
      collisions.time[c] = reader.f64();
      ReadVec(reader, collisions.point, c, 3);
      ReadVec(reader, collisions.normal, c, 3);
      collisions.impulse[c] = reader.f64();
      c++;
    }
  }
}

/**
 * Parses a recording from an ArrayBuffer (or a typed array view of one).
 * Returns {header, bodies: {count, shape, mass, bounding_radius, flags}, segments, collisions,
 * start_time, end_time, truncated}; `truncated` is null for a complete file, else a message
 * (the tables then hold what was readable). Throws RecordingError for a file that is not a
 * readable recording.
 */
export function ParseRecording(buffer) {
  const bytes = ArrayBuffer.isView(buffer) ? buffer : new Uint8Array(buffer);
  const view = new DataView(bytes.buffer, bytes.byteOffset, bytes.byteLength);
  const reader = new Reader(view);
  let header;
  let bodies;
  try {
    header = ReadHeader(reader);
    bodies = ReadBodies(reader, header);
  } catch (e) {
    if (e instanceof Truncated) throw new RecordingError(`not a complete recording: ${e.message}`);
    throw e;
  }
  const records_at = reader.at;
  const scan = ScanRecords(reader, header.bodies);
  for (let i = 0; i < header.bodies; ++i) {
    if (scan.per_body[i] === 0) throw new RecordingError(`body ${i} has no segment`);
  }
  const total = scan.per_body.reduce((a, b) => a + b, 0);
  const segments = AllocateSegments(scan.per_body, total);
  const m = scan.collisions;
  const collisions = {
    count: m, a: new Uint32Array(m), b: new Uint32Array(m), wall: new Uint8Array(m),
    time: new Float64Array(m), point: new Float64Array(3 * m), normal: new Float64Array(3 * m),
    impulse: new Float64Array(m),
  };
  reader.at = records_at;
  FillRecords(reader, scan.stop, segments, collisions);
  const last_time = total > 0 ? Math.max(...LastTimes(segments, collisions)) : header.start_time;
  return {
    header,
    bodies: {count: header.bodies, ...bodies},
    segments,
    collisions,
    start_time: header.start_time,
    end_time: scan.end_time ?? header.end_time ?? last_time,
    truncated: scan.truncated,
  };
}

function LastTimes(segments, collisions) {
  const times = [segments.t0.reduce((a, b) => Math.max(a, b), -Infinity)];
  if (collisions.count > 0) times.push(collisions.time[collisions.count - 1]);
  return times;
}
