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
  std::string message;
};

/// The value of a fallible operation, or the Error that prevented it (becomes std::expected
/// with C++23). Bad user input is reported this way; it never throws.
template <typename T>
class [[nodiscard]] Result {
 public:
  Result(T value) : storage_(std::move(value)) {}          // NOLINT: implicit by design
  Result(Error error) : storage_(std::move(error)) {}      // NOLINT: implicit by design

  bool ok() const { return std::holds_alternative<T>(storage_); }
  explicit operator bool() const { return ok(); }

  T& value() & {
    SPARSEDYN_ASSERT(ok(), "Result::value() on an error");
    return std::get<T>(storage_);
  }
  const T& value() const& {
    SPARSEDYN_ASSERT(ok(), "Result::value() on an error");
    return std::get<T>(storage_);
  }
  T&& value() && {
    SPARSEDYN_ASSERT(ok(), "Result::value() on an error");
    return std::get<T>(std::move(storage_));
  }
  T& operator*() & { return value(); }
  const T& operator*() const& { return value(); }
  T&& operator*() && { return std::move(*this).value(); }
  T* operator->() { return &value(); }
  const T* operator->() const { return &value(); }

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
  Status(Error error) : error_(std::move(error)), ok_(false) {}  // NOLINT: implicit by design
  static Status Ok() { return {}; }

  bool ok() const { return ok_; }
  explicit operator bool() const { return ok_; }
  const Error& error() const {
    SPARSEDYN_ASSERT(!ok_, "Status::error() on success");
    return error_;
  }

 private:
  Error error_;
  bool ok_ = true;
};

}  // namespace sparsedyn
