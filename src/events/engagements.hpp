// SPDX-License-Identifier: MIT
#pragma once

#include <algorithm>
#include <cstdint>
#include <unordered_map>
#include <vector>

#include "sparsedyn/narrow/closest_features.hpp"
#include "sparsedyn/types.hpp"

namespace sparsedyn {

/// The engaged pairs (§3.3): two elements whose bounding spheres overlap while their bodies may
/// not touch yet. A body may have several engagements at once; when it collides, all of them are
/// predicted again. Each engagement owns one slot in the engagement queue (its id).
class Engagements {
 public:
  struct Engagement {
    std::uint32_t a = kNoIndex;
    std::uint32_t b = kNoIndex;
    bool contact_next = false;   // the queued detail event is a contact (else a separation)
    bool checkpoint = false;     // ... or only resumes an unfinished contact prediction
    bool alive = false;
    bool has_features = false;   // `features` holds the pair's last closest features
    FeaturePair features;        // warm start of the next closest-feature query (coherence)
  };

  /// Engages a and b; returns the engagement id.
  std::uint32_t Add(std::uint32_t a, std::uint32_t b) {
    std::uint32_t id;
    if (!free_.empty()) {
      id = free_.back();
      free_.pop_back();
    } else {
      id = static_cast<std::uint32_t>(items_.size());
      items_.emplace_back();
    }
    items_[id] = Engagement{};
    items_[id].a = a;
    items_[id].b = b;
    items_[id].alive = true;
    by_body_[a].push_back(id);
    by_body_[b].push_back(id);
    ++active_;
    return id;
  }

  void Remove(std::uint32_t id) {
    Engagement& e = items_[id];
    Unlink(e.a, id);
    Unlink(e.b, id);
    e.alive = false;
    free_.push_back(id);
    --active_;
  }

  bool Engaged(std::uint32_t a, std::uint32_t b) const {
    const auto it = by_body_.find(a);
    if (it == by_body_.end()) return false;
    return std::any_of(it->second.begin(), it->second.end(), [&](std::uint32_t id) {
      return items_[id].a == b || items_[id].b == b;
    });
  }

  bool HasAny(std::uint32_t body) const { return by_body_.count(body) != 0; }

  /// The ids of body's engagements (a copy: handlers may end engagements while iterating).
  std::vector<std::uint32_t> Of(std::uint32_t body) const {
    const auto it = by_body_.find(body);
    return it == by_body_.end() ? std::vector<std::uint32_t>{} : it->second;
  }

  Engagement& operator[](std::uint32_t id) { return items_[id]; }
  const Engagement& operator[](std::uint32_t id) const { return items_[id]; }
  std::size_t Active() const { return active_; }
  /// Ends every engagement.
  void Clear() { *this = Engagements{}; }

  /// The bodies were renumbered (World's memory order): body b is now new_of_old[b]; a
  /// partner named beyond new_of_old (a static body's key) keeps its name. The engagement ids,
  /// and so the engagement queue, stay as they are.
  void Renumber(const std::vector<std::uint32_t>& new_of_old) {
    const auto renamed = [&](std::uint32_t body) {
      return body < new_of_old.size() ? new_of_old[body] : body;
    };
    std::unordered_map<std::uint32_t, std::vector<std::uint32_t>> by_body;
    by_body.reserve(by_body_.size());
    for (auto& [body, ids] : by_body_) by_body.emplace(renamed(body), std::move(ids));
    by_body_.swap(by_body);
    for (Engagement& e : items_) {
      if (!e.alive) continue;
      e.a = renamed(e.a);
      e.b = renamed(e.b);
    }
  }

 private:
  void Unlink(std::uint32_t body, std::uint32_t id) {
    auto it = by_body_.find(body);
    if (it == by_body_.end()) return;
    std::erase(it->second, id);
    if (it->second.empty()) by_body_.erase(it);
  }

  std::vector<Engagement> items_;
  std::vector<std::uint32_t> free_;
  std::unordered_map<std::uint32_t, std::vector<std::uint32_t>> by_body_;
  std::size_t active_ = 0;
};

}  // namespace sparsedyn
