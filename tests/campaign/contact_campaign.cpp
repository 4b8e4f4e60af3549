// A seeded random campaign of load sweeps: surfaces of the wave curve (m = 0 a quarter of the
// time, else uniform in [0, --most-m], 35 by default) with 1 to
// --harmonics roughness harmonics (even n up to --max-n, slopes H n from 0.1 to 20, H <= 0.2), each swept
// by one solve_contact call over --loads loads from pa/p* = 0.01 to beyond full contact. Every
// contact returned is checked on the whole period, independently of the solver's own
// verification: p >= 0 on its zones and gap >= 0 off them (to 1e-7 of the largest pressure
// and of the height range), sampled 16 times a shortest wavelength. A sweep that throws is a
// stall; one whose estimate misses the tolerance is reported apart.
//
//   contact_campaign --seed S --sweeps N [--max-n 1024] [--loads 8] [--tolerance 1e-8]
//                    [--harmonics 4] [--first K] [--most-m 35]
// prints one line a sweep and a summary; exits 0 only with no stall and no violation.
#include <chrono>
#include <cmath>
#include <cstdio>
#include <exception>
#include <random>
#include <string>
#include <vector>

#include "wavecontact/contact.hpp"
#include "wavecontact/errors.hpp"

namespace {

constexpr double b1 = 10, H1 = 1, E = 1;

struct Settings {
  unsigned seed = 1;
  int sweeps = 10, first = 0, max_n = 1024, loads = 8, harmonics = 4;
  double tolerance = 1e-8, most_m = 35;
};

struct Sweep {
  double m;
  std::vector<wavecontact::Harmonic> harmonics;
  std::vector<double> loads;
};

// Sweep k of the campaign: its own generator, so that any sweep can be rerun alone.
Sweep draw(const Settings& s, int k) {
  std::mt19937_64 random(s.seed * 1000003ULL + static_cast<unsigned long long>(k));
  std::uniform_real_distribution<double> unit(0, 1);
  Sweep w;
  w.m = unit(random) < 0.25 ? 0 : s.most_m * unit(random);
  // No more harmonics than there are even n up to max_n (--max-n 4 drew three of n = 2 and 4,
  // and searched for the third for ever).
  const int count = std::min(1 + static_cast<int>(s.harmonics * unit(random)), s.max_n / 2);
  double slopes = 0;
  while (static_cast<int>(w.harmonics.size()) < count) {
    const int n = 2 * static_cast<int>(std::lround(std::exp(unit(random) * std::log(s.max_n / 2.0))));
    bool taken = false;
    for (const wavecontact::Harmonic& h : w.harmonics) taken = taken || h.n == n;
    if (taken || n < 2) continue;
    const double slope = std::exp(std::log(0.1) + unit(random) * std::log(200.0));
    const double H = std::min(0.2, slope / n);
    w.harmonics.push_back({H, n});
    slopes += H * n;
  }
  // From pa/p* = 0.01 (p* = pi E* H1) to beyond full contact: a sine's is at pa/p* = 2, a
  // flat punch's (large m) about 1 + m times that, and each harmonic adds its slope's share.
  const double pstar_load = M_PI * E * H1;
  const double bottom = 0.01 * pstar_load, top = 2 * pstar_load * (1 + w.m + slopes / H1);
  for (int i = 0; i < s.loads; ++i)
    w.loads.push_back(bottom * std::pow(top / bottom, static_cast<double>(i) / (s.loads - 1)));
  return w;
}

// The worst violation of p >= 0 and gap >= 0 over the period (relative), and where.
std::pair<double, double> violation(const wavecontact::Contact& c, double height_range, int max_n) {
  const int samples = 16 * max_n;
  double worst = 0, at = 0;
  const double p_scale = c.max_pressure();
  for (int i = 0; i <= samples; ++i) {
    const double x = b1 * i / samples;
    const double p = c.pressure(x), g = c.gap(x);
    const double v = std::max(-p / p_scale, -g / height_range);
    if (v > worst) worst = v, at = x;
  }
  return {worst, at};
}

}  // namespace

