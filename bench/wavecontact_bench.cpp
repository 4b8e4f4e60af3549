// Benchmarks with their baselines in the same run, so that ratios are meaningful on a
// shared machine (scripts/bench.sh prints them). Issue: performance.
#include <benchmark/benchmark.h>

#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <string>
#include <vector>

#include <Eigen/Core>
#include <boost/math/constants/constants.hpp>

#include "emit/file_contents.hpp"  // derive/
#include "formulas/roughness.hpp"  // derive/
#include "kinked_reference.hpp"    // tests/
#include "bench_inputs.hpp"
#include "plain_kernel.hpp"
#include "wavecontact/angles.hpp"
#include "wavecontact/isa.hpp"
#include "wavecontact/numerical_inversion.hpp"
#include "wavecontact/stability.hpp"
#include "wavecontact/threads.hpp"
#include "wavecontact/two_scale.hpp"
#include "wavecontact/waviness.hpp"
#include "wavecontact/generated/waviness_evaluators.hpp"
#include "waviness_csrc.hpp"

namespace {

using namespace wavecontact;

using bench::half_width;
using bench::waviness;
using bench::zone_points;
using boost::math::double_constants::pi;

// G(x^) = -(E/2) y'(x^) of the waviness, written from eq. 2 (as in the tests).
double waviness_rhs(double v) {
  const double x = 2 * std::atan(v), d = waviness.m * std::cos(x) + 1;
  return waviness.E * waviness.H1 / 2 * (waviness.m + 1) * std::sin(x) / (d * d);
}

// The smallest node count (doubling) at which the numerical inversion agrees with the
// closed form to `tolerance` (relative to scale) at 16 points: equal accuracy.
template <typename Rhs, typename Closed>
int nodes_for_accuracy(const Rhs& rhs, const Closed& closed, double a, double b1, double scale, double tolerance) {
  const double alpha = std::tan(pi * a / (2 * b1));
  for (int nodes = 8;; nodes *= 2) {
    double worst = 0;
    for (int i = 0; i < 16; ++i) {
      const double x = a * i / 16.0, u = std::tan(pi * x / (2 * b1));
      worst = std::max(worst, std::abs(pi / b1 * numerical_inversion(rhs, alpha, u, nodes) - closed(x)));
    }
    if (worst <= tolerance * scale || nodes > (1 << 20)) return nodes;
  }
}

// One thread (as every baseline here); BM_waviness_pressure_threads for more.
void BM_waviness_pressure_generated(benchmark::State& state) {
  const Eigen::ArrayXd xs = zone_points(state.range(0), half_width);
  Eigen::ArrayXd p(xs.size());  // the caller's buffer: no allocation in the loop
  set_array_kernel_threads(1);
  for (auto _ : state) {
    pressure(waviness, half_width, xs, p);
    benchmark::DoNotOptimize(p.data());
  }
  set_array_kernel_threads(0);
  state.SetItemsProcessed(state.iterations() * xs.size());
  state.SetLabel(isa_name(array_kernel_isa()));
}
BENCHMARK(BM_waviness_pressure_generated)->Arg(1000000)->Unit(benchmark::kMillisecond);

// The same 10^6 points on 1, 2, ... threads (wavecontact/threads.hpp).
void BM_waviness_pressure_threads(benchmark::State& state) {
  const Eigen::ArrayXd xs = zone_points(1000000, half_width);
  Eigen::ArrayXd p(xs.size());
  set_array_kernel_threads(static_cast<int>(state.range(0)));
  for (auto _ : state) {
    pressure(waviness, half_width, xs, p);
    benchmark::DoNotOptimize(p.data());
  }
  set_array_kernel_threads(0);
  state.SetItemsProcessed(state.iterations() * xs.size());
}
BENCHMARK(BM_waviness_pressure_threads)->Arg(1)->Arg(2)->UseRealTime()->Unit(benchmark::kMillisecond);

// The same generated formula, its atoms from scalar libm sin/cos, into the same buffer:
// the "scalar libm" baseline for the vectorised kernel.
void BM_waviness_pressure_scalar_libm(benchmark::State& state) {
  const Eigen::ArrayXd xs = zone_points(state.range(0), half_width);
  const ZoneAngles zone = zone_angles(half_width, waviness.b1);
  const double a = half_width, b1 = waviness.b1;
  Eigen::ArrayXd p(xs.size());
  for (auto _ : state) {
    for (Eigen::Index i = 0; i < xs.size(); ++i) {
      const double r = std::fabs(xs[i]), half = std::sin(pi * r / (2 * b1));
      const double D = 2 * std::sin(pi * (a + r) / (2 * b1)) * std::sin(pi * (a - r) / (2 * b1));
      p[i] = r < a ? generated::waviness_pressure_exact(waviness.E, waviness.H1, b1, waviness.m, zone.Ca, zone.Sa,
                                                        std::cos(pi * r / b1), 2 * half * half, D)
                   : 0.0;
    }
    benchmark::DoNotOptimize(p.data());
  }
  state.SetItemsProcessed(state.iterations() * xs.size());
}
BENCHMARK(BM_waviness_pressure_scalar_libm)->Arg(1000000)->Unit(benchmark::kMillisecond);

// The plain fast-math kernel (plain_kernel.cpp) built for the path the array kernels take
// (array_kernel_isa(); scripts/bench.sh runs each path): the cost floor of the same formula.
void BM_waviness_pressure_plain_same_isa(benchmark::State& state) {
  const Isa isa = array_kernel_isa();
  const bench::PlainKernel plain = bench::plain_waviness_pressure(isa);
  const Eigen::ArrayXd xs = zone_points(state.range(0), half_width);
  Eigen::ArrayXd p(xs.size());
  for (auto _ : state) {
    plain(waviness.E, waviness.H1, waviness.b1, waviness.m, half_width, xs.data(), p.data(),
          static_cast<std::size_t>(xs.size()));
    benchmark::DoNotOptimize(p.data());
  }
  state.SetItemsProcessed(state.iterations() * xs.size());
  state.SetLabel(isa_name(isa));
}
BENCHMARK(BM_waviness_pressure_plain_same_isa)->Arg(1000000)->Unit(benchmark::kMillisecond);

void BM_waviness_pressure_no_cse(benchmark::State& state) {
  const Eigen::ArrayXd xs = zone_points(state.range(0), half_width);
  const ZoneAngles zone = zone_angles(half_width, waviness.b1);
  for (auto _ : state) {
    Eigen::ArrayXd p(xs.size());
    for (Eigen::Index i = 0; i < xs.size(); ++i) {
      const PointAngles point = point_angles(std::fabs(xs[i]), half_width, waviness.b1);
      p[i] = bench::waviness_pressure_csrc(waviness.E, waviness.H1, waviness.b1, waviness.m, zone.Ca, zone.Sa, point.Cx,
                                           point.Sx, point.D);
    }
    benchmark::DoNotOptimize(p.data());
  }
  state.SetItemsProcessed(state.iterations() * xs.size());
}
BENCHMARK(BM_waviness_pressure_no_cse)->Arg(1000000)->Unit(benchmark::kMillisecond);

void BM_waviness_pressure_numerical(benchmark::State& state) {
  const Eigen::ArrayXd xs = zone_points(state.range(0), half_width);
  const double alpha = std::tan(pi * half_width / (2 * waviness.b1));
  const double scale = pressure(waviness, half_width, 0.0);
  const int nodes = nodes_for_accuracy(
      waviness_rhs, [](double x) { return pressure(waviness, half_width, x); }, half_width, waviness.b1, scale,
      64 * 2.220446049250313e-16);
  for (auto _ : state) {
    double sum = 0;
    for (Eigen::Index i = 0; i < xs.size(); ++i) {
      sum += numerical_inversion(waviness_rhs, alpha, std::tan(pi * xs[i] / (2 * waviness.b1)), nodes);
    }
    benchmark::DoNotOptimize(sum);
  }
  state.counters["nodes"] = nodes;
  state.SetItemsProcessed(state.iterations() * xs.size());
}
BENCHMARK(BM_waviness_pressure_numerical)->Arg(10000)->Unit(benchmark::kMillisecond);

TwoScaleParams rough(int n) { return {waviness, {0.01 / n, n}}; }

// The array API: the zone's Legendre coefficients (generated) once, the series across
// blocks of points.
void BM_roughness_pressure_generated(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  const TwoScaleContact contact(rough(n), half_width);
  const Eigen::ArrayXd xs = zone_points(100000, half_width);
  Eigen::ArrayXd p(xs.size());
  set_array_kernel_threads(1);  // as the baselines
  for (auto _ : state) {
    contact.roughness_pressure(xs, p);
    benchmark::DoNotOptimize(p.data());
  }
  set_array_kernel_threads(0);
  state.SetItemsProcessed(state.iterations() * xs.size());
}
BENCHMARK(BM_roughness_pressure_generated)->Arg(16)->Arg(64)->Arg(256)->Unit(benchmark::kMillisecond);

// The point API: the generated roughness_n<N>_pressure, Legendre values included, per call.
void BM_roughness_pressure_point(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  const TwoScaleContact contact(rough(n), half_width);
  const Eigen::ArrayXd xs = zone_points(100000, half_width);
  for (auto _ : state) {
    double sum = 0;
    for (Eigen::Index i = 0; i < xs.size(); ++i) sum += contact.roughness_pressure(xs[i]);
    benchmark::DoNotOptimize(sum);
  }
  state.SetItemsProcessed(state.iterations() * xs.size());
}
BENCHMARK(BM_roughness_pressure_point)->Arg(16)->Arg(64)->Arg(256)->Unit(benchmark::kMillisecond);

void BM_roughness_pressure_numerical(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  const TwoScaleParams params = rough(n);
  const TwoScaleContact contact(params, half_width);
  const double H2 = params.roughness.H2, b1 = waviness.b1, E = waviness.E;
  const auto rhs = [&](double v) { return E / 2 * H2 * n * std::sin(n * 2 * std::atan(v)); };
  const double scale = E * H2 * n * pi / b1;
  // Equal accuracy: the generated evaluator is within 2e-13 of the scale up to n = 256.
  const int nodes = nodes_for_accuracy(
      rhs, [&](double x) { return contact.roughness_pressure(x); }, half_width, b1, scale, 2e-13);
  const double alpha = std::tan(pi * half_width / (2 * b1));
  const Eigen::ArrayXd xs = zone_points(1000, half_width);
  for (auto _ : state) {
    double sum = 0;
    for (Eigen::Index i = 0; i < xs.size(); ++i) {
      sum += numerical_inversion(rhs, alpha, std::tan(pi * xs[i] / (2 * b1)), nodes);
    }
    benchmark::DoNotOptimize(sum);
  }
  state.counters["nodes"] = nodes;
  state.SetItemsProcessed(state.iterations() * xs.size());
}
BENCHMARK(BM_roughness_pressure_numerical)->Arg(16)->Arg(64)->Arg(256)->Unit(benchmark::kMillisecond);

// P(a) for a sweeping [lo, hi) in steps of 0.01 (b1 = 10).
void load_sweep(benchmark::State& state, double lo, double hi) {
  double a = lo;
  for (auto _ : state) {
    benchmark::DoNotOptimize(load(waviness, a));
    a = a < hi ? a + 0.01 : lo;
  }
}

void BM_load(benchmark::State& state) { load_sweep(state, 0.5, 4.9); }
BENCHMARK(BM_load);

// Beyond b1/2: the sub-interval closed forms with I_{j,l}.
void BM_load_beyond_half(benchmark::State& state) { load_sweep(state, 5.01, 9.9); }
BENCHMARK(BM_load_beyond_half);

// The pressure beyond b1/2 (a = 0.75 b1, m = 2), in closed form (derive/formulas/beyond_branch.hpp): over
// the zone, and within 1e-2 to 1e-12 (relative) of the kink at x = b1/2, on both sides; and,
// for the ratio, the independent quadrature of eq. 12 that the tests take as the reference
// (tests/kinked_reference.hpp, long double).
std::vector<double> points_over_zone() {
  std::vector<double> xs;
  for (int i = 0; i < 100; ++i) xs.push_back(bench::half_width_beyond * (i + 0.5) / 100);
  return xs;
}

std::vector<double> points_near_kink() {
  std::vector<double> xs;
  for (int k = 2; k <= 12; ++k) {
    for (double side : {-1.0, 1.0}) xs.push_back(5 * (1 + side * std::pow(10.0, -k)));
  }
  return xs;
}

void pressure_points(benchmark::State& state, const std::vector<double>& xs, bool quadrature) {
  const double a = bench::half_width_beyond;
  for (auto _ : state) {
    double sum = 0;
    for (double x : xs) {
      sum += quadrature ? static_cast<double>(
                              wave_curve_reference_pressure(waviness.m, pi * a / waviness.b1, pi * x / waviness.b1))
                        : pressure(waviness, a, x);
    }
    benchmark::DoNotOptimize(sum);
  }
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(xs.size()));
}

