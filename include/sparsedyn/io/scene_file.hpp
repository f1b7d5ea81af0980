// SPDX-License-Identifier: MIT
#pragma once

#include <Eigen/Geometry>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "sparsedyn/geometry/convex_polyhedron.hpp"
#include "sparsedyn/result.hpp"
#include "sparsedyn/types.hpp"
#include "sparsedyn/world.hpp"

namespace sparsedyn {

/// A shape of a scene: a sphere or a convex polyhedron, built from the spec the scene gives
/// (docs/scene-format.md "Shapes"). Immutable once built; bodies refer to it by index.
struct SceneShape {
  /// A sphere or a convex polyhedron.
  enum class Kind { kSphere, kPolyhedron };
  /// Which of the two.
  Kind kind = Kind::kSphere;
  /// Sphere radius, m; for a polyhedron its bounding radius about the centroid.
  double radius = 0.0;
  /// The polyhedron in its body frame with the centroid at the origin (null for a sphere).
  std::shared_ptr<const ConvexPolyhedron> polyhedron;
  /// The shape's spec as compact JSON, exactly what FormatScene writes back, e.g.
  /// {"sphere":{"radius":0.5}} or {"generator":"random_convex","faces":60,"seed":3}. Also the
  /// key that makes bodies with equal specs share one shape.
  std::string spec;

  /// Volume, m^3 (for density -> mass).
  double Volume() const;
};

/// A body of a scene: everything docs/scene-format.md lets a body say, resolved (defaults
/// applied, density turned into mass). Spheres ignore orientation, angular velocity and
/// friction (they are frictionless); polyhedra use them all.
struct SceneBody {
  std::uint32_t shape = 0;       ///< index into SceneDescription::shapes
  Vec3 position = Vec3::Zero();  ///< centre of mass in the world frame, m
  Eigen::Quaterniond orientation = Eigen::Quaterniond::Identity();  ///< body to world, unit
  Vec3 velocity = Vec3::Zero();                                     ///< m/s
  Vec3 angular_velocity = Vec3::Zero();                             ///< rad/s, world frame
  Vec3 thrust = Vec3::Zero();  ///< own acceleration added to gravity, m/s^2
  /// Later changes of `thrust` (s, m/s^2), times strictly increasing and not before the
  /// scene's start time (WorldSettings::start_time): BodyDef::thrust_schedule.
  std::vector<ThrustChange> thrust_schedule;
  double mass = 1.0;              ///< kg (from "mass", or "density" x volume)
  std::optional<double> density;  ///< kg/m^3 when the file gave a density
  double restitution = 1.0;       ///< in [0, 1]
  double friction = 0.0;          ///< Coulomb coefficient >= 0 (polyhedra)
  bool is_static = false;         ///< "static": fixed in place, infinite mass (BodyDef)
  /// "god": {"max_acceleration": A, "track": [{"time": t, "position": [x, y, z],
  /// "velocity": [x, y, z] (optional)}, ...]}: a god object (BodyDef::god).
  std::optional<GodDef> god;
  /// "drag": {"linear": c1, "quadratic": c2}, the body's own (BodyDef::drag); unset: the
  /// scene's top-level "drag" (WorldSettings::drag) applies.
  std::optional<Drag> drag;
};

/// A scene as a file describes it: the World's settings, shapes, bodies and how long to run.
struct SceneDescription {
  std::string name;               ///< reported by `sparsedyn run` as "preset"
  std::uint64_t seed = 1;         ///< default seed of random generators; reported
  std::optional<double> packing;  ///< informational packing fraction, reported as "density"
  /// Simulated seconds `sparsedyn run` advances by default, from the start time: the run ends
  /// at EndTime().
  double duration = 10.0;
  /// The World's settings (container, gravity, broad phase, tolerances, start time).
  WorldSettings settings;
  /// The distinct shapes; bodies refer to them by index.
  std::vector<SceneShape> shapes;
  /// Every body, in the order BuildWorld adds them.
  std::vector<SceneBody> bodies;

