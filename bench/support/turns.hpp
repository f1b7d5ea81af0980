// SPDX-License-Identifier: MIT
// Taking turns with another benchmark process on the same core (scripts/bench-ab.sh): two
// builds time their stretches in alternating slices of a fraction of a second, so that the
// machine's swings, which last seconds, fall on both alike. A token passed through two named
// pipes says whose turn it is.
#pragma once

#include <fcntl.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <optional>
#include <sstream>
#include <string>

namespace sparsedyn::bench {

class Turns {
 public:
  /// From SPARSEDYN_GAS_TURNS="IN,OUT,READY,COUNT": wait for the token on the pipe IN, pass it
  /// on through the pipe OUT, create the file READY once set up, time COUNT slices. Unset: no
  /// turns (one slice). Set but malformed or unusable: an error naming what is wrong.
  static std::optional<Turns> FromEnvironment(std::string& error) {
    const char* text = std::getenv("SPARSEDYN_GAS_TURNS");
    if (text == nullptr) return Turns{};
    std::istringstream fields(text);
    std::string in, out, count;
    Turns turns;
    if (!std::getline(fields, in, ',') || !std::getline(fields, out, ',') ||
        !std::getline(fields, turns.ready_, ',') || !std::getline(fields, count) ||
        !fields.eof()) {
      error = std::string("SPARSEDYN_GAS_TURNS=") + text + ": expected IN,OUT,READY,COUNT";
      return std::nullopt;
    }
    char* end = nullptr;
    const long slices = std::strtol(count.c_str(), &end, 10);
    if (end == count.c_str() || *end != '\0' || slices < 1 || slices > 100000) {
      error = "SPARSEDYN_GAS_TURNS: COUNT must be 1 to 100000, not '" + count + "'";
      return std::nullopt;
    }
    turns.slices_ = static_cast<int>(slices);
    // Read and write ends opened together (O_RDWR): opening a pipe for one end only blocks
    // until the other process opens the other end.
    turns.in_ = open(in.c_str(), O_RDWR);
    turns.out_ = open(out.c_str(), O_RDWR);
    if (turns.in_ < 0 || turns.out_ < 0) {
      error = "SPARSEDYN_GAS_TURNS: cannot open the pipes " + in + " and " + out;
      return std::nullopt;
    }
    return turns;
  }

  Turns(const Turns&) = delete;
  Turns& operator=(const Turns&) = delete;
  Turns(Turns&& other) noexcept
      : in_(other.in_), out_(other.out_), slices_(other.slices_), ready_(other.ready_) {
    other.in_ = other.out_ = -1;
  }
  Turns& operator=(Turns&&) = delete;
  ~Turns() {
    if (in_ >= 0) close(in_);
    if (out_ >= 0) close(out_);
  }

  int Slices() const { return slices_; }

  /// Says that this process is set up and waits for its first turn.
  bool Ready() const {
    if (ready_.empty()) return true;
    std::FILE* file = std::fopen(ready_.c_str(), "w");
    return file != nullptr && std::fclose(file) == 0;
  }
  /// Blocks until it is this process's turn.
  bool Wait() const {
    char token = 0;
    return in_ < 0 || read(in_, &token, 1) == 1;
  }
  /// Hands the turn to the other process.
  bool Pass() const {
    const char token = 't';
    return out_ < 0 || write(out_, &token, 1) == 1;
  }

 private:
  Turns() = default;
  int in_ = -1;
  int out_ = -1;
  int slices_ = 1;
  std::string ready_;
};

}  // namespace sparsedyn::bench