void BM_pressure_beyond_half(benchmark::State& state) { pressure_points(state, points_over_zone(), false); }
BENCHMARK(BM_pressure_beyond_half);

void BM_pressure_beyond_half_near_kink(benchmark::State& state) { pressure_points(state, points_near_kink(), false); }
BENCHMARK(BM_pressure_beyond_half_near_kink);

// The same zone as an array of 10^4 points, on one thread: the zone's atoms once, the Cauchy
// part's atoms tabulated in log(1 + y) (runtime/src/closed_forms/cauchy_atom_table.hpp).
void BM_pressure_beyond_half_array(benchmark::State& state) {
  const Eigen::ArrayXd xs = zone_points(state.range(0), bench::half_width_beyond);
  Eigen::ArrayXd p(xs.size());
  set_array_kernel_threads(1);
  for (auto _ : state) {
    pressure(waviness, bench::half_width_beyond, xs, p);
    benchmark::DoNotOptimize(p.data());
  }
  set_array_kernel_threads(0);
  state.SetItemsProcessed(state.iterations() * xs.size());
}
BENCHMARK(BM_pressure_beyond_half_array)->Arg(10000)->Unit(benchmark::kMicrosecond);

void BM_pressure_beyond_half_quadrature(benchmark::State& state) { pressure_points(state, points_over_zone(), true); }
BENCHMARK(BM_pressure_beyond_half_quadrature)->Unit(benchmark::kMicrosecond);

