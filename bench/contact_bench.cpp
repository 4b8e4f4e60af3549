// Benchmarks of the contact at a load (wavecontact/contact.hpp), with the FFT boundary-element
// oracle of tests/ as the baseline in the same run.
#include <benchmark/benchmark.h>

#include <cmath>
#include <vector>

#include <boost/math/constants/constants.hpp>

#include "wavecontact/contact.hpp"
#include "wavecontact/two_scale.hpp"
#ifdef WAVECONTACT_BEM_BASELINE
#include "bem_oracle.hpp"  // tests/
#endif

namespace {

using namespace wavecontact;

using boost::math::double_constants::pi;

// The seed's Fig. 7 profile with n = 16 at pa/p* = 0.3: seven zones per period.
const TwoScaleParams rough16{{1.0, 10.0, 0.0, 1.0}, {0.15, 16}};
constexpr double multi_zone_load = 0.3 * pi;

void BM_contact_multi_zone_n16(benchmark::State& state) {
  const Surface surface(rough16);
  int zones = 0;
  double estimate = 0;
  for (auto _ : state) {
    const Contact c = solve_contact(surface, multi_zone_load, {1e-8, 0});
    zones = c.zones_per_period(), estimate = c.error_estimate();
    benchmark::DoNotOptimize(zones);
  }
  state.counters["zones"] = zones;
  state.counters["error_estimate"] = estimate;
}
BENCHMARK(BM_contact_multi_zone_n16)->UseRealTime()->Unit(benchmark::kMillisecond);

// A curve of 200 loads, pa/p* up to 0.6 (n = 8, up to six zones per period), by one
// continuation; and the wave curve m = 10 through snap-through to full contact.
void BM_contact_curve_200(benchmark::State& state) {
  const bool waviness = state.range(0) == 0;
  const Surface surface = waviness ? Surface(WavinessParams{1.0, 10.0, 10.0, 1.0})
                                   : Surface(TwoScaleParams{{1.0, 10.0, 0.0, 1.0}, {0.15, 8}});
  std::vector<double> loads;
  for (int i = 1; i <= 200; ++i) loads.push_back((waviness ? 4.5 : 0.6) * pi * i / 200);
  for (auto _ : state) benchmark::DoNotOptimize(solve_contact(surface, loads).back().contact_fraction());
  state.SetLabel(waviness ? "wave curve m = 10, pa/p* to 4.5" : "two-scale n = 8, pa/p* to 0.6");
}
BENCHMARK(BM_contact_curve_200)->Arg(1)->Arg(0)->UseRealTime()->Unit(benchmark::kMillisecond);

// A dense sweep of two roughness scales (n = 34 and 412) on the wave curve m = 3.74, whose
// zones change from load to load (campaign seed 11, sweep 76): 40 loads from pa/p* = 0.01 to
// full contact, each step a fifth of its load, so that each load may start from the loads
// before (Arg 1: one call); against the same loads solved one by one (Arg 0), each from the
// grid's seed.
void BM_contact_dense_sweep(benchmark::State& state) {
  const Surface surface(WavinessParams{1.0, 10.0, 3.7432525558204013, 1.0},
                        {{0.0010532608530750996, 412}, {0.022823156268234428, 34}});
  const double bottom = 0.01 * pi,
               top = 2 * pi * (1 + 3.7432525558204013 + 0.0010532608530750996 * 412 + 0.022823156268234428 * 34);
  std::vector<double> loads;
  for (int i = 0; i < 40; ++i) loads.push_back(bottom * std::pow(top / bottom, i / 39.0));
  const bool one_call = state.range(0) == 1;
  for (auto _ : state) {
    if (one_call) {
      benchmark::DoNotOptimize(solve_contact(surface, loads, {1e-8, 0}).back().contact_fraction());
    } else {
      for (double P : loads) benchmark::DoNotOptimize(solve_contact(surface, P, {1e-8, 0}).contact_fraction());
    }
  }
  state.SetLabel(one_call ? "one call" : "one call a load");
}
BENCHMARK(BM_contact_dense_sweep)->Arg(1)->Arg(0)->UseRealTime()->Unit(benchmark::kMillisecond);

// Two scales a decade apart, n = 6 and 64 (H2 = 0.15, 0.01), at P = 5.3 (pa/p* = 1.69, eight
// zones per period, near full contact): 36 s with the several-interval solver.
void BM_contact_two_scales_6_64(benchmark::State& state) {
  const Surface surface(WavinessParams{1.0, 10.0, 0.0, 1.0}, {{0.15, 6}, {0.01, 64}});
  Contact c = solve_contact(surface, 5.3, {1e-8, 0});
  for (auto _ : state) {
    c = solve_contact(surface, 5.3, {1e-8, 0});
    benchmark::DoNotOptimize(c.contact_fraction());
  }
  state.counters["zones"] = c.zones_per_period();
  state.counters["error_estimate"] = c.error_estimate();
}
BENCHMARK(BM_contact_two_scales_6_64)->UseRealTime()->Unit(benchmark::kMillisecond);

#ifdef WAVECONTACT_BEM_BASELINE
// The oracle on the same contact: three grids (4096, 8192, 16384 points) and Richardson
// extrapolation, which reach p(0) to about 1e-5 and the zone ends to about 1e-5 of the period:
// far less accurate than the solver at 1e-8, so the ratio understates the difference.
void BM_contact_bem_oracle(benchmark::State& state) {
  const auto y = [](double x) { return std::cos(x) + 0.15 * std::cos(16 * x); };
  test::BemEstimate e{};
  for (auto _ : state) {
    e = test::bem_extrapolated(y, 1.0, multi_zone_load, 4096);
    benchmark::ClobberMemory();
  }
  const Contact c = solve_contact(Surface(rough16), multi_zone_load, {1e-8, 0});
  state.counters["p0_error"] = std::fabs(e.p0 - c.pressure(0) * 10 / pi);  // normalised p^
  state.counters["p0_error_estimate"] = e.p0_error;
}
BENCHMARK(BM_contact_bem_oracle)->UseRealTime()->Unit(benchmark::kMillisecond);
#endif

}  // namespace

