// A first guess of the contact zones at one load, for Newton's method on the zone system
// (docs/contact.md): the contact of the surface sampled on a uniform grid of the period,
// the pressure constant on each cell, solved as the quadratic programme it is by Polonsky and
// Keer's constrained conjugate gradients (Wear 231, 1999), every displacement by FFT. It
// knows the zones to about a cell; Newton's method on the zone system makes them exact, and
// the verification of the whole period finds any zone narrower than a cell it missed.
#pragma once

#include "surface_model.hpp"
#include "zone_system.hpp"

namespace wavecontact::detail {

// The zones (ends in x^ on [0, pi], sorted) and their densities' first coefficients (from the
// grid's pressure at each zone's `nodes` Chebyshev nodes) of the contact under the load P
// (normalised), on `cells` cells a period (a power of two); C is left at 0.
Configuration grid_seed(const SurfaceModel& surface, double P, int cells, int nodes);

// The cells a period for the surface: 32 a shortest wavelength, 1024 at least, 2^17 at most.
int seed_cells(const SurfaceModel& surface);

}  // namespace wavecontact::detail
