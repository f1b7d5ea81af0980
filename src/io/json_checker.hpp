// SPDX-License-Identifier: MIT
#pragma once

// Strict reading of JSON input (scene files): every problem is collected with its JSON path,
// e.g. "bodies[3].velocity[1]: must be a number, got string", and nothing is guessed.

#include <initializer_list>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "sparsedyn/result.hpp"
#include "sparsedyn/types.hpp"

namespace sparsedyn::json_input {

using nlohmann::json;

/// "a.b", "a[3]" path composition; the root is "".
std::string Key(const std::string& path, const std::string& key);
std::string Index(const std::string& path, std::size_t index);

/// Collects errors with their JSON path; the first kMaxErrors are kept.
class Checker {
 public:
  static constexpr std::size_t kMaxErrors = 20;

  explicit Checker(std::string name) : name_(std::move(name)) {}

  void Fail(const std::string& path, const std::string& what);
  bool ok() const { return errors_.empty(); }
  /// Every failure so far, kept or dropped: a caller that compares counts must see each one.
  std::size_t ErrorCount() const { return errors_.size() + dropped_; }
  /// All errors, one per line: "<name>: <path>: <what>".
  Error ToError() const;

  /// Checks that `value` is an object whose keys are all in `allowed`; each unknown key is an
  /// error naming the keys that are allowed. False if `value` is not an object.
  bool Object(const json& value, const std::string& path,
              std::initializer_list<const char*> allowed);

  /// A finite number (integers are accepted).
  std::optional<double> Number(const json& value, const std::string& path);
  /// A number in [lo, hi] (or (lo, hi] when `lo_open`).
  std::optional<double> NumberIn(const json& value, const std::string& path, double lo, double hi,
                                 bool lo_open = false);
  /// A non-negative integer <= max.
  std::optional<std::uint64_t> Unsigned(const json& value, const std::string& path,
                                        std::uint64_t max);
  std::optional<std::string> String(const json& value, const std::string& path);
  /// An array of exactly 3 finite numbers.
  std::optional<Vec3> Vector(const json& value, const std::string& path);

 private:
  std::string name_;
  std::vector<std::string> errors_;
  std::size_t dropped_ = 0;
};

/// The type of `value` as an error message says it: "string \"abc\"", "array", "null"...
std::string Describe(const json& value);

/// A double as JSON writes it (shortest form that reads back to the same value).
std::string FormatNumber(double value);

}  // namespace sparsedyn::json_input
