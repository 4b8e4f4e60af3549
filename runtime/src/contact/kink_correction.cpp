#include "kink_correction.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <mutex>

#include "chebyshev.hpp"
#include "constants.hpp"
#include "log_end_quadrature.hpp"
#include "support/parallel.hpp"

namespace wavecontact::detail {

namespace {

// W(u) = (1 - v)^K sum_{i<L} C(K + i - 1, i) v^i, v = u^2: 1 - O(u^(2 L)) at 0 (the truncated
// series of (1 - v)^-K), zero to order K at |u| = 1, a polynomial of degree 2 (K + L - 1)
// falling monotonically (a regularised incomplete beta function).
constexpr int window_flatness = 5;
// The order K: steep_order for a window of radius steep_from or more (in s), gentle_order
// below. The rest of the density, C^(K-1) at the window's edges, converges like N^-K: with
// K = 8 alone (until 2026-11-29) a zone across the kink on m = 5.1, n = 24 erred by 7e-7 on
// 512 nodes, with K = 20 by 8e-9 (K = 24 did as well, 12 and 16 less). A steep window needs
// nodes for its own shape, though: one of radius r next to a zone's end (extent at most 2 in
// s) holds about (N / pi) sqrt(2.1 r) of the zone's N nodes, at the most working nodes 33 for
// r = 3e-4, and narrower steep windows (2.3e-5 and 5.9e-5 at ends just past the kink:
// campaign seeds 23 and 25 with --max-n 8 and 32) left a spurious tension at the end, cut
// and back until the changes ran out, where the gentle window settles.
constexpr int steep_order = 20, gentle_order = 8;
constexpr double steep_from = 3e-4;
constexpr double least_inside = 1e-6;  // of the zone's extent in s: nearer an end, its effect is below rounding
constexpr int most_piece_nodes = 257;
// A piece's interpolant also stops where its tail stays at the values' own noise: once below
// this (of the largest value) and no longer falling by a factor of 8 a doubling. Near a small
// window's kink the slope jump (a difference of the branches) and the quadrature leave noise
// of about 1e-13 of the values; 1e-15 was never reached there, and every piece near the kink
// went to most_piece_nodes, each node a quadrature (the 200 loads of the wave curve m = 10
// spent 2.7 s of 7.4 building eleven windows, 0.7 s for the smallest).
constexpr double piece_noise = 1e-12;
// Beyond twice the radius from the kink, the potential is its expansion in the moments of the
// window, (r / (s - s0))^k / k falling at least like 2^-k: 56 terms reach 1e-17.
constexpr int multipole_terms = 56;

double window(double u, int order) {
  if (!(std::fabs(u) < 1)) return 0;
  const double v = u * u;
  double term = 1, sum = 1;
  for (int i = 1; i < window_flatness; ++i) {
    term *= v * (order + i - 1) / i;
    sum += term;
  }
  return std::pow(1 - v, order) * sum;
}

}  // namespace

// The windows of one kink, by radius.
struct KinkWindows {
  std::mutex mutex;
  std::map<double, std::shared_ptr<const KinkCorrection>> windows;
};

std::shared_ptr<KinkWindows> make_kink_windows() { return std::make_shared<KinkWindows>(); }

std::shared_ptr<KinkWindows> shared_kink_windows(const std::vector<double>& key) {
  // A map's load lines at one shape m and many roughnesses build each window once instead of
  // once a line (the 10^4 points of bench/map_vs_loops.py at m = 10: 3.24 -> 2.61 s, the same
  // rows), as long as its shapes are at most this many: a map takes its lines roughness by
  // roughness. A window holds about 10 KB (m = 10: 22 to 32 pieces, 600 to 1200 coefficients).
  constexpr std::size_t kept_kinks = 32;
  static std::mutex mutex;
  static std::vector<std::pair<std::vector<double>, std::shared_ptr<KinkWindows>>> recent;  // the newest last
  const std::lock_guard<std::mutex> lock(mutex);
  const auto found = std::find_if(recent.begin(), recent.end(), [&](const auto& entry) { return entry.first == key; });
  std::shared_ptr<KinkWindows> windows;
  if (found != recent.end()) {
    windows = std::move(found->second);
    recent.erase(found);
  } else {
    windows = make_kink_windows();
    if (recent.size() == kept_kinks) recent.erase(recent.begin());
  }
  recent.emplace_back(key, windows);
  return windows;
}

KinkCorrection::KinkCorrection(const Kink& kink, double r)
    : s0_(kink.s), slope_jump_(kink.slope_jump), r_(r), order_(r >= steep_from ? steep_order : gentle_order) {
  const double s0 = kink.s;
  // nu_k = Int q_k(t) ((t - s0) / r)^k dt, the moments of the far field. The moments, then the
  // pieces, are each computed alone, on the threads: a window is most of a single solve's time
  // on a surface with a kink (at m = 2, n = 16, pa/p* = 1: 57 % of 50 ms).
  moments_.resize(multipole_terms + 1);
  for_each_index(moments_.size(), 2, [&](std::size_t k) {
    const auto moment = [&](double t) { return density(t) * std::pow((t - s0) / r, static_cast<int>(k)); };
    moments_[k] = log_end_integral(moment, s0 - r, s0) + log_end_integral(moment, s0, s0 + r);
  });
  load_ = moments_[0];
  // The potential on pieces between -1 and 1 graded geometrically towards s0 (where it goes
  // like (s - s0)^2 log|s - s0|) and away from the window's edges s0 -+ r (where it is only
  // C^(K-1)): each piece then holds a function smooth on its own scale, which a few tens of
  // Chebyshev coefficients represent (a piece spanning the scales needed hundreds, and each
  // node of a zone across the kink evaluates one). Interpolants at the extrema cos(pi i / n)
  // of T_n, n doubling (each doubling reuses the values it has) until the last coefficients
  // are below 1e-15 of the largest value, or stay at the values' noise (piece_noise).
  std::vector<double> cuts{-1.0, 1.0, s0};
  for (double d = r; d > r * 0x1p-6; d /= 2) cuts.push_back(s0 - d), cuts.push_back(s0 + d);
  for (double d = 2 * r; d < 2; d *= 2) cuts.push_back(s0 - d), cuts.push_back(s0 + d);
  for (double& c : cuts) c = std::clamp(c, -1.0, 1.0);
  std::sort(cuts.begin(), cuts.end());
  cuts.erase(std::unique(cuts.begin(), cuts.end()), cuts.end());
  pieces_.resize(cuts.size() - 1);
  for_each_index(pieces_.size(), 2, [&](std::size_t i) {
    const double lo = cuts[i], hi = cuts[i + 1];
    Piece& piece = pieces_[i];
    piece = {lo, hi, {}};
    std::vector<double> values;  // at cos(pi i / n), i = 0 .. n
    double previous_tail = std::numeric_limits<double>::infinity();
    for (int n = 16;; n *= 2) {
      std::vector<double> next(static_cast<std::size_t>(n) + 1);
      for (int k = 0; k <= n; ++k) {
        if (!values.empty() && k % 2 == 0) {
          next[static_cast<std::size_t>(k)] = values[static_cast<std::size_t>(k / 2)];
        } else {
          next[static_cast<std::size_t>(k)] = direct_potential((lo + hi) / 2 + (hi - lo) / 2 * std::cos(pi * k / n));
        }
      }
      values = std::move(next);
      piece.coefficients = chebyshev::extrema_coefficients(values);
      double largest = 0;
      for (double v : values) largest = std::max(largest, std::fabs(v));
      const std::size_t m = piece.coefficients.size();
      const double tail = std::fabs(piece.coefficients[m - 1]) + std::fabs(piece.coefficients[m - 2]);
      const double scale = std::max(largest, 1e-300);
      const bool at_noise = tail <= piece_noise * scale && tail > previous_tail / 8;
      if (tail <= 1e-15 * scale || at_noise || n + 1 >= most_piece_nodes) break;
      previous_tail = tail;
    }
  });
}

namespace {

// The kink well inside the zone (room: its distance in s from the nearer end), if any.
const Kink* kink_inside(const SurfaceModel& surface, const ZoneGeometry& zone, double& room) {
  for (const Kink& kink : surface.kinks) {
    if (!(kink.angle > zone.a && kink.angle < zone.b)) continue;
    const double upper = std::cos(zone.a), lower = std::cos(zone.b);  // s of the ends
    room = std::min(upper - kink.s, kink.s - lower);
    return room < least_inside * (upper - lower) ? nullptr : &kink;
  }
  return nullptr;
}

}  // namespace

double KinkCorrection::radius_for(const SurfaceModel& surface, const ZoneGeometry& zone) {
  double room = 0;
  const Kink* kink = kink_inside(surface, zone, room);
  if (!kink) return 0;
  double r = 0.5 * kink->radius;  // few windows, each computed once
  while (r > 0.9 * room) r *= 0.5;
  return r;
}

bool KinkCorrection::fits(const SurfaceModel& surface, const ZoneGeometry& zone, double r) {
  double room = 0;
  const Kink* kink = kink_inside(surface, zone, room);
  return kink ? r > 0 && r <= room : r == 0;
}

std::shared_ptr<const KinkCorrection> KinkCorrection::of(const SurfaceModel& surface, const ZoneGeometry& zone,
                                                         double r) {
  if (r == 0) return nullptr;
  for (const Kink& kink : surface.kinks) {
    if (!(kink.angle > zone.a && kink.angle < zone.b)) continue;
    const std::lock_guard<std::mutex> lock(kink.windows->mutex);
    std::shared_ptr<const KinkCorrection>& window = kink.windows->windows[r];
    if (!window) window = std::make_shared<const KinkCorrection>(kink, r);
    return window;
  }
  return nullptr;
}

double KinkCorrection::nodes_within(const ZoneGeometry& zone, std::size_t nodes) const {
  const auto angle = [&](double s) { return std::acos(std::clamp((s - zone.m) / zone.h, -1.0, 1.0)); };
  return static_cast<double>(nodes) / pi * std::fabs(angle(s0_ - r_) - angle(s0_ + r_));
}

double KinkCorrection::density(double t) const {
  const double u = (t - s0_) / r_;
  if (!(std::fabs(u) < 1) || t == s0_) return 0;
  return -slope_jump_(t) * std::log(std::fabs(t - s0_)) * window(u, order_) / pi;
}

double KinkCorrection::direct_potential(double s) const {
  // Far: log|s - t| = log|s - s0| - sum_k ((t - s0) / (s - s0))^k / k.
  if (std::fabs(s - s0_) >= 2 * r_) {
    const double ratio = r_ / (s - s0_);
    double sum = moments_[0] * std::log(std::fabs(s - s0_)), power = 1;
    for (int k = 1; k <= multipole_terms; ++k) power *= ratio, sum -= moments_[static_cast<std::size_t>(k)] * power / k;
    return -sum / pi;
  }
  const double lo = s0_ - r_, hi = s0_ + r_;
  const auto f = [&](double t) { return t == s ? 0.0 : density(t) * std::log(std::fabs(s - t)); };
  std::vector<double> cuts{lo, s0_, hi};
  if (s > lo && s < hi && s != s0_) cuts.push_back(s);
  std::sort(cuts.begin(), cuts.end());
  double sum = 0;
  for (std::size_t i = 0; i + 1 < cuts.size(); ++i) sum += log_end_integral(f, cuts[i], cuts[i + 1]);
  return -sum / pi;
}

std::size_t KinkCorrection::piece_of(double s) const {
  // The last piece that starts at or below s (the pieces are sorted and tile [-1, 1]).
  const auto after =
      std::upper_bound(pieces_.begin(), pieces_.end(), s, [](double v, const Piece& p) { return v < p.lo; });
  if (after == pieces_.begin() || !(s <= (after - 1)->hi)) return pieces_.size();
  return static_cast<std::size_t>(after - 1 - pieces_.begin());
}

double KinkCorrection::potential(double x) const {
  double value = 0;
  potentials(&x, 1, &value);
  return value;
}

void KinkCorrection::potentials(const double* x, std::size_t count, double* out) const {
  // In chunks whose s and t stay on the stack (a single point allocates nothing).
  constexpr std::size_t chunk = 64;
  double s[chunk], t[chunk];
  for (std::size_t first = 0; first < count; first += chunk) {
    const std::size_t n = std::min(chunk, count - first);
    for (std::size_t i = 0; i < n; ++i) s[i] = std::cos(x[first + i]);
    for (std::size_t i = 0; i < n;) {
      const std::size_t k = piece_of(s[i]);
      std::size_t end = i + 1;
      while (end < n && piece_of(s[end]) == k) ++end;
      if (k == pieces_.size()) {
        for (std::size_t j = i; j < end; ++j) out[first + j] = direct_potential(s[j]);
      } else {
        const Piece& p = pieces_[k];
        for (std::size_t j = i; j < end; ++j) t[j] = std::clamp((2 * s[j] - p.lo - p.hi) / (p.hi - p.lo), -1.0, 1.0);
        chebyshev::sums(chebyshev::Kind::t, p.coefficients.data(), p.coefficients.size(), t + i, out + first + i,
                        end - i);
      }
      i = end;
    }
  }
}

}  // namespace wavecontact::detail
