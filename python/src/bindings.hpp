// The pieces of the `wavecontact` Python module (python/src/bind_*.cpp) and what they share:
// the scalar-or-array convention of every evaluator that takes x.
#pragma once

#include <initializer_list>
#include <string>
#include <utility>

#include <Eigen/Core>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

namespace wavecontact::python {

namespace py = pybind11;

void bind_waviness(py::module_& m);
void bind_two_scale(py::module_& m);
void bind_profile(py::module_& m);
void bind_contact(py::module_& m);
void bind_map(py::module_& m);

// Python's repr of a field, for the reprs of the module's value types.
inline std::string repr_of(double x) { return py::repr(py::float_(x)); }
inline std::string repr_of(int n) { return std::to_string(n); }
inline std::string repr_of(bool b) { return b ? "True" : "False"; }
// "Type(name=value, ...)", the fields' values already repr_of's.
inline std::string repr_of_fields(const char* type, std::initializer_list<std::pair<const char*, std::string>> fields) {
  std::string text = std::string(type) + "(";
  for (const auto& [name, value] : fields) text += (text.back() == '(' ? "" : ", ") + std::string(name) + "=" + value;
  return text + ")";
}

// x as a C-contiguous float64 array: the caller's own memory when it already is one (no
// copy), otherwise converted once. Whatever is not real numbers (None, strings, complex
// numbers, whose imaginary part a cast would drop) is a ValueError naming the function and
// the parameter; non-finite values are the runtime's to refuse.
inline py::array_t<double, py::array::c_style> as_points(const py::handle& x, const char* function, const char* name) {
  auto refuse = [&](const std::string& what) {
    return py::value_error(std::string(function) + ": " + name + " must be a number or an array of numbers, not " +
                           what);
  };
  if (x.is_none() || PyComplex_Check(x.ptr())) throw refuse(std::string(py::str(py::type::of(x).attr("__name__"))));
  const auto array = py::array::ensure(x);
  if (!array) throw refuse(std::string(py::str(py::type::of(x).attr("__name__"))));
  const char kind = array.dtype().kind();
  if (kind != 'f' && kind != 'i' && kind != 'u' && kind != 'b') {
    throw refuse("an array of dtype " + std::string(py::str(array.dtype())));
  }
  auto points = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(array);
  if (!points) throw refuse(std::string(py::str(py::type::of(x).attr("__name__"))));
  return points;
}

// A Python int or float as a double: an int beyond the doubles is a ValueError (not an
// OverflowError from deep inside the conversion).
inline double as_double(const py::handle& x, const char* function, const char* name) {
  if (py::isinstance<py::int_>(x)) {
    const double value = PyLong_AsDouble(x.ptr());
    if (value == -1.0 && PyErr_Occurred()) {
      PyErr_Clear();
      throw py::value_error(std::string(function) + ": " + name + " = " +
                            std::string(py::str(py::repr(x))).substr(0, 40) + "... is beyond the range of a double");
    }
    return value;
  }
  return x.cast<double>();
}

// Enum(value) for a value of one of its `count` members 0 .. count - 1, else ValueError
// (pybind11's own constructor takes any int).
template <class Enum, int count>
Enum checked_enum(int value) {
  if (value < 0 || value >= count) {
    throw py::value_error("wavecontact: " + std::to_string(value) + " is not a value of this enum (0 to " +
                          std::to_string(count - 1) + ")");
  }
  return static_cast<Enum>(value);
}

// An evaluator of one point applied to a number (a float back), or to an array of any shape
// (an array of that shape back: one allocation). kernel(x, p) fills p from x without the GIL.
template <class Scalar, class Kernel>
py::object scalar_or_array(const py::handle& x, const char* function, const char* name, Scalar scalar, Kernel kernel) {
  if (py::isinstance<py::float_>(x) || py::isinstance<py::int_>(x)) {
    return py::float_(scalar(as_double(x, function, name)));
  }
  const auto points = as_points(x, function, name);
  if (points.ndim() == 0 && !py::isinstance<py::array>(x)) return py::float_(scalar(*points.data()));  // numpy.int64(3)
  py::array_t<double> result(std::vector<py::ssize_t>(points.shape(), points.shape() + points.ndim()));
  const Eigen::Map<const Eigen::ArrayXd> in(points.data(), points.size());
  Eigen::Map<Eigen::ArrayXd> out(result.mutable_data(), result.size());
  {
    py::gil_scoped_release release;
    kernel(in, out);
  }
  return std::move(result);
}

// The same for an evaluator that has only a scalar form: the loop runs without the GIL.
template <class Scalar>
py::object scalar_or_array(const py::handle& x, const char* function, const char* name, Scalar scalar) {
  return scalar_or_array(x, function, name, scalar,
                         [&](const Eigen::Map<const Eigen::ArrayXd>& in, Eigen::Map<Eigen::ArrayXd>& out) {
                           for (Eigen::Index i = 0; i < in.size(); ++i) out[i] = scalar(in[i]);
                         });
}

}  // namespace wavecontact::python
