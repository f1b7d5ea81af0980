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

  /// Adds a body (InputError when refused) and returns its index, its row in the arrays.
  std::uint32_t AddBody(const BodyDef& def);
  /// Processes every event up to t with the GIL released (SimulationError on failure).
  void AdvanceTo(double t);

  /// The simulated time now, s.
  double Time();
  /// The number of bodies (rows of the arrays).
  std::size_t BodyCount();
  /// One field of every body at time t (default: now) as an (N, 3) or (N, 4) float64 array,
  /// evaluated from the paths in C++. t before now is an InputError.
  pybind11::array_t<double> States(StateField field, std::optional<double> t);
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

/// The numpy dtype of PyWorld::Collisions: time, a, b, wall, point[3], normal[3], impulse.
pybind11::dtype CollisionDtype();

}  // namespace sparsedyn::python