void BM_pressure_beyond_half_near_kink_quadrature(benchmark::State& state) {
  pressure_points(state, points_near_kink(), true);
}
BENCHMARK(BM_pressure_beyond_half_near_kink_quadrature)->Unit(benchmark::kMicrosecond);

// a(P) in the single-asperity regime (a <= b1/2): the closed-form inverse.
void BM_single_asperity_half_width(benchmark::State& state) {
  double P = 0.05;
  for (auto _ : state) {
    benchmark::DoNotOptimize(single_asperity_half_width(waviness, P));
    P = P < 1.5 ? P + 0.01 : 0.05;
  }
}
BENCHMARK(BM_single_asperity_half_width);

// Every zone carrying P over 0 < a < b1, given the turning points of P(a) (LoadCurve).
void BM_equilibria(benchmark::State& state) {
  const LoadCurve curve(waviness);
  double P = 0.05;
  for (auto _ : state) {
    benchmark::DoNotOptimize(curve.equilibria(P));
    P = P < 1.5 ? P + 0.01 : 0.05;
  }
}
BENCHMARK(BM_equilibria)->Unit(benchmark::kMicrosecond);

// The turning points of P(a) over 0 < a <= b1.
void BM_load_curve(benchmark::State& state) {
  for (auto _ : state) benchmark::DoNotOptimize(LoadCurve(waviness));
}
BENCHMARK(BM_load_curve)->Unit(benchmark::kMillisecond);

