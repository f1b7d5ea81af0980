// SPDX-License-Identifier: MIT
#pragma once

#include <cstdint>
#include <vector>

#include "sparsedyn/types.hpp"

namespace sparsedyn {

/// What holds a body at rest against a surface (docs/sparse-phase.md#coming-to-rest): walls
/// (bits, one per box wall) and at most one static body's face, whose unit normal points from
/// the static to the body.
struct Hold {
  std::uint8_t walls = 0;
  std::uint32_t on_static = kNoIndex;  // the static's index (StaticBodies), or none
  Vec3 normal = Vec3::Zero();          // the static face's normal when on_static is set
  std::int32_t face = -1;              // that face's index in the static's polyhedron
  bool Any() const { return walls != 0 || on_static != kNoIndex; }
};

/// Each body's acceleration during its current segment. Gravity alone is one vector shared by
/// every body (a gas on straight lines reads no per-body value) until some body has an
/// acceleration of its own (a thrust, a hold), when each body gets its own. Once a wall or a
/// static face holds a body, the free acceleration (gravity plus thrust) each body returns to
/// when released is kept beside it, with what holds it.
class Accelerations {
 public:
  explicit Accelerations(const Vec3& gravity) : uniform_(gravity) {}

  /// Body i's acceleration in its current segment.
  const Vec3& Of(std::uint32_t i) const { return own_ ? per_body_[i] : uniform_; }
  /// Whether every body has the shared acceleration (UniformValue()).
  bool Uniform() const { return !own_; }
  const Vec3& UniformValue() const { return uniform_; }
  /// Gravity plus body i's thrust: its acceleration unless a wall holds it.
  Vec3 Free(std::uint32_t i) const {
    if (!free_.empty()) return free_[i];
    return Of(i);
  }
  /// Bit w: wall w holds body i (0 before the first hold).
  std::uint8_t HeldBy(std::uint32_t i) const { return held_by_.empty() ? 0 : held_by_[i]; }
  /// The static face that holds body i, if any (its on_static is kNoIndex if none).
  Hold HoldOf(std::uint32_t i) const {
    Hold hold;
    hold.walls = HeldBy(i);
    if (!on_static_.empty() && on_static_[i].on_static != kNoIndex) {
      hold.on_static = on_static_[i].on_static;
      hold.normal = on_static_[i].normal;
      hold.face = on_static_[i].face;
    }
    return hold;
  }
  /// Whether a static's face holds body i.
  bool OnStatic(std::uint32_t i) const {
    return !on_static_.empty() && on_static_[i].on_static != kNoIndex;
  }
  bool Held(std::uint32_t i) const { return HoldOf(i).Any(); }
  /// Whether some body was ever held (each body then has its own acceleration).
  bool AnyHeld() const { return !held_by_.empty(); }

  /// A new body (index size()) with the free acceleration `a`.
  void Append(std::uint32_t index, const Vec3& a) {
    if (!own_ && a != uniform_) {
      own_ = true;  // the first body with an acceleration of its own
      per_body_.assign(index, uniform_);
    }
    if (own_) per_body_.push_back(a);
    if (!held_by_.empty()) {
      held_by_.push_back(0);
      free_.push_back(a);
    }
    if (!on_static_.empty()) on_static_.push_back(StaticHold{});
  }

  /// Body i held by `hold` (hold.Any() false: released): its acceleration is the free one
  /// with the components along the held walls' axes zeroed (the walls are axis-aligned: exact
  /// zeros, so the gap stays as it is) and, on a static face, its part along the face's normal
  /// removed. Returns that acceleration.
  Vec3 SetHeld(std::uint32_t i, const Hold& hold, std::size_t count) {
    if (held_by_.empty()) {
      // The first hold: every body gets its own acceleration, and its free one is kept.
      if (!own_) per_body_.assign(count, uniform_);
      own_ = true;
      free_ = per_body_;
      held_by_.assign(count, 0);
    }
    if (hold.on_static != kNoIndex && on_static_.empty()) on_static_.assign(count, StaticHold{});
    held_by_[i] = hold.walls;
    if (!on_static_.empty()) on_static_[i] = StaticHold{hold.normal, hold.on_static, hold.face};
    per_body_[i] = HeldAcceleration(free_[i], hold);
    return per_body_[i];
  }

  /// The acceleration `a` has under `hold`.
  static Vec3 HeldAcceleration(Vec3 a, const Hold& hold) {
    for (int w = 0; w < 6; ++w) {
      if ((hold.walls >> w & 1u) != 0) a[w / 2] = 0.0;
    }
    if (hold.on_static != kNoIndex) a -= hold.normal.dot(a) * hold.normal;
    return a;
  }

  /// Body i's free acceleration from now on is `a` (a new thrust): any wall's hold ends.
  void SetFree(std::uint32_t i, const Vec3& a, std::size_t count) {
    if (!own_) {
      if (a == uniform_) return;
      own_ = true;
      per_body_.assign(count, uniform_);
    }
    per_body_[i] = a;
    if (!held_by_.empty()) {
      free_[i] = a;
      held_by_[i] = 0;
    }
    if (!on_static_.empty()) on_static_[i] = StaticHold{};
  }

  /// The bodies were renumbered: new body e is old body old_of_new[e].
  template <typename PermuteFn>
  void Permute(PermuteFn&& permute) {
    if (own_) permute(per_body_);
    if (!held_by_.empty()) {
      permute(held_by_);
      permute(free_);
    }
    if (!on_static_.empty()) permute(on_static_);
  }

  std::size_t MemoryBytes() const {
    return per_body_.capacity() * sizeof(Vec3) + held_by_.capacity() +
           free_.capacity() * sizeof(Vec3) + on_static_.capacity() * sizeof(StaticHold);
  }

 private:
  Vec3 uniform_;
  bool own_ = false;
  std::vector<Vec3> per_body_;      // once own_
  std::vector<std::uint8_t> held_by_;  // once some wall held a body
  std::vector<Vec3> free_;          // likewise
  struct StaticHold {
    Vec3 normal = Vec3::Zero();
    std::uint32_t on_static = kNoIndex;
    std::int32_t face = -1;
  };
  std::vector<StaticHold> on_static_;  // once some static face held a body
};

}  // namespace sparsedyn
