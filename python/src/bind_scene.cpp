// SPDX-License-Identifier: MIT
// Scenes (include/sparsedyn/io/scene_file.hpp) and the presets of scenes/ as the Python class
// Scene and the functions preset, load_scene and parse_scene.
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <optional>
#include <string>

#include "bindings.hpp"
#include "errors.hpp"
#include "py_world.hpp"
#include "scenes/presets.hpp"
#include "sparsedyn/io/run_summary.hpp"
#include "sparsedyn/io/scene_file.hpp"

namespace py = pybind11;

namespace sparsedyn::python {
namespace {

// A scene and the packing fraction its summary reports (a preset's own, else ReportedPacking).
struct PyScene {
  SceneDescription scene;
  double density = 0;
};

PyScene Preset(const std::string& name, std::optional<std::uint32_t> n,
               std::optional<double> density, std::optional<std::uint64_t> seed,
               std::optional<Broadphase> broadphase) {
  scenes::PresetRequest request;
  request.name = name;
  request.n = n;
  request.density = density;
  request.seed = seed;
  request.broadphase = broadphase;
  scenes::Preset preset = ValueOrRaise(scenes::MakePreset(request));
  return {std::move(preset.scene), preset.density};
}

PyScene Described(SceneDescription scene) {
  const double density = ReportedPacking(scene);
  return {std::move(scene), density};
}

std::unique_ptr<PyWorld> Build(const PyScene& s) {
  World world = ValueOrRaise(BuildWorld(s.scene));
  return std::make_unique<PyWorld>(std::move(world), s.scene.name, s.density, s.scene.seed);
}

}  // namespace

void BindScene(py::module_& m) {
  py::class_<PyScene>(m, "Scene",
                      "A scene (SceneDescription): settings, shapes, bodies and how long to run.")
      .def("build", &Build, "A new World holding the scene's bodies (InputError if refused).")
      .def_property_readonly("name", [](const PyScene& s) { return s.scene.name; })
      .def_property_readonly("seed", [](const PyScene& s) { return s.scene.seed; })
      .def_property_readonly(
          "duration", [](const PyScene& s) { return s.scene.duration; },
          "Simulated seconds `sparsedyn run` advances by default.")
      .def_property_readonly(
          "density", [](const PyScene& s) { return s.density; },
          "The packing fraction the summary reports.")
      .def_property_readonly("body_count", [](const PyScene& s) { return s.scene.bodies.size(); })
      .def_property_readonly("settings", [](const PyScene& s) { return s.scene.settings; })
      .def(
          "to_json", [](const PyScene& s) { return FormatScene(s.scene); },
          "The scene as scene-file JSON (docs/scene-format.md), every body listed.")
      .def(
          "write",
          [](const PyScene& s, const std::string& path) { Check(WriteScene(s.scene, path)); },
          py::arg("path"), "Writes to_json() to `path`.");

  m.def("preset", &Preset, py::arg("name") = "default", py::arg("n") = py::none(),
        py::arg("density") = py::none(), py::arg("seed") = py::none(),
        py::arg("broadphase") = py::none(),
        "A preset scene ('default', 'gas', 'thesis'), as `sparsedyn run --preset NAME --n N "
        "--density D --seed S` builds it; unset values take the preset's defaults.");
  m.def("preset_names", &scenes::PresetNames);
  m.def(
      "load_scene",
      [](const std::string& path) { return Described(ValueOrRaise(ReadScene(path))); },
      py::arg("path"), "Reads a scene file (docs/scene-format.md); mesh paths are relative to it.");
  m.def(
      "parse_scene",
      [](const std::string& text, const std::string& name, const std::string& base_dir) {
        return Described(ValueOrRaise(ParseScene(text, name, base_dir)));
      },
      py::arg("text"), py::arg("name") = "scene", py::arg("base_dir") = ".",
      "Parses scene JSON text; errors name `name` and the JSON path.");
}

}  // namespace sparsedyn::python