void BM_pa_over_pstar_curve_1000(benchmark::State& state) {
  for (auto _ : state) {
    double sum = 0;
    for (int i = 1; i <= 1000; ++i) sum += pa_over_pstar(waviness, waviness.b1 / 2 * i / 1000);
    benchmark::DoNotOptimize(sum);
  }
}
BENCHMARK(BM_pa_over_pstar_curve_1000)->Unit(benchmark::kMicrosecond);

void BM_kcoefficients(benchmark::State& state) {
  for (auto _ : state) {
    benchmark::DoNotOptimize(derive::expansion_coefficients(static_cast<int>(state.range(0))));
  }
}
BENCHMARK(BM_kcoefficients)->Arg(64)->Arg(128)->Arg(256)->Arg(1024)->Unit(benchmark::kMillisecond);

void BM_regenerate_default(benchmark::State& state) {
  for (auto _ : state) benchmark::DoNotOptimize(derive::generate_all());
}
BENCHMARK(BM_regenerate_default)->Iterations(1)->Unit(benchmark::kSecond);

// The user's alternative: SymPy doing the same expansion (bench/sympy_kcoef.py).
void BM_sympy_kcoefficients(benchmark::State& state) {
  const std::string command =
      "python3 " WAVECONTACT_SYMPY_BASELINE " " + std::to_string(state.range(0)) + " > /dev/null 2>&1";
  for (auto _ : state) {
    const auto start = std::chrono::steady_clock::now();
    if (std::system(command.c_str()) != 0) {
      state.SkipWithError("python3 with sympy is not available");
      break;
    }
    state.SetIterationTime(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  }
}
BENCHMARK(BM_sympy_kcoefficients)->Arg(128)->UseManualTime()->Iterations(1)->Unit(benchmark::kMillisecond);

}  // namespace
