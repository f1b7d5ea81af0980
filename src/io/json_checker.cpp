// SPDX-License-Identifier: MIT
#include "io/json_checker.hpp"

#include <cmath>

namespace sparsedyn::json_input {

std::string Key(const std::string& path, const std::string& key) {
  return path.empty() ? key : path + "." + key;
}

std::string Index(const std::string& path, std::size_t index) {
  return path + "[" + std::to_string(index) + "]";
}

std::string Describe(const json& value) {
  if (value.is_string()) {
    std::string s = value.get<std::string>();
    if (s.size() > 40) s = s.substr(0, 40) + "...";
    return "string " + json(s).dump();
  }
  if (value.is_number()) return "number " + value.dump();
  if (value.is_boolean()) return value.get<bool>() ? "true" : "false";
  return value.type_name();
}

std::string FormatNumber(double value) { return json(value).dump(); }

void Checker::Fail(const std::string& path, const std::string& what) {
  if (errors_.size() >= kMaxErrors) {
    ++dropped_;
    return;
  }
  const std::string prefix = name_.empty() ? std::string() : name_ + ": ";
  errors_.push_back(prefix + (path.empty() ? "(top level)" : path) + ": " + what);
}

Error Checker::ToError() const {
  std::string message;
  for (const std::string& e : errors_) message += (message.empty() ? "" : "\n") + e;
  if (dropped_ > 0) message += "\n... and " + std::to_string(dropped_) + " more";
  return Error{message};
}

bool Checker::Object(const json& value, const std::string& path,
                     std::initializer_list<const char*> allowed) {
  if (!value.is_object()) {
    Fail(path, "must be an object, got " + Describe(value));
    return false;
  }
  for (const auto& [key, unused] : value.items()) {
    bool known = false;
    for (const char* k : allowed) known = known || key == k;
    if (known) continue;
    std::string list;
    for (const char* k : allowed) list += std::string(list.empty() ? "" : ", ") + k;
    Fail(Key(path, key), "unknown key (allowed here: " + list + ")");
  }
  return true;
}

std::optional<double> Checker::Number(const json& value, const std::string& path) {
  if (!value.is_number()) {
    Fail(path, "must be a number, got " + Describe(value));
    return std::nullopt;
  }
  const double v = value.get<double>();
  if (!std::isfinite(v)) {
    Fail(path, "must be finite, got " + value.dump());
    return std::nullopt;
  }
  return v;
}

std::optional<double> Checker::NumberIn(const json& value, const std::string& path, double lo,
                                        double hi, bool lo_open) {
  const std::optional<double> v = Number(value, path);
  if (!v) return v;
  if (*v < lo || *v > hi || (lo_open && *v == lo)) {
    // Appended piece by piece: `"(" + std::string` trips GCC 12's false -Wrestrict at -O3.
    std::string range = lo_open ? "(" : "[";
    range += FormatNumber(lo);
    range += ", ";
    range += std::isinf(hi) ? std::string("inf)") : FormatNumber(hi) + "]";
    Fail(path, "must be in " + range + ", got " + FormatNumber(*v));
    return std::nullopt;
  }
  return v;
}

std::optional<std::uint64_t> Checker::Unsigned(const json& value, const std::string& path,
                                               std::uint64_t max) {
  if (!value.is_number_unsigned() || value.get<std::uint64_t>() > max) {
    Fail(path, "must be an integer in [0, " + std::to_string(max) + "], got " + Describe(value));
    return std::nullopt;
  }
  return value.get<std::uint64_t>();
}

std::optional<std::string> Checker::String(const json& value, const std::string& path) {
  if (!value.is_string()) {
    Fail(path, "must be a string, got " + Describe(value));
    return std::nullopt;
  }
  return value.get<std::string>();
}

std::optional<Vec3> Checker::Vector(const json& value, const std::string& path) {
  if (!value.is_array() || value.size() != 3) {
    Fail(path,
         "must be an array of 3 numbers, got " +
             (value.is_array() ? "an array of " + std::to_string(value.size()) : Describe(value)));
    return std::nullopt;
  }
  Vec3 v;
  bool ok = true;
  for (std::size_t k = 0; k < 3; ++k) {
    const std::optional<double> c = Number(value[k], Index(path, k));
    ok = ok && c.has_value();
    if (c) v[static_cast<int>(k)] = *c;
  }
  if (!ok) return std::nullopt;
  return v;
}

}  // namespace sparsedyn::json_input
