// The wave curve (waviness.hpp, parameters.hpp) and the single-zone solutions over the whole
// range with their stability and admissibility (stability.hpp).
#include <pybind11/stl.h>

#include "bindings.hpp"
#include "wavecontact/isa.hpp"
#include "wavecontact/stability.hpp"
#include "wavecontact/threads.hpp"
#include "wavecontact/waviness.hpp"
#include "wavecontact/waviness_zone.hpp"

namespace wavecontact::python {

namespace {

std::string repr(const WavinessParams& p) {
  return repr_of_fields("WavinessParams",
                        {{"H1", repr_of(p.H1)}, {"b1", repr_of(p.b1)}, {"m", repr_of(p.m)}, {"E", repr_of(p.E)}});
}

}  // namespace

void bind_waviness(py::module_& m) {
  using namespace py::literals;
  py::enum_<Form>(m, "Form", "Which closed form: the exact solution of eq. 12, or the paper's printed eq. 13/14.")
      .value("exact", Form::exact, "the exact solution of eq. 12 (derived by wavecontact-derive)")
      .value("paper", Form::paper, "eq. 13/14 as printed: exact only for m = 0")
      .def(py::init(&checked_enum<Form, 2>), "value"_a, py::prepend());

  py::class_<WavinessParams>(m, "WavinessParams",
                             "The parametric wave curve of eq. 2, w = H1 (m+1) cos(pi x/b1) / "
                             "(m |cos(pi x/b1)| + 1), against a half-plane of reduced modulus E*.")
      .def(py::init([](double H1, double b1, double m, double E) {
             const WavinessParams p{H1, b1, m, E};
             validate(p, "wavecontact.WavinessParams");
             return p;
           }),
           "H1"_a, "b1"_a, "m"_a, "E"_a,
           "Height H1 [length], half-period b1 [length], shape m >= 0 (0 sine, 0.2 ~ parabola, "
           "large: flat punch), reduced modulus E [pressure]. ValueError if one is invalid.")
      .def_readonly("H1", &WavinessParams::H1, "height of the wave [length]")
      .def_readonly("b1", &WavinessParams::b1, "half-period [length]")
      .def_readonly("m", &WavinessParams::m, "shape parameter")
      .def_readonly("E", &WavinessParams::E, "reduced modulus E* [pressure]")
      .def("__repr__", &repr);

  py::enum_<Isa>(m, "Isa", "The instruction set of the array kernels (wavecontact/isa.hpp).")
      .value("scalar", Isa::scalar, "the scalar loops")
      .value("avx2", Isa::avx2, "AVX2 + FMA kernels")
      .value("avx512", Isa::avx512, "the same with sincospi 8 wide")
      .def(py::init(&checked_enum<Isa, 3>), "value"_a, py::prepend());
  m.def("array_kernel_isa", &array_kernel_isa,
        "The path the array kernels run on: the best the CPU has, or WAVECONTACT_ISA "
        "(scalar, avx2, avx512) capped at it, read at the first array evaluation.");
  m.def("cpu_isa", &cpu_isa, "The best array-kernel path this CPU has.");
  m.def("array_kernel_threads", &array_kernel_threads,
        "The most threads an array evaluation uses: set_array_kernel_threads(), else WAVECONTACT_THREADS, "
        "else the CPU's hardware threads. Results are the same bits whatever the count.");
  m.def("set_array_kernel_threads", &set_array_kernel_threads, "threads"_a,
        "Caps the threads of the array evaluations (1: the calling thread only; 0: the default).");

  m.def("reduced_modulus", &reduced_modulus, "E1"_a, "nu1"_a, "E2"_a, "nu2"_a,
        "Eq. 7, plane strain: 1/E* = (1 - nu1^2)/E1 + (1 - nu2^2)/E2.");

  m.def(
      "pressure",
      [](const WavinessParams& p, double a, const py::handle& x, Form form) {
        return scalar_or_array(
            x, "wavecontact.pressure", "x", [&](double xi) { return pressure(p, a, xi, form); },
            [&](const Eigen::Map<const Eigen::ArrayXd>& in, Eigen::Map<Eigen::ArrayXd>& out) {
              pressure(p, a, in, out, form);
            });
      },
      "params"_a, "a"_a, "x"_a, "form"_a = Form::exact,
      "Contact pressure p(x) [pressure] of one zone of half-width a, 0 < a < b1, at x (a float, "
      "or an array of any shape: the result has its shape). x is taken modulo 2 b1; 0 off the "
      "zone. Arrays use the vectorised kernel (AVX2) without the GIL.");
  py::enum_<AtomTables>(m, "AtomTables",
                        "Beyond a = b1/2, how a WavinessZone takes the atoms of the points near the other "
                        "branch's pole.")
      .value("kept", AtomTables::kept,
             "tabulated, a panel the first time a point falls into it (some tens of us, once), then about "
             "0.1 us a point; the same values from a point or an array, within a few eps of pressure()'s")
      .value("per_call", AtomTables::per_call,
             "as pressure() takes them (about 2 us a point), and so its values bit for bit")
      .def(py::init(&checked_enum<AtomTables, 2>), "value"_a, py::prepend());
  py::class_<WavinessZone>(m, "WavinessZone",
                           "One zone of half-width a, prepared once: pressure(x) then costs only the point's "
                           "own terms (what depends on params and a alone is computed once). Up to a = b1/2 the "
                           "values are pressure()'s, bit for bit; beyond, see AtomTables.")
      .def(py::init<const WavinessParams&, double, Form, AtomTables>(), "params"_a, "a"_a, "form"_a = Form::exact,
           "tables"_a = AtomTables::kept, "The zone |x| <= a, 0 < a < b1; ValueError if a or params is invalid.")
      .def(
          "pressure",
          [](const WavinessZone& zone, const py::handle& x) {
            return scalar_or_array(
                x, "wavecontact.WavinessZone.pressure", "x", [&](double xi) { return zone.pressure(xi); },
                [&](const Eigen::Map<const Eigen::ArrayXd>& in, Eigen::Map<Eigen::ArrayXd>& out) {
                  zone.pressure(in, out);
                });
          },
          "x"_a, "p(x) [pressure] at x (a float, or an array of any shape: the result has its shape); 0 off the zone.")
      .def_property_readonly("params", &WavinessZone::params, "the wave curve")
      .def_property_readonly("a", &WavinessZone::half_width, "the half-width [length]")
      .def_property_readonly("form", &WavinessZone::form, "the closed form evaluated")
      .def_property_readonly("tables", &WavinessZone::atom_tables, "how it takes the atoms beyond b1/2")
      .def("__repr__", [](const WavinessZone& z) {
        return "WavinessZone(" + repr(z.params()) + ", a=" + repr_of(z.half_width()) +
               ", form=" + (z.form() == Form::exact ? "Form.exact" : "Form.paper") +
               ", tables=" + (z.atom_tables() == AtomTables::kept ? "AtomTables.kept" : "AtomTables.per_call") + ")";
      });
  m.def("load", &load, "params"_a, "a"_a, "form"_a = Form::exact,
        "Load per unit length P (eq. 6) carried by one zone of half-width a, 0 < a <= b1.");
  m.def("load_slope", &load_slope, "params"_a, "a"_a, "dP/da of the exact load, 0 < a <= b1.");
  m.def("mean_pressure", &mean_pressure, "params"_a, "a"_a, "Mean pressure pa = P/(2 b1).");
  m.def("pstar", &pstar, "params"_a, "p* = pi E* H1/(2 b1), the mean pressure of full contact of a sine wave.");
  m.def("pa_over_pstar", &pa_over_pstar, "params"_a, "a"_a, "form"_a = Form::exact,
        "pa/p* = P/(pi E* H1) for the half-width a.");
  m.def("contact_fraction", &contact_fraction, "params"_a, "a"_a, "2a/L1 = a/b1.");
  m.def("single_asperity_half_width", &single_asperity_half_width, "params"_a, "P"_a,
        "The half-width a in (0, b1/2] carrying the load P (0 < P <= load(params, b1/2)).");
  m.def(
      "wave_curve",
      [](const WavinessParams& p, const py::handle& x) {
        return scalar_or_array(x, "wavecontact.wave_curve", "x", [&](double xi) { return wave_curve(p, xi); });
      },
      "params"_a, "x"_a, "The profile w(x, m) of eq. 2 at x (a float or an array).");

  py::class_<Admissibility>(m, "Admissibility", "Whether one zone is the contact: p >= 0 in it and gap >= 0 off it.")
      .def_readonly("admissible", &Admissibility::admissible, "p >= 0 in the zone and gap >= 0 off it")
      .def_readonly("most_negative_x", &Admissibility::most_negative_x, "where p is lowest (0 if p >= 0)")
      .def_readonly("most_negative_pressure", &Admissibility::most_negative_pressure, "that p if < 0, else 0")
      .def_readonly("lowest_gap", &Admissibility::lowest_gap, "the lowest gap off the zone [length]")
      .def_readonly("x_of_lowest_gap", &Admissibility::x_of_lowest_gap, "where, x >= 0")
      .def("__repr__", [](const Admissibility& r) {
        return repr_of_fields("Admissibility", {{"admissible", repr_of(r.admissible)},
                                                {"most_negative_x", repr_of(r.most_negative_x)},
                                                {"most_negative_pressure", repr_of(r.most_negative_pressure)},
                                                {"lowest_gap", repr_of(r.lowest_gap)},
                                                {"x_of_lowest_gap", repr_of(r.x_of_lowest_gap)}});
      });
  m.def("admissibility", py::overload_cast<const WavinessParams&, double>(&admissibility), "params"_a, "a"_a,
        "Whether the single zone of half-width a, 0 < a < b1, of the wave curve is the contact.");

  py::class_<HalfWidthRange>(m, "HalfWidthRange", "A range of half-widths [begin, end).")
      .def_readonly("begin", &HalfWidthRange::begin)
      .def_readonly("end", &HalfWidthRange::end)
      .def("__repr__", [](const HalfWidthRange& r) {
        return repr_of_fields("HalfWidthRange", {{"begin", repr_of(r.begin)}, {"end", repr_of(r.end)}});
      });
  py::class_<Equilibrium>(m, "Equilibrium", "A half-width carrying a load, its stability and admissibility.")
      .def_readonly("a", &Equilibrium::a, "contact half-width [length]")
      .def_readonly("stable", &Equilibrium::stable, "dP/da > 0")
      .def_readonly("admissible", &Equilibrium::admissible, "p >= 0 in the zone and gap >= 0 off it")
      .def("__repr__", [](const Equilibrium& e) {
        return repr_of_fields(
            "Equilibrium", {{"a", repr_of(e.a)}, {"stable", repr_of(e.stable)}, {"admissible", repr_of(e.admissible)}});
      });
  py::class_<LoadCurve>(m, "LoadCurve",
                        "The single-zone load P(a) over 0 < a <= b1 with its turning points, located "
                        "once, so that equilibria(P) is cheap.")
      .def(py::init<const WavinessParams&>(), "params"_a, "The load curve of the wave curve.")
      .def(py::init<const Profile&>(), "profile"_a, "The load curve of a user profile.")
      .def_property_readonly("unstable_ranges", &LoadCurve::unstable_ranges, "the ranges of a where dP/da < 0")
      .def_property_readonly("maximum_load", &LoadCurve::maximum_load, "the largest single-zone load")
      .def_property_readonly("full_contact_load", &LoadCurve::full_contact_load, "P at a = b1")
      .def("equilibria", &LoadCurve::equilibria, "P"_a,
           "Every half-width carrying P, in increasing order, with stability and admissibility.");

  m.def("contact_half_width", py::overload_cast<const WavinessParams&, double>(&contact_half_width), "params"_a, "P"_a,
        "The one half-width carrying P; ValueError if several do (use LoadCurve.equilibria) or none.");
  m.def("contact_half_width_for_pa_over_pstar", &contact_half_width_for_pa_over_pstar, "params"_a, "pa_over_pstar"_a,
        "contact_half_width for the load pa/p* = P/(pi E* H1).");
}

}  // namespace wavecontact::python
