// One call at a time, as loops and optimisers call (issue: performance like with like): one
// point by the free function and by a WavinessZone (wavecontact/waviness_zone.hpp), within
// b1/2 and beyond it, and ten points as an array. Each figure is ns a call over 100 points.
#include <benchmark/benchmark.h>

#include <Eigen/Core>

#include "bench_inputs.hpp"
#include "wavecontact/waviness.hpp"
#include "wavecontact/waviness_zone.hpp"

namespace {

using namespace wavecontact;
using bench::waviness;

double zone_width(bool beyond_half) { return beyond_half ? bench::half_width_beyond : bench::half_width; }

// The free function pressure(params, a, x): validation, the zone's angles and the point's.
void BM_point_free_function(benchmark::State& state) {
  const double a = zone_width(state.range(0) != 0);
  const Eigen::ArrayXd xs = bench::zone_points(100, a);
  for (auto _ : state) {
    double sum = 0;
    for (double x : xs) sum += pressure(waviness, a, x);
    benchmark::DoNotOptimize(sum);
  }
  state.SetItemsProcessed(state.iterations() * xs.size());
}
BENCHMARK(BM_point_free_function)->Arg(0)->Arg(1);

// The same through one zone made beforehand: the point's own terms only.
void BM_point_zone(benchmark::State& state) {
  const double a = zone_width(state.range(0) != 0);
  const WavinessZone zone(waviness, a);
  const Eigen::ArrayXd xs = bench::zone_points(100, a);
  for (auto _ : state) {
    double sum = 0;
    for (double x : xs) sum += zone.pressure(x);
    benchmark::DoNotOptimize(sum);
  }
  state.SetItemsProcessed(state.iterations() * xs.size());
}
BENCHMARK(BM_point_zone)->Arg(0)->Arg(1);

// Ten points as an array through the zone, into the caller's buffer: ns a call.
void BM_ten_points_zone(benchmark::State& state) {
  const WavinessZone zone(waviness, bench::half_width);
  const Eigen::ArrayXd xs = bench::zone_points(10, bench::half_width);
  Eigen::ArrayXd p(xs.size());
  for (auto _ : state) {
    zone.pressure(xs, p);
    benchmark::DoNotOptimize(p.data());
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_ten_points_zone);

}  // namespace