  /// Adds `shape` unless one with the same spec is there; returns its index.
  std::uint32_t AddShape(SceneShape shape);
  /// The number of bodies whose shape is a polyhedron.
  std::size_t PolyhedralBodyCount() const;
  /// When `sparsedyn run` stops by default: settings.start_time + duration, s.
  double EndTime() const { return settings.start_time + duration; }
};

/// A sphere shape of radius `radius` with its spec.
SceneShape SphereShape(double radius);

/// Builds a shape from its JSON spec (docs/scene-format.md "Shapes"); mesh paths are relative
/// to `base_dir`, and `default_seed` seeds random generators that give no seed of their own.
/// Errors name `json_path` (e.g. "bodies[3].shape") and what is wrong.
Result<SceneShape> ParseShapeSpec(std::string_view spec_json, const std::filesystem::path& base_dir,
                                  std::uint64_t default_seed = 1,
                                  std::string_view json_path = "shape");

/// Parses scene JSON strictly: unknown keys, wrong types and out-of-range values are errors.
/// The Error lists every problem found (one per line, at most 20), each as
/// "<name>: <json path>: <what>", e.g. "s.json: bodies[3].velocity[1]: must be a number, got
/// string". Mesh files are read relative to `base_dir`.
Result<SceneDescription> ParseScene(std::string_view json_text, std::string_view name,
                                    const std::filesystem::path& base_dir);

/// Reads and parses a scene file (mesh paths relative to the file's folder).
Result<SceneDescription> ReadScene(const std::filesystem::path& path);

/// The scene as JSON text that ParseScene reads back to the same description: every body
/// listed with every field, doubles written so that they read back bit for bit.
std::string FormatScene(const SceneDescription& scene);

/// Rewrites the relative mesh paths of `scene`'s shapes, read relative to `from_dir` (the folder
/// of the file the scene came from), so that they name the same files relative to `to_dir` (the
/// folder a scene file is written to): a scene written elsewhere still finds its meshes. Absolute
/// paths, and every path when the two folders are the same, are kept as they are.
void RebaseMeshPaths(SceneDescription& scene, const std::filesystem::path& from_dir,
                     const std::filesystem::path& to_dir);

/// Writes FormatScene(scene) to `path`.
Status WriteScene(const SceneDescription& scene, const std::filesystem::path& path);

/// The BodyDef of body `index` of the scene (its shape's radius and polyhedron, shared between
/// the bodies of one shape): what BuildWorld adds, and what other simulators of a scene take.
BodyDef SceneBodyDef(const SceneDescription& scene, std::size_t index);

/// The scene of `world` at its clock, to run on from there (`sparsedyn run
/// --write-final-scene`): `scene` is what the World was built from and `ids[i]` the handle of
/// scene.bodies[i] (after BuildWorld, world.IdOf(i)). Every body still in the World, in the
/// scene's order (removed ones left out), with its state at world.Time() (position, wrapped
/// into a periodic box; orientation; velocity; angular velocity), its shape (the same spec),
/// mass or density, restitution and friction, its thrust then and the changes of its
/// thrust_schedule still to come (time > world.Time()); the settings kept, with start_time =
/// world.Time(), and the same duration. Valid after AdvanceTo succeeded (events at the clock
/// all processed). The thrusts come from `scene`: SetThrust calls are not known here, and
/// bodies added after the build are not in `scene`.
SceneDescription FinalScene(const SceneDescription& scene, const World& world,
                            const std::vector<BodyId>& ids);

/// A World holding the scene's bodies, added in order. Nothing is returned half-built: an Error
/// names the body ("bodies[12]: ...") when the World refuses it (overlap, outside the
/// container, a static body in a periodic box...).
Result<World> BuildWorld(const SceneDescription& scene);

}  // namespace sparsedyn
