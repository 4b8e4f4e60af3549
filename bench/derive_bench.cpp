// The derivation of a user profile against its order: one harmonic H cos(k x), a power
// H cos(x)^k and a pole 1/(2 + cos x)^k (up to 32, the bound of a denominator). "Now":
// wavecontact-derive --profile end to end (the cosine sum split off in the Legendre-Dirichlet
// form, derive/profile/harmonic_part.hpp, then the header and manifest written). "Whole": the
// closed forms alone of the same profile through the engine's partial fractions, as the
// engine derived every profile before the split (orders up to 32; it grows like the fourth
// power of the order). scripts/bench.sh prints the table of docs/performance.md.
#include <string>
#include <utility>
#include <vector>

#include <benchmark/benchmark.h>

#include "core/symbols.hpp"
#include "emit/file_contents.hpp"
#include "engine/closed_forms.hpp"
#include "formulas/user_profile.hpp"
#include "profile/block_keer.hpp"

namespace {

namespace derive = wavecontact::derive;

void derive_profile_file(benchmark::State& state, const std::string& expression,
                         std::vector<derive::ProfileParameter> parameters = {{"H", 1}}) {
  const derive::ProfileSpec spec{"p", expression, std::move(parameters)};
  for (auto _ : state) benchmark::DoNotOptimize(derive::generate_profile(spec, "bench"));
}

const GiNaC::realsymbol& H() {
  static const GiNaC::realsymbol symbol("H");
  return symbol;
}

void derive_whole(benchmark::State& state, const GiNaC::ex& y) {
  GiNaC::exmap sample = derive::sample_point_v();
  sample[H()] = 1;
  for (auto _ : state) {
    benchmark::DoNotOptimize(derive::derive_closed_forms(y, {{}, derive::in_cosine(y)}, sample));
  }
}

void BM_derive_profile_harmonic(benchmark::State& state) {
  derive_profile_file(state, "H*cos(" + std::to_string(state.range(0)) + "*x)");
}
BENCHMARK(BM_derive_profile_harmonic)->RangeMultiplier(2)->Range(8, 256)->Unit(benchmark::kMillisecond)->Iterations(1);

void BM_derive_profile_power(benchmark::State& state) {
  derive_profile_file(state, "H*cos(x)^" + std::to_string(state.range(0)));
}
BENCHMARK(BM_derive_profile_power)->RangeMultiplier(2)->Range(8, 256)->Unit(benchmark::kMillisecond)->Iterations(1);

void BM_derive_profile_pole(benchmark::State& state) {
  derive_profile_file(state, "1/(2+cos(x))^" + std::to_string(state.range(0)), {});
}
BENCHMARK(BM_derive_profile_pole)->RangeMultiplier(2)->Range(8, 32)->Unit(benchmark::kMillisecond)->Iterations(1);

void BM_derive_whole_harmonic(benchmark::State& state) {
  derive_whole(state, H() * GiNaC::cos(state.range(0) * derive::sym::x()));
}
BENCHMARK(BM_derive_whole_harmonic)->RangeMultiplier(2)->Range(8, 32)->Unit(benchmark::kMillisecond)->Iterations(1);

void BM_derive_whole_power(benchmark::State& state) {
  derive_whole(state, H() * GiNaC::pow(GiNaC::cos(derive::sym::x()), state.range(0)));
}
BENCHMARK(BM_derive_whole_power)->RangeMultiplier(2)->Range(8, 32)->Unit(benchmark::kMillisecond)->Iterations(1);

}  // namespace
