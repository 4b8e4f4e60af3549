// The derivation of a user profile against its order (wavecontact-derive --profile): one
// harmonic H cos(k x) and a power H cos(x)^k, the whole chain (g, inversion, load, angle
// forms, emitted header). scripts/bench.sh prints the table of the README.
#include <string>

#include <benchmark/benchmark.h>

#include "generate.hpp"
#include "user_profile.hpp"

namespace {

void derive_profile_file(benchmark::State& state, const std::string& expression) {
  const wavecontact::derive::ProfileSpec spec{"p", expression, {{"H", 1}}};
  for (auto _ : state) {
    benchmark::DoNotOptimize(wavecontact::derive::generate_profile(spec, "bench"));
  }
}

void BM_derive_profile_harmonic(benchmark::State& state) {
  derive_profile_file(state, "H*cos(" + std::to_string(state.range(0)) + "*x)");
}
BENCHMARK(BM_derive_profile_harmonic)->DenseRange(8, 32, 8)->Unit(benchmark::kMillisecond)
    ->Iterations(1);

void BM_derive_profile_power(benchmark::State& state) {
  derive_profile_file(state, "H*cos(x)^" + std::to_string(state.range(0)));
}
BENCHMARK(BM_derive_profile_power)->DenseRange(8, 32, 8)->Unit(benchmark::kMillisecond)
    ->Iterations(1);

}  // namespace
