// The contact at any load (contact.hpp): any number of zones per period, full contact.
#include <pybind11/stl.h>

#include "bindings.hpp"
#include "wavecontact/contact.hpp"
#include "wavecontact/two_scale.hpp"

namespace wavecontact::python {

void bind_contact(py::module_& m) {
  using namespace py::literals;
  py::register_exception<BeyondReach>(m, "BeyondReach", PyExc_RuntimeError);
  py::class_<Harmonic>(m, "Harmonic", "A roughness harmonic H cos(n pi x/b1), n >= 1.")
      .def(py::init([](double H, int n) {
             return Harmonic{H, n};
           }),
           "H"_a, "n"_a)
      .def_readonly("H", &Harmonic::H)
      .def_readonly("n", &Harmonic::n)
      .def("__repr__", [](const Harmonic& h) {
        return repr_of_fields("Harmonic", {{"H", repr_of(h.H)}, {"n", repr_of(h.n)}});
      });

  py::class_<Surface>(m, "Surface", "An even surface of period 2 b1 for solve_contact().")
      .def(py::init<const WavinessParams&, const std::vector<Harmonic>&>(), "waviness"_a,
           "roughness"_a = std::vector<Harmonic>{}, "The wave curve plus any number of harmonics.")
      .def(py::init<const TwoScaleParams&>(), "params"_a, "The seed's two-scale profile (eq. 1).")
      .def(py::init<const Profile&>(), "profile"_a, "A user profile without a pole on the period.")
      .def_property_readonly("b1", &Surface::b1)
      .def_property_readonly("E", &Surface::E)
      .def(
          "height",
          [](const Surface& s, const py::handle& x) {
            return scalar_or_array(x, "wavecontact.Surface.height", "x", [&](double xi) { return s.height(xi); });
          },
          "x"_a, "y(x) [length] (a float or an array).");

  py::class_<ContactZone>(m, "ContactZone", "One zone of the period [-b1, b1); one around the valley ends past b1.")
      .def_readonly("x_start", &ContactZone::x_start)
      .def_readonly("x_end", &ContactZone::x_end)
      .def_readonly("load", &ContactZone::load, "the load it carries")
      .def_readonly("max_pressure", &ContactZone::max_pressure)
      .def_readonly("x_of_max_pressure", &ContactZone::x_of_max_pressure)
      .def("__repr__", [](const ContactZone& z) {
        return repr_of_fields("ContactZone", {{"x_start", repr_of(z.x_start)},
                                              {"x_end", repr_of(z.x_end)},
                                              {"load", repr_of(z.load)},
                                              {"max_pressure", repr_of(z.max_pressure)},
                                              {"x_of_max_pressure", repr_of(z.x_of_max_pressure)}});
      });

  py::class_<Contact>(m, "Contact", "The contact at one load: zones, pressure, gap, error estimate.")
      .def_property_readonly("load", &Contact::load, "P per period")
      .def_property_readonly("zones", &Contact::zones, "the zones of [-b1, b1), in increasing x_start")
      .def_property_readonly("zones_per_period", &Contact::zones_per_period)
      .def_property_readonly("full_contact", &Contact::full_contact)
      .def_property_readonly("contact_fraction", &Contact::contact_fraction, "contact length over the period")
      .def_property_readonly("max_pressure", &Contact::max_pressure)
      .def_property_readonly("x_of_max_pressure", &Contact::x_of_max_pressure)
      .def_property_readonly("error_estimate", &Contact::error_estimate,
                             "relative error of the pressure (to its maximum) and of the ends (to the period)")
      .def_property_readonly("rounding_error", &Contact::rounding_error,
                             "the part of error_estimate that rounding alone makes")
      .def_property_readonly("nodes_per_zone", &Contact::nodes_per_zone, "the most Chebyshev nodes of a zone")
      .def("__repr__",
           [](const Contact& c) {
             return repr_of_fields("Contact", {{"load", repr_of(c.load())},
                                               {"zones_per_period", repr_of(c.zones_per_period())},
                                               {"full_contact", repr_of(c.full_contact())},
                                               {"contact_fraction", repr_of(c.contact_fraction())},
                                               {"max_pressure", repr_of(c.max_pressure())},
                                               {"error_estimate", repr_of(c.error_estimate())}});
           })
      .def(
          "pressure",
          [](const Contact& c, const py::handle& x) {
            return scalar_or_array(
                x, "wavecontact.Contact.pressure", "x", [&](double xi) { return c.pressure(xi); },
                [&](const Eigen::Map<const Eigen::ArrayXd>& in, Eigen::Map<Eigen::ArrayXd>& out) {
                  c.pressure(in, out);
                });
          },
          "x"_a, "p(x) [pressure], 0 off the zones (a float or an array).")
      .def(
          "gap",
          [](const Contact& c, const py::handle& x) {
            return scalar_or_array(x, "wavecontact.Contact.gap", "x", [&](double xi) { return c.gap(xi); });
          },
          "x"_a, "The gap [length], 0 on the zones (a float or an array).");

  m.def(
      "solve_contact",
      [](const Surface& surface, const py::handle& P, double tolerance, int nodes_per_zone,
         double max_seconds) -> py::object {
        // Ctrl-C reaches the solve at its next safe point (about every tenth of a second):
        // the checkpoint takes the GIL, and a pending KeyboardInterrupt abandons the solve.
        SolverOptions options{tolerance, nodes_per_zone, max_seconds};
        options.checkpoint = [] {
          py::gil_scoped_acquire acquire;
          if (PyErr_CheckSignals() != 0) throw py::error_already_set();
        };
        if (py::isinstance<py::float_>(P) || py::isinstance<py::int_>(P)) {
          const double load = as_double(P, "wavecontact.solve_contact", "P");
          py::gil_scoped_release release;
          return py::cast(solve_contact(surface, load, options));
        }
        const auto loads = as_points(P, "wavecontact.solve_contact", "P");
        if (loads.ndim() == 0 && !py::isinstance<py::array>(P)) {  // a NumPy scalar: one load
          const double load = *loads.data();
          py::gil_scoped_release release;
          return py::cast(solve_contact(surface, load, options));
        }
        const std::vector<double> values(loads.data(), loads.data() + loads.size());
        std::vector<Contact> contacts;
        {
          py::gil_scoped_release release;
          contacts = solve_contact(surface, values, options);
        }
        return py::cast(contacts);
      },
      "surface"_a, "P"_a, "tolerance"_a = 1e-10, "nodes_per_zone"_a = 0, "max_seconds"_a = 60.0,
      "The contact carrying the load P > 0 per period: a Contact for a float, a list of them for "
      "a sequence or array of loads (one continuation through them). tolerance: the relative error "
      "estimate to meet; nodes_per_zone > 0 fixes the Chebyshev nodes of every zone; max_seconds: the work budget of "
      "each load, "
      "beyond which BeyondReach is raised. Ctrl-C interrupts it within a second.");
  m.def("full_contact_load", &full_contact_load, "surface"_a, "The load from which the contact is full.");

  py::class_<SingleZoneCheck>(m, "SingleZoneCheck", "Whether one zone |x| < a is the contact.")
      .def_readonly("solution", &SingleZoneCheck::solution)
      .def_readonly("penetrates", &SingleZoneCheck::penetrates)
      .def_readonly("lowest_gap", &SingleZoneCheck::lowest_gap)
      .def_readonly("x_of_lowest_gap", &SingleZoneCheck::x_of_lowest_gap)
      .def_readonly("lowest_pressure", &SingleZoneCheck::lowest_pressure)
      .def_readonly("x_of_lowest_pressure", &SingleZoneCheck::x_of_lowest_pressure)
      .def("__repr__", [](const SingleZoneCheck& r) {
        return repr_of_fields("SingleZoneCheck", {{"solution", repr_of(r.solution)},
                                                  {"penetrates", repr_of(r.penetrates)},
                                                  {"lowest_gap", repr_of(r.lowest_gap)},
                                                  {"x_of_lowest_gap", repr_of(r.x_of_lowest_gap)},
                                                  {"lowest_pressure", repr_of(r.lowest_pressure)},
                                                  {"x_of_lowest_pressure", repr_of(r.x_of_lowest_pressure)}});
      });
  m.def("single_zone_check", &single_zone_check, "surface"_a, "a"_a,
        "Whether the single zone of half-width a (eq. 12's pressure) is the contact: p >= 0 on it, gap >= 0 off it.");
}

}  // namespace wavecontact::python
