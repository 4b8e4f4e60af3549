// User profiles derived by wavecontact-derive --profile (profile.hpp), their single-zone
// checks (stability.hpp), and shape design (shape_design.hpp).
#include <pybind11/stl.h>

#include "bindings.hpp"
#include "wavecontact/profile.hpp"
#include "wavecontact/shape_design.hpp"
#include "wavecontact/stability.hpp"

namespace wavecontact::python {

void bind_profile(py::module_& m) {
  using namespace py::literals;
  m.def("available_profiles", &available_profiles, "Every user profile compiled in or registered, sorted.");
  m.def(
      "profile_parameters", [](const std::string& name) { return profile_evaluator(name).parameters; }, "name"_a,
      "The parameter names of a profile, in its order.");
  m.def(
      "profile_expression", [](const std::string& name) { return profile_evaluator(name).expression; }, "name"_a,
      "The profile's expression y(x^) over the period 2 pi of x^ = pi x/b1.");

  py::class_<Profile>(m, "Profile",
                      "A user profile with its parameters bound and checked: one contact zone |x| < a per "
                      "period 2 b1.")
      .def(py::init([](const std::string& name, double b1, double E, const py::kwargs& parameters) {
             ProfileParams p{name, {}, b1, E};
             for (const auto& [key, value] : parameters) p.parameters[py::str(key)] = value.cast<double>();
             return Profile(p);
           }),
           "name"_a, "b1"_a, "E"_a,
           "Profile(name, b1, E, **parameters), e.g. Profile('two_harmonic', b1=10, E=1, H1=1, H3=-0.2). "
           "ValueError if a parameter is missing, unknown or not finite.")
      .def_property_readonly("name", [](const Profile& p) { return p.params().name; })
      .def_property_readonly("parameters", [](const Profile& p) { return p.params().parameters; })
      .def_property_readonly("b1", [](const Profile& p) { return p.params().b1; })
      .def_property_readonly("E", [](const Profile& p) { return p.params().E; })
      .def_property_readonly("reach", &Profile::reach, "the largest half-width: b1, or the first pole of the profile")
      .def(
          "pressure",
          [](const Profile& p, double a, const py::handle& x) {
            return scalar_or_array(x, "wavecontact.Profile.pressure", "x",
                                   [&](double xi) { return p.pressure(a, xi); });
          },
          "a"_a, "x"_a, "p(x) for the half-width a, 0 < a < reach (a float or an array).")
      .def("load", &Profile::load, "a"_a, "P (eq. 6) for the half-width a.")
      .def("load_slope", &Profile::load_slope, "a"_a, "dP/da.")
      .def("full_contact_pressure", &Profile::full_contact_pressure, "P"_a, "x"_a,
           "Full contact in closed form: P/(2 b1) + p_fc(x), while it is >= 0.");

  m.def("admissibility", py::overload_cast<const Profile&, double>(&admissibility), "profile"_a, "a"_a,
        "Whether the single zone of half-width a of a user profile is the contact.");
  m.def("contact_half_width", py::overload_cast<const Profile&, double>(&contact_half_width), "profile"_a, "P"_a,
        "The one half-width of a user profile carrying P.");

  py::class_<PressureUniformity>(m, "PressureUniformity", "How uniform the pressure of one shape is.")
      .def_readonly("m", &PressureUniformity::m, "shape parameter")
      .def_readonly("a_over_b1", &PressureUniformity::a_over_b1, "contact half-width / b1")
      .def_readonly("max_over_mean", &PressureUniformity::max_over_mean, "max p / mean p over the zone, >= 1")
      .def_readonly("x_of_max_over_a", &PressureUniformity::x_of_max_over_a, "where the maximum is, x/a")
      .def("__repr__", [](const PressureUniformity& u) {
        return repr_of_fields("PressureUniformity", {{"m", repr_of(u.m)},
                                                     {"a_over_b1", repr_of(u.a_over_b1)},
                                                     {"max_over_mean", repr_of(u.max_over_mean)},
                                                     {"x_of_max_over_a", repr_of(u.x_of_max_over_a)}});
      });
  m.def("pressure_uniformity", &pressure_uniformity, "m"_a, "pa_over_pstar"_a,
        "max p / mean p for the shape m at pa/p*.");
  m.def("most_uniform_shape", &most_uniform_shape, "pa_over_pstar"_a, "m_max"_a = 100.0,
        "The m in [0, m_max] whose pressure is most uniform at pa/p* (CLI: optimize-shape).");
}

}  // namespace wavecontact::python
