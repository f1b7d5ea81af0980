// SPDX-License-Identifier: MIT
// The parts of the module `sparsedyn._sparsedyn`, one function per part (module.cpp calls them).
#pragma once

#include <pybind11/pybind11.h>

namespace sparsedyn::python {

void BindErrors(pybind11::module_& m);    // errors.cpp
void BindTypes(pybind11::module_& m);     // bind_types.cpp: Container, Settings, Body, Polyhedron
void BindWorld(pybind11::module_& m);     // bind_world.cpp: World
void BindScene(pybind11::module_& m);     // bind_scene.cpp: Scene, preset, load_scene
void BindDistance(pybind11::module_& m);  // bind_distance.cpp: distance

}  // namespace sparsedyn::python
