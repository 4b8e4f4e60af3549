// The `wavecontact` Python module: the runtime library (runtime/include/wavecontact/) on
// floats and NumPy arrays. std::domain_error becomes ValueError with the same message.
#include "bindings.hpp"

PYBIND11_MODULE(_wavecontact, m) {
  m.doc() =
      "Elastic contact of regular rough surfaces (Tsukanov): the closed forms derived by "
      "wavecontact-derive and the contact at any load, on floats and NumPy arrays.";
  m.attr("__version__") = WAVECONTACT_VERSION;
  wavecontact::python::bind_waviness(m);
  wavecontact::python::bind_two_scale(m);
  wavecontact::python::bind_profile(m);
  wavecontact::python::bind_contact(m);
  wavecontact::python::bind_map(m);
}