// The six many-zone cases of tests/contact_many_zones_test.cpp, side by side with the
// boundary-element method (Polonsky-Keer CG on an FFT grid) on the coarsest grid 2^k whose
// contact fraction lies within 1e-4 of the finest's (2^18 points), chosen before the timing.
// Counters: zones, the solver's error estimate, the grid and the grid's p(0) error against
// the solver (normalised p^).
namespace many_zones {

using namespace wavecontact;

struct Case {
  const char* name;
  double m;
  std::vector<Harmonic> harmonics;
  double P;  // per period; the same number in the oracle's normalised units
};

const std::vector<Case>& cases() {
  static const std::vector<Case> all{
      {"four scales to n = 256, P = 1", 0, {{0.1, 4}, {0.05, 16}, {0.025, 64}, {0.0125, 256}}, 1.0},
      {"four scales to n = 256, P = 2", 0, {{0.1, 4}, {0.05, 16}, {0.025, 64}, {0.0125, 256}}, 2.0},
      {"m = 10, n = 128, pa/p* = 1", 10, {{0.03, 128}}, pi},
      {"m = 10, n = 128, pa/p* = 2", 10, {{0.03, 128}}, 2 * pi},
      {"n = 256, H2 = 0.15, pa/p* = 0.2", 0, {{0.15, 256}}, 0.2 * pi},
      {"n = 1024, H2 = 0.05, pa/p* = 4", 0, {{0.05, 1024}}, 4 * pi},
  };
  return all;
}

Surface surface_of(const Case& k) { return Surface(WavinessParams{1.0, 10.0, k.m, 1.0}, k.harmonics); }

void BM_contact_many_zones(benchmark::State& state) {
  const Case& k = cases()[static_cast<std::size_t>(state.range(0))];
  const Surface surface = surface_of(k);
  Contact c = solve_contact(surface, k.P, {1e-8, 0});
  for (auto _ : state) {
    c = solve_contact(surface, k.P, {1e-8, 0});
    benchmark::DoNotOptimize(c.contact_fraction());
  }
  state.counters["zones"] = c.zones_per_period();
  state.counters["error_estimate"] = c.error_estimate();
  state.SetLabel(k.name);
}
BENCHMARK(BM_contact_many_zones)->DenseRange(0, 5)->UseRealTime()->Unit(benchmark::kMillisecond);

#ifdef WAVECONTACT_BEM_BASELINE
void BM_contact_many_zones_bem(benchmark::State& state) {
  const Case& k = cases()[static_cast<std::size_t>(state.range(0))];
  const auto y = [&k](double x) {
    const double c = std::cos(x);
    double v = (k.m + 1) * c / (k.m * std::fabs(c) + 1);
    for (const Harmonic& h : k.harmonics) v += h.H * std::cos(h.n * x);
    return v;
  };
  const std::vector<double> kinks = k.m > 0 ? std::vector<double>{pi / 2} : std::vector<double>{};
  constexpr int finest = 1 << 18;
  const double reference = test::bem_contact(y, 1.0, k.P, finest, kinks).contact_fraction;
  int grid = 1024;
  while (grid < finest && std::fabs(test::bem_contact(y, 1.0, k.P, grid, kinks).contact_fraction - reference) > 1e-4)
    grid *= 2;
  test::BemContact b{};
  for (auto _ : state) {
    b = test::bem_contact(y, 1.0, k.P, grid, kinks);
    benchmark::ClobberMemory();
  }
  const Contact c = solve_contact(surface_of(k), k.P, {1e-8, 0});
  state.counters["grid"] = grid;
  state.counters["p0_error"] = std::fabs(b.p0 - c.pressure(0) * 10 / pi) / b.p0;
  state.counters["fraction_error"] = std::fabs(b.contact_fraction - c.contact_fraction());
  state.SetLabel(k.name);
}
BENCHMARK(BM_contact_many_zones_bem)
    ->DenseRange(0, 5)
    ->UseRealTime()
    ->Unit(benchmark::kMillisecond)
    ->Iterations(1)
    ->Repetitions(3);
#endif

}  // namespace many_zones
