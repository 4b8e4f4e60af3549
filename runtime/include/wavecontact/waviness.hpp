// Contact of the parametric wave curve (seed eq. 2) with an elastic half-plane:
// one contact zone |x| <= a per period, a <= b1/2 (the contact stays on the top half of
// each asperity, where eq. 11 holds). All formulas are the closed forms derived by
// wavecontact-derive (generated/waviness.hpp).
#pragma once

#include <Eigen/Core>

#include "wavecontact/parameters.hpp"

namespace wavecontact {

// Contact pressure p(x) [pressure] for the contact half-width a, 0 < a <= b1/2.
// x is taken modulo the period 2 b1; outside the contact zone the pressure is 0.
double pressure(const WavinessParams& params, double a, double x, Form form = Form::exact);

// The same at every point of x.
Eigen::ArrayXd pressure(const WavinessParams& params, double a,
                        const Eigen::Ref<const Eigen::ArrayXd>& x, Form form = Form::exact);

// Load per unit length P = Int p dx over one zone (eq. 6) [pressure x length].
// The printed eq. 13/14 integrates to the same load, so there is one load function.
double load(const WavinessParams& params, double a);

// Mean pressure pa = P / L1 = P / (2 b1).
double mean_pressure(const WavinessParams& params, double a);

// p* = pi E* H1 / (2 b1), the mean pressure of full contact of a sine wave.
double pstar(const WavinessParams& params);

// pa / p*, dimensionless.
double pa_over_pstar(const WavinessParams& params, double a);

// 2a / L1 = a / b1.
double contact_fraction(const WavinessParams& params, double a);

// Inverse of load(): the half-width a in (0, b1/2] that carries the load P,
// 0 < P <= load(params, b1/2). A bracketed root (TOMS 748) on the closed-form load.
double contact_half_width(const WavinessParams& params, double P);

// Inverse of pa_over_pstar().
double contact_half_width_for_pa_over_pstar(const WavinessParams& params, double ratio);

// The profile w(x, m) of eq. 2 (both branches, any x).
double wave_curve(const WavinessParams& params, double x);

}  // namespace wavecontact
