// Benchmarks of the contact at a load (wavecontact/contact.hpp), with the FFT boundary-element
// oracle of tests/ as the baseline in the same run.
#include <benchmark/benchmark.h>

#include <cmath>
#include <vector>

#include "wavecontact/contact.hpp"
#include "wavecontact/two_scale.hpp"
#ifdef WAVECONTACT_BEM_BASELINE
#include "bem_oracle.hpp"  // tests/
#endif

namespace {

using namespace wavecontact;

constexpr double pi = 3.14159265358979323846;

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
BENCHMARK(BM_contact_multi_zone_n16)->Unit(benchmark::kMillisecond);

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
BENCHMARK(BM_contact_curve_200)->Arg(1)->Arg(0)->Unit(benchmark::kMillisecond);

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
BENCHMARK(BM_contact_bem_oracle)->Unit(benchmark::kMillisecond);
#endif

}  // namespace
