// Contact of the parametric wave curve (seed eq. 2) with an elastic half-plane: one contact
// zone |x| <= a per period, 0 < a < b1.
// - a <= b1/2 (single-asperity regime, the zone stays on the top half of each asperity,
//   where eq. 11 holds): the closed forms derived by wavecontact-derive (generated/waviness_evaluators.hpp).
// - a > b1/2 (periodic regime, the zone reaches the |cos| branch of eq. 2, whose slope has
//   a kink at x = b1/2): the exact form is the inversion of eq. 12 by quadrature split at
//   the kink, geometrically convergent on each smooth piece (runtime/src/closed_forms/kinked_inversion.*);
//   Form::paper continues the printed eq. 13/14, as the seed's Fig. 5b does.
// Whether the single-zone solution is physical (p >= 0) and stable (dP/da > 0): stability.hpp.
#pragma once

#include <Eigen/Core>

#include "wavecontact/parameters.hpp"

namespace wavecontact {

// Contact pressure p(x) [pressure] for the contact half-width a, 0 < a < b1 (printed form:
// beyond b1/2 only while 1 + m cos(pi a/b1) > 0). x is taken modulo the period 2 b1;
// outside the contact zone the pressure is 0. For many calls on one zone, WavinessZone
// (waviness_zone.hpp) keeps what depends on (params, a) alone.
double pressure(const WavinessParams& params, double a, double x, Form form = Form::exact);

// The same at every point of x. For a <= b1/2 on a CPU with AVX2 and FMA this is a
// vectorised kernel (SLEEF sinpi/cospi, then the generated closed form), same accuracy.
Eigen::ArrayXd pressure(const WavinessParams& params, double a, const Eigen::Ref<const Eigen::ArrayXd>& x,
                        Form form = Form::exact);

// The same into p (p.size() == x.size()), without allocating.
void pressure(const WavinessParams& params, double a, const Eigen::Ref<const Eigen::ArrayXd>& x,
              Eigen::Ref<Eigen::ArrayXd> p, Form form = Form::exact);

// Load per unit length P = Int p dx over one zone (eq. 6) [pressure x length], 0 < a <= b1
// (a = b1: the onset of full contact). Up to b1/2 the printed eq. 13/14 integrates to the
// same load; beyond, Form::paper is the continuation of that closed form.
double load(const WavinessParams& params, double a, Form form = Form::exact);

// dP/da of the exact load [pressure], 0 < a <= b1 (closed form up to b1/2, fact 7 by
// quadrature beyond); negative where the single-zone equilibrium is unstable (snap-through).
double load_slope(const WavinessParams& params, double a);

// Mean pressure pa = P / L1 = P / (2 b1).
double mean_pressure(const WavinessParams& params, double a);

// p* = pi E* H1 / (2 b1), the mean pressure of full contact of a sine wave.
double pstar(const WavinessParams& params);

// pa / p* = P / (pi E* H1), dimensionless.
double pa_over_pstar(const WavinessParams& params, double a, Form form = Form::exact);

// 2a / L1 = a / b1.
double contact_fraction(const WavinessParams& params, double a);

// The half-width a in (0, b1/2] (single-asperity regime) that carries the load P,
// 0 < P <= load(params, b1/2): safeguarded Newton on the closed-form load and its
// derivative (both generated), in Sa = 1 - cos(pi a/b1).
// Every solution over the whole range, with its stability: stability.hpp.
double single_asperity_half_width(const WavinessParams& params, double P);

// The profile w(x, m) of eq. 2 (both branches, any x).
double wave_curve(const WavinessParams& params, double x);

}  // namespace wavecontact
