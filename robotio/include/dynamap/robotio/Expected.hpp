// A small Expected-style result for operations that can fail for reasons outside the
// program (files, devices, user input): either a value or an Error with a message that
// names the file, the key and what was expected.
#pragma once

#include <cassert>
#include <string>
#include <utility>
#include <variant>

namespace dynamap::robotio {

struct Error {
  std::string message;  // Full sentence naming the file/field/device and what was expected.
};

template <typename T>
class [[nodiscard]] Expected {
 public:
  Expected(T value) : storage_(std::move(value)) {}          // NOLINT(google-explicit-constructor)
  Expected(Error error) : storage_(std::move(error)) {}      // NOLINT(google-explicit-constructor)

  [[nodiscard]] bool ok() const { return std::holds_alternative<T>(storage_); }
  explicit operator bool() const { return ok(); }

  [[nodiscard]] const T& value() const& {
    assert(ok());
    return std::get<T>(storage_);
  }
  [[nodiscard]] T& value() & {
    assert(ok());
    return std::get<T>(storage_);
  }
  [[nodiscard]] T&& value() && {
    assert(ok());
    return std::get<T>(std::move(storage_));
  }
  [[nodiscard]] const Error& error() const {
    assert(!ok());
    return std::get<Error>(storage_);
  }
  const T* operator->() const { return &value(); }
  T* operator->() { return &value(); }
  const T& operator*() const& { return value(); }
  T& operator*() & { return value(); }

 private:
  std::variant<T, Error> storage_;
};

// For operations that return nothing on success.
struct Ok {};
using Status = Expected<Ok>;

}  // namespace dynamap::robotio
