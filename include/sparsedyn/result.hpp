// SPDX-License-Identifier: MIT
#pragma once

#include <string>
#include <utility>
#include <variant>

#include "sparsedyn/assert.hpp"

namespace sparsedyn {

/// What went wrong with user input: a sentence that names the body, file:line or JSON path and
/// the field, e.g. "body 3: radius must be > 0, got -1".
struct Error {
  /// The sentence, ready to print.
  std::string message;
};

/// The value of a fallible operation, or the Error that prevented it (becomes std::expected
/// with C++23). Bad user input is reported this way; it never throws.
template <typename T>
class [[nodiscard]] Result {
 public:
  /// A success holding `value`.
  Result(T value) : storage_(std::move(value)) {}          // NOLINT: implicit by design
  /// A failure holding `error`.
  Result(Error error) : storage_(std::move(error)) {}      // NOLINT: implicit by design

  /// Whether it holds a value.
  bool ok() const { return std::holds_alternative<T>(storage_); }
  /// ok().
  explicit operator bool() const { return ok(); }

  /// The value (asserts ok()).
  T& value() & {
    SPARSEDYN_ASSERT(ok(), "Result::value() on an error");
    return std::get<T>(storage_);
  }
  /// The value (asserts ok()).
  const T& value() const& {
    SPARSEDYN_ASSERT(ok(), "Result::value() on an error");
    return std::get<T>(storage_);
  }
  /// The value, moved out (asserts ok()).
  T&& value() && {
    SPARSEDYN_ASSERT(ok(), "Result::value() on an error");
    return std::get<T>(std::move(storage_));
  }
  /// value().
  T& operator*() & { return value(); }
  /// value().
  const T& operator*() const& { return value(); }
  /// value(), moved out.
  T&& operator*() && { return std::move(*this).value(); }
  /// A pointer to the value (asserts ok()).
  T* operator->() { return &value(); }
  /// A pointer to the value (asserts ok()).
  const T* operator->() const { return &value(); }

  /// The error (asserts !ok()).
  const Error& error() const {
    SPARSEDYN_ASSERT(!ok(), "Result::error() on a value");
    return std::get<Error>(storage_);
  }

 private:
  std::variant<T, Error> storage_;
};

/// Success or an Error, for operations with no value.
class [[nodiscard]] Status {
 public:
  Status() = default;
  /// A failure holding `error`.
  Status(Error error) : error_(std::move(error)), ok_(false) {}  // NOLINT: implicit by design
  /// Success.
  static Status Ok() { return {}; }

  /// Whether it is a success.
  bool ok() const { return ok_; }
  /// ok().
  explicit operator bool() const { return ok_; }
  /// The error (asserts !ok()).
  const Error& error() const {
    SPARSEDYN_ASSERT(!ok_, "Status::error() on success");
    return error_;
  }

 private:
  Error error_;
  bool ok_ = true;
};

}  // namespace sparsedyn