int main(int argc, char** argv) {
  Settings s;
  for (int i = 1; i + 1 < argc; i += 2) {
    const std::string key = argv[i], value = argv[i + 1];
    if (key == "--seed")
      s.seed = static_cast<unsigned>(std::stoul(value));
    else if (key == "--sweeps")
      s.sweeps = std::stoi(value);
    else if (key == "--first")
      s.first = std::stoi(value);
    else if (key == "--max-n")
      s.max_n = std::stoi(value);
    else if (key == "--loads")
      s.loads = std::stoi(value);
    else if (key == "--tolerance")
      s.tolerance = std::stod(value);
    else if (key == "--harmonics")
      s.harmonics = std::stoi(value);
    else if (key == "--most-m")
      s.most_m = std::stod(value);
    else {
      std::fprintf(stderr, "contact_campaign: unknown option %s\n", key.c_str());
      return 2;
    }
  }
  if (s.max_n < 2 || s.loads < 2) {
    std::fprintf(stderr, "contact_campaign: --max-n %d and --loads %d must be at least 2\n", s.max_n, s.loads);
    return 2;
  }
  if (!(s.most_m >= 0)) {
    std::fprintf(stderr, "contact_campaign: --most-m %g must be at least 0\n", s.most_m);
    return 2;
  }
  if (s.harmonics < 1 || s.harmonics > static_cast<int>(wavecontact::max_harmonics)) {
    std::fprintf(stderr, "contact_campaign: --harmonics %d must be from 1 to %zu\n", s.harmonics,
                 wavecontact::max_harmonics);
    return 2;
  }
  int stalls = 0, violations = 0, missed = 0, contacts = 0, most_zones = 0;
  double slowest = 0, total = 0;
  for (int k = s.first; k < s.first + s.sweeps; ++k) {
    const Sweep w = draw(s, k);
    // Every digit, so that a sweep reruns exactly through the CLI (--m, --H2, --n).
    const auto digits = [](double v) {
      char text[32];
      std::snprintf(text, sizeof text, "%.17g", v);
      return std::string(text);
    };
    std::string surface = "m " + digits(w.m);
    double range = 2 * H1;
    int highest = 1;
    for (const wavecontact::Harmonic& h : w.harmonics) {
      surface += " " + digits(h.H) + ":" + std::to_string(h.n), range += 2 * h.H;
      highest = std::max(highest, h.n);
    }
    const auto start = std::chrono::steady_clock::now();
    try {
      const std::vector<wavecontact::Contact> sweep =
          wavecontact::solve_contact(wavecontact::Surface(wavecontact::WavinessParams{H1, b1, w.m, E}, w.harmonics),
                                     w.loads, wavecontact::SolverOptions(s.tolerance));
      const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      slowest = std::max(slowest, seconds), total += seconds;
      int zones = 0, bad = 0;
      double estimate = 0;  // the largest of the sweep
      const bool full = sweep.back().full_contact();
      for (const wavecontact::Contact& c : sweep) {
        ++contacts;
        zones = std::max(zones, c.zones_per_period());
        estimate = std::max(estimate, c.error_estimate());
        if (c.error_estimate() > s.tolerance) ++missed;
        const auto [worst, at] = violation(c, range, highest);
        if (worst > 1e-7) {
          ++bad;
          std::printf("sweep %d: VIOLATION %.3g at x = %.9g, P = %.9g (%s)\n", k, worst, at, c.load(), surface.c_str());
        }
      }
      violations += bad;
      most_zones = std::max(most_zones, zones);
      std::printf("sweep %d: %s, %zu loads, up to %d zones%s, estimates up to %.1e, %.2f s%s\n", k, surface.c_str(),
                  w.loads.size(), zones, full ? ", full contact at the last" : "", estimate, seconds,
                  bad ? ", VIOLATED" : "");
    } catch (const std::exception& e) {
      ++stalls;
      const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      total += seconds;
      std::printf("sweep %d: STALL after %.2f s (%s): %s\n", k, seconds, surface.c_str(), e.what());
    }
    std::fflush(stdout);
  }
  std::printf(
      "campaign seed %u, sweeps %d..%d: %d stalls, %d violations, %d of %d contacts above the tolerance, "
      "up to %d zones, %.1f s in all, slowest sweep %.2f s\n",
      s.seed, s.first, s.first + s.sweeps - 1, stalls, violations, missed, contacts, most_zones, total, slowest);
  return stalls == 0 && violations == 0 ? 0 : 1;
}
