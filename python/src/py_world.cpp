// SPDX-License-Identifier: MIT
#include "py_world.hpp"

#include <algorithm>
#include <chrono>
#include <cstring>
#include <limits>

#include "errors.hpp"

namespace py = pybind11;

namespace sparsedyn::python {
namespace {

// One row of the collisions array; its layout matches CollisionDtype().
struct CollisionRow {
  double time;
  std::int64_t a;
  std::int64_t b;     // -1 for a wall collision
  std::int64_t wall;  // 0..5 = -x,+x,-y,+y,-z,+z, or -1
  double point[3];
  double normal[3];
  double impulse;
};

static_assert(sizeof(CollisionRow) == 88, "CollisionRow must match CollisionDtype()");

// The error of a state asked for at t before the World's clock `now`.
InputError BeforeNow(double t, double now) {
  return InputError("t = " + py::repr(py::float_(t)).cast<std::string>() +
                    " is before the World's time " + py::repr(py::float_(now)).cast<std::string>() +
                    ": states are known from the current time on");
}

}  // namespace

std::string NotInTheWorld(const char* call, BodyId id) {
  return std::string(call) + ": body " + std::to_string(id.index) + " (generation " +
         std::to_string(id.generation) + ") is not in the World (removed, or never added)";
}

py::dtype CollisionDtype() {
  py::list fields;
  auto add = [&](const char* name, const char* type) { fields.append(py::make_tuple(name, type)); };
  add("time", "<f8");
  add("a", "<i8");
  add("b", "<i8");
  add("wall", "<i8");
  fields.append(py::make_tuple("point", "<f8", py::make_tuple(3)));
  fields.append(py::make_tuple("normal", "<f8", py::make_tuple(3)));
  add("impulse", "<f8");
  return py::dtype::from_args(fields);
}

PyWorld::PyWorld(World world, std::string preset, double density, std::uint64_t seed)
    : world_(std::move(world)) {
  context_.preset = std::move(preset);
  context_.density = density;
  context_.seed = seed;
  world_.OnCollision([this](const CollisionEvent& e) { collisions_.push_back(e); });
}

void PyWorld::CaptureInitialState() {
  context_.kinetic_energy_initial = world_.KineticEnergy();
  context_.momentum_initial = world_.Momentum();
}

BodyId PyWorld::AddBody(const BodyDef& def) {
  Result<BodyId> id = [&] {
    py::gil_scoped_release release;
    std::lock_guard<std::mutex> lock(mutex_);
    return world_.AddBody(def);
  }();
  return ValueOrRaise(std::move(id));
}

void PyWorld::AdvanceTo(double t) {
  Status status;
  {
    py::gil_scoped_release release;
    std::lock_guard<std::mutex> lock(mutex_);
    if (!started_) CaptureInitialState();
    started_ = true;
    const auto start = std::chrono::steady_clock::now();
    status = world_.AdvanceTo(t);
    context_.wall_seconds +=
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  }
  Check<SimulationError>(status);
}

double PyWorld::Time() {
  return With([](const World& w) { return w.Time(); });
}

std::size_t PyWorld::BodyCount() {
  return With([](const World& w) { return w.BodyCount(); });
}

py::array_t<double> PyWorld::States(StateField field, std::optional<double> t) {
  const std::size_t columns = field == StateField::kOrientation ? 4 : 3;
  std::vector<double> values;
  double now = 0;
  const bool ok = With([&](const World& w) {
    now = w.Time();
    const double at = t.value_or(now);
    if (!(at >= now)) return false;
    // One row per slot: an empty slot's row is NaN, so that rows stay the bodies' indices.
    values.assign(w.SlotCount() * columns, std::numeric_limits<double>::quiet_NaN());
    for (std::uint32_t slot = 0; slot < w.SlotCount(); ++slot) {
      const BodyId id = w.IdOf(slot);
      if (!id.valid()) continue;
      const BodyState s = w.StateAt(id, at);
      double* row = values.data() + slot * columns;
      switch (field) {
        case StateField::kPosition:
          std::copy_n(s.position.data(), 3, row);
          break;
        case StateField::kVelocity:
          std::copy_n(s.velocity.data(), 3, row);
          break;
        case StateField::kAngularVelocity:
          std::copy_n(s.angular_velocity.data(), 3, row);
          break;
        case StateField::kOrientation:
          row[0] = s.orientation.w();
          row[1] = s.orientation.x();
          row[2] = s.orientation.y();
          row[3] = s.orientation.z();
          break;
      }
    }
    return true;
  });
  if (!ok) throw BeforeNow(*t, now);
  const auto rows = static_cast<py::ssize_t>(values.size() / columns);
  py::array_t<double> out(std::vector<py::ssize_t>{rows, static_cast<py::ssize_t>(columns)});
  std::copy(values.begin(), values.end(), out.mutable_data());
  return out;
}

BodyState PyWorld::StateOf(BodyId id, std::optional<double> t) {
  enum class Refused { kNone, kHandle, kTime };
  Refused refused = Refused::kNone;
  double now = 0;
  BodyState state;
  With([&](const World& w) {
    now = w.Time();
    if (!w.IsValid(id)) {
      refused = Refused::kHandle;
    } else if (!(t.value_or(now) >= now)) {
      refused = Refused::kTime;
    } else {
      state = w.StateAt(id, t.value_or(now));
    }
    return 0;
  });
  if (refused == Refused::kHandle) throw InputError(NotInTheWorld("state", id));
  if (refused == Refused::kTime) throw BeforeNow(*t, now);
  return state;
}

std::string PyWorld::SummaryJson() {
  py::gil_scoped_release release;
  std::lock_guard<std::mutex> lock(mutex_);
  // Before the first advance_to the initial values are those of now.
  if (!started_) CaptureInitialState();
  return RunSummaryJson(world_, context_);
}

py::array PyWorld::Collisions() {
  std::vector<CollisionEvent> taken;
  {
    py::gil_scoped_release release;
    std::lock_guard<std::mutex> lock(mutex_);
    taken.swap(collisions_);
  }
  py::array out(CollisionDtype(), std::vector<py::ssize_t>{static_cast<py::ssize_t>(taken.size())});
  auto* rows = static_cast<CollisionRow*>(out.mutable_data());
  for (std::size_t k = 0; k < taken.size(); ++k) {
    const CollisionEvent& e = taken[k];
    CollisionRow& r = rows[k];
    r.time = e.time;
    r.a = e.a.index;
    r.b = e.b.valid() ? static_cast<std::int64_t>(e.b.index) : -1;
    r.wall = e.wall;
    std::copy_n(e.point.data(), 3, r.point);
    std::copy_n(e.normal.data(), 3, r.normal);
    r.impulse = e.impulse;
  }
  return out;
}

}  // namespace sparsedyn::python
