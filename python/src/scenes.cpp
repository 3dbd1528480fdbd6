// Scenes: a shipped scene by name ("rope") or a JSON file, loaded as the command line loads it
// (app::resolve_scene, then load_scene with the --set overrides), and what it holds, read-only.
#include "bindings.hpp"
#include "util/data_dir.hpp"

namespace springlab::python {

namespace {

// A vector the scene owns as a read-only numpy view kept alive by the scene's Python object.
template <typename T>
py::array_t<T> vector_view(const std::vector<T>& values, const py::handle& owner) {
  py::array_t<T> a(static_cast<py::ssize_t>(values.size()), values.data(), owner);
  py::detail::array_proxy(a.ptr())->flags &= ~py::detail::npy_api::NPY_ARRAY_WRITEABLE_;
  return a;
}

using ScenePy = py::class_<LoadedScene, std::shared_ptr<LoadedScene>>;

// Scene's name, file and overrides, its description and counts, its settings (methods, dt,
// sub-steps, safety, duration, tolerance) and physics (gravity, drag).
void bind_scene_settings(ScenePy& scene) {
  scene.def_property_readonly("name", [](const LoadedScene& s) { return s.scene.name; })
      .def_property_readonly("file", [](const LoadedScene& s) { return s.scene.file; })
      .def_property_readonly(
          "overrides", [](const LoadedScene& s) { return s.sets; },
          "the --set overrides it was loaded with, as KEY=VALUE strings")
      .def_property_readonly("description",
                             [](const LoadedScene& s) { return s.scene.description; })
      .def_property_readonly("particle_count",
                             [](const LoadedScene& s) { return s.scene.model.particle_count(); })
      .def_property_readonly("spring_count",
                             [](const LoadedScene& s) { return s.scene.model.spring_count(); })
      .def_property_readonly(
          "methods",
          [](const LoadedScene& s) {
            std::vector<std::string> names;
            for (Method method : s.scene.methods) names.emplace_back(method_info(method).name);
            return names;
          },
          "the methods it shows side by side; the first is its default")
      .def_property_readonly(
          "dt", [](const LoadedScene& s) { return s.scene.dt; }, "its step, s")
      .def_property_readonly(
          "substeps",
          [](const LoadedScene& s) -> py::object {
            if (s.scene.substeps == 0) return py::str("auto");
            return py::int_(s.scene.substeps);
          },
          "its sub-steps a step: a number, or 'auto'")
      .def_property_readonly("safety", [](const LoadedScene& s) { return s.scene.safety; })
      .def_property_readonly(
          "duration", [](const LoadedScene& s) { return s.scene.duration; }, "s")
      .def_property_readonly("tolerance", [](const LoadedScene& s) { return s.scene.tolerance; })
      .def_property_readonly("inverse_kinematics",
                             [](const LoadedScene& s) { return s.scene.ik.has_value(); })
      .def_property_readonly("gravity",
                             [](const LoadedScene& s) { return Vec3(s.scene.model.gravity); })
      .def_property_readonly("drag", [](const LoadedScene& s) { return s.scene.model.drag; });
}

// Scene's arrays (positions, velocities, masses, pinned, springs, rest lengths; the read-only
// ones views of the loaded scene), its generators' particles by name, and its repr.
void bind_scene_arrays(ScenePy& scene) {
  scene
      .def_property_readonly(
          "positions", [](const LoadedScene& s) { return view(s.scene.state.x); },
          py::return_value_policy::reference_internal, "N x 3, m (read-only)")
      .def_property_readonly(
          "velocities", [](const LoadedScene& s) { return view(s.scene.state.v); },
          py::return_value_policy::reference_internal, "N x 3, m/s (read-only)")
      .def_property_readonly(
          "masses",
          [](const py::object& self) {
            return vector_view(self.cast<const LoadedScene&>().scene.model.mass, self);
          },
          "kg, each particle's (read-only)")
      .def_property_readonly(
          "pinned",
          [](const LoadedScene& s) {
            py::array_t<bool> pinned(s.scene.model.particle_count());
            auto out = pinned.mutable_unchecked<1>();
            for (int i = 0; i < s.scene.model.particle_count(); ++i)
              out(i) = s.scene.model.pinned(i);
            return pinned;
          },
          "whether each particle is pinned")
      .def_property_readonly(
          "springs",
          [](const LoadedScene& s) {
            const Model& model = s.scene.model;
            py::array_t<std::int32_t> ends({model.spring_count(), 2});
            auto out = ends.mutable_unchecked<2>();
            for (int k = 0; k < model.spring_count(); ++k) {
              out(k, 0) = model.spring_a[k];
              out(k, 1) = model.spring_b[k];
            }
            return ends;
          },
          "S x 2, the particles each spring joins")
      .def_property_readonly(
          "rest_lengths",
          [](const py::object& self) {
            return vector_view(self.cast<const LoadedScene&>().scene.model.rest_length, self);
          },
          "m, each spring's (read-only)")
      .def_property_readonly(
          "named",
          [](const LoadedScene& s) {
            py::dict named;
            for (const auto& [name, range] : s.scene.named)
              named[py::str(name)] = py::make_tuple(range.first, range.second);
            return named;
          },
          "each generator's particles: name -> (first, count)")
      .def("__repr__", [](const LoadedScene& s) {
        return "<springlab.Scene '" + s.scene.name +
               "': " + std::to_string(s.scene.model.particle_count()) + " particles, " +
               std::to_string(s.scene.model.spring_count()) + " springs>";
      });
}

}  // namespace

void bind_scenes(py::module_& m) {
  ScenePy scene_class(m, "Scene", R"(A scene as loaded from its JSON file.

Made by springlab.load_scene(); its arrays are read-only views of the loaded scene. A Simulation,
a sweep or a StabilityAnalysis made from it starts from this state.)");
  bind_scene_settings(scene_class);
  bind_scene_arrays(scene_class);

  m.def(
      "load_scene",
      [](const std::string& scene, const py::object& set) {
        auto loaded = std::make_shared<LoadedScene>();
        loaded->sets = set_overrides(set);
        loaded->path = app::resolve_scene(scene);
        loaded->scene = load_scene(loaded->path, loaded->sets);
        return loaded;
      },
      py::arg("scene"), py::arg("set") = py::none(),
      R"(Loads a scene: a shipped scene's name ("rope") or a JSON file.

set: overrides, as the command line's --set: "rope.nodes=64", a list of such strings, or a dict
{"cloth.width": 64, "gravity": [0, -9.81, 0]}. Bad input raises springlab.InputError with the
command line's message.)");
  m.def("scenes", &app::shipped_scenes, "the names of the shipped scenes, sorted");
  m.def("tableaux", &app::shipped_tableaux,
        "the names of the shipped Butcher tableaux, sorted (each usable as a method)");
  m.def(
      "data_dir", [] { return app::data_dir().string(); },
      "the folder the shipped scenes and tableaux are read from (assets/ in it)");
}

}  // namespace springlab::python
