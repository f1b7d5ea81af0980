// SPDX-License-Identifier: MIT
// The World as the Python package holds it: the World itself, what its summary needs beyond it
// (RunContext), and the collisions reported since the last collisions() call.
#pragma once

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include "errors.hpp"
#include "sparsedyn/io/run_summary.hpp"
#include "sparsedyn/world.hpp"

namespace sparsedyn::python {

/// A body's state that PyWorld::States evaluates for every body at once.
enum class StateField { kPosition, kVelocity, kOrientation, kAngularVelocity };

/// A World with its run's context. Every method that touches the World takes the mutex with the
/// GIL released, so another Python thread may call it while advance_to runs (it then waits).
class PyWorld {
 public:
  /// Takes `world`; `preset`, `density` and `seed` are what stats() reports about its origin.
  PyWorld(World world, std::string preset, double density, std::uint64_t seed);

  /// Adds a body (InputError when refused) and returns its handle; its index is its row in the
  /// arrays.
  BodyId AddBody(const BodyDef& def);
  /// Runs the change `f(world)` (returning a Status) under the mutex with the GIL released;
  /// InputError with the library's message when the World refuses it (and nothing changed).
  template <typename F>
  void Change(F&& f) {
    Status status;
    {
      pybind11::gil_scoped_release release;
      std::lock_guard<std::mutex> lock(mutex_);
      status = f(world_);
    }
    if (!status) throw InputError(status.error().message);
  }
  /// Processes every event up to t with the GIL released (SimulationError on failure).
  void AdvanceTo(double t);

  /// The simulated time now, s.
  double Time();
  /// The number of bodies the World holds.
  std::size_t BodyCount();
  /// One field of every slot at time t (default: now) as an (S, 3) or (S, 4) float64 array,
  /// S = SlotCount(), evaluated from the paths in C++: row k is the body in slot k (its
  /// BodyId::index), a row of NaN for an empty slot (a removed body's, not taken again). t
  /// before now is an InputError.
  pybind11::array_t<double> States(StateField field, std::optional<double> t);
  /// The state of `id` at time t (default: now); InputError for a handle the World does not
  /// hold or a t before now.
  BodyState StateOf(BodyId id, std::optional<double> t);
  /// The summary of `sparsedyn run --json` (RunSummaryJson) as JSON text.
  std::string SummaryJson();
  /// The collisions since the last call, as a numpy structured array; the buffer is emptied.
  pybind11::array Collisions();

  /// Runs `f(world)` under the mutex with the GIL released and returns its result.
  template <typename F>
  auto With(F&& f) {
    pybind11::gil_scoped_release release;
    std::lock_guard<std::mutex> lock(mutex_);
    return f(static_cast<const World&>(world_));
  }

 private:
  void CaptureInitialState();

  std::mutex mutex_;
  World world_;
  RunContext context_;
  bool started_ = false;  // the first AdvanceTo has fixed the initial energy and momentum
  std::vector<CollisionEvent> collisions_;
};

/// The message of a query `call` about a handle the World does not hold, in the words of the
/// library's own refusals (src/world/changes.cpp).
std::string NotInTheWorld(const char* call, BodyId id);

/// The numpy dtype of PyWorld::Collisions: time, a, b, wall, point[3], normal[3], impulse.
pybind11::dtype CollisionDtype();

}  // namespace sparsedyn::python
