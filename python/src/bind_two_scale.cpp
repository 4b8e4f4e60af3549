// The two-scale profile of eq. 1 with one zone per period (two_scale.hpp): the roughness
// harmonic for any even n, the coefficients of eq. 18.
#include <pybind11/stl.h>

#include "bindings.hpp"
#include "wavecontact/two_scale.hpp"

namespace wavecontact::python {

void bind_two_scale(py::module_& m) {
  using namespace py::literals;
  py::class_<RoughnessParams>(m, "RoughnessParams", "The roughness harmonic of eq. 3, H2 cos(n pi x/b1), n even.")
      .def(py::init([](double H2, int n) {
             const RoughnessParams p{H2, n};
             validate(p, "wavecontact.RoughnessParams");
             return p;
           }),
           "H2"_a, "n"_a, "Height H2 >= 0 [length] and wavelength ratio n = b1/b2, even, 2..4096.")
      .def_readonly("H2", &RoughnessParams::H2, "height of the roughness [length]")
      .def_readonly("n", &RoughnessParams::n, "wavelength ratio b1/b2")
      .def("__repr__", [](const RoughnessParams& r) {
        return repr_of_fields("RoughnessParams", {{"H2", repr_of(r.H2)}, {"n", repr_of(r.n)}});
      });
  py::class_<TwoScaleParams>(m, "TwoScaleParams", "The two-scale profile of eq. 1: waviness plus roughness.")
      .def(py::init([](const WavinessParams& w, const RoughnessParams& r) {
             return TwoScaleParams{w, r};
           }),
           "waviness"_a, "roughness"_a)
      .def_readonly("waviness", &TwoScaleParams::waviness)
      .def_readonly("roughness", &TwoScaleParams::roughness)
      .def("__repr__", [](const TwoScaleParams& t) {
        return repr_of_fields("TwoScaleParams", {{"waviness", py::repr(py::cast(t.waviness))},
                                                 {"roughness", py::repr(py::cast(t.roughness))}});
      });

  py::class_<TwoScaleContact>(m, "TwoScaleContact",
                              "One zone of half-width a of the two-scale profile (eq. 21 with the exact "
                              "parts). pressure() refuses a zone that is not the contact (ValueError): "
                              "solve_contact() gives the contact at any load.")
      .def(py::init<const TwoScaleParams&, double, Form>(), "params"_a, "a"_a, "form"_a = Form::exact)
      .def(
          "waviness_pressure",
          [](const TwoScaleContact& c, const py::handle& x) {
            return scalar_or_array(x, "wavecontact.TwoScaleContact.waviness_pressure", "x",
                                   [&](double xi) { return c.waviness_pressure(xi); });
          },
          "x"_a, "The waviness part of the pressure at x (a float or an array).")
      .def(
          "roughness_pressure",
          [](const TwoScaleContact& c, const py::handle& x) {
            return scalar_or_array(
                x, "wavecontact.TwoScaleContact.roughness_pressure", "x",
                [&](double xi) { return c.roughness_pressure(xi); },
                [&](const Eigen::Map<const Eigen::ArrayXd>& in, Eigen::Map<Eigen::ArrayXd>& out) {
                  c.roughness_pressure(in, out);
                });
          },
          "x"_a, "The roughness part of the pressure at x (a float or an array; arrays vectorised).")
      .def(
          "pressure",
          [](const TwoScaleContact& c, const py::handle& x) {
            return scalar_or_array(
                x, "wavecontact.TwoScaleContact.pressure", "x", [&](double xi) { return c.pressure(xi); },
                [&](const Eigen::Map<const Eigen::ArrayXd>& in, Eigen::Map<Eigen::ArrayXd>& out) {
                  c.pressure(in, out);
                });
          },
          "x"_a, "Waviness plus roughness pressure at x; ValueError if the zone is not the contact.")
      .def_property_readonly("waviness_load", &TwoScaleContact::waviness_load)
      .def_property_readonly("roughness_load", &TwoScaleContact::roughness_load)
      .def_property_readonly("load", &TwoScaleContact::load, "the load the zone carries")
      .def_property_readonly("admissible", &TwoScaleContact::admissible, "p >= 0 in the zone and gap >= 0 off it")
      .def_property_readonly("most_negative_x", &TwoScaleContact::most_negative_x)
      .def_property_readonly("most_negative_pressure", &TwoScaleContact::most_negative_pressure)
      .def_property_readonly("lowest_gap", &TwoScaleContact::lowest_gap, "< 0: a neighbour penetrates")
      .def_property_readonly("x_of_lowest_gap", &TwoScaleContact::x_of_lowest_gap)
      .def_property_readonly("half_width", &TwoScaleContact::half_width);

  m.def("roughness_full_contact_pressure", &roughness_full_contact_pressure, "params"_a, "x"_a,
        "Eq. 15: the roughness harmonic in full contact at its onset.");
  m.def("two_scale_half_widths", &two_scale_half_widths, "params"_a, "P"_a,
        "Every single-zone half-width of the two-scale profile carrying P, with stability and "
        "admissibility.");
  m.def("available_roughness_n", &available_roughness_n,
        "Every n whose generated roughness evaluators are compiled in (others: wavecontact-derive --n N "
        "and register_roughness_evaluator() from C++).");
  m.def(
      "kcoef",
      [](int n) {
        const std::vector<std::string> k = expansion_coefficients(n);
        const py::object fraction = py::module_::import("fractions").attr("Fraction");
        py::list result;
        for (const std::string& value : k) result.append(fraction(value));
        return result;
      },
      "n"_a, "The exact k_1..k_n of eq. 18 as fractions.Fraction, any even n from 2 to 4096.");
}

}  // namespace wavecontact::python
