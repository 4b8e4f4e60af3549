#include "interval_inversion.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <mutex>
#include <stdexcept>

#include <boost/math/constants/constants.hpp>
#include <boost/math/special_functions/legendre.hpp>

namespace wavecontact::detail {

namespace {

constexpr double pi = boost::math::double_constants::pi;
constexpr double eps = std::numeric_limits<double>::epsilon();
// A panel is no longer than its distance (in w) from the nearest singular point: its
// Bernstein ellipse then has rho >= 2 + sqrt(5), and n-point Gauss-Legendre errs by about
// rho^(-2n).
constexpr double panel_ratio = 1.0;
constexpr int max_panel_depth = 64;

struct GaussLegendre {
  std::vector<double> x, w;  // on [-1, 1]
};

// The Gauss-Legendre rule of an order (Boost.Math's zeros of P_n), cached.
const GaussLegendre& gauss_legendre(int order) {
  static std::mutex mutex;
  static std::map<int, GaussLegendre> cache;
  const std::lock_guard<std::mutex> lock(mutex);
  auto it = cache.find(order);
  if (it != cache.end()) return it->second;
  GaussLegendre rule;
  for (double z : boost::math::legendre_p_zeros<double>(order)) {
    const double d = boost::math::legendre_p_prime(order, z);
    const double w = 2 / ((1 - z * z) * d * d);
    rule.x.push_back(z), rule.w.push_back(w);
    if (z != 0) rule.x.push_back(-z), rule.w.push_back(w);
  }
  return cache.emplace(order, std::move(rule)).first->second;
}

// Distance from the real segment [a, b] to the complex point z.
double distance(double a, double b, std::complex<double> z) {
  if (z.real() >= a && z.real() <= b) return std::fabs(z.imag());
  return std::min(std::abs(z - a), std::abs(z - b));
}

// w^power for power in {0, 1, 2}.
double power_of(double w, int power) { return power == 0 ? 1.0 : power == 1 ? w : w * w; }

}  // namespace

IntervalInversion::IntervalInversion(const SurfaceSlope& surface, std::vector<Zone> zones,
                                     int order, Grading grading, std::shared_ptr<Layout> layout)
    : surface_(surface), zones_(std::move(zones)), order_(order),
      narrowest_(grading == Grading::evaluation ? 1e-14 : 1e-9),
      layout_(layout ? std::move(layout) : std::make_shared<Layout>()) {
  if (zones_.empty()) throw std::logic_error("IntervalInversion: no zone");
  for (std::size_t k = 0; k < zones_.size(); ++k) {
    const Zone& z = zones_[k];
    if (!(z.lo >= 0 && z.lo < z.hi && z.hi <= pi) || (k > 0 && !(zones_[k - 1].hi < z.lo))) {
      throw std::logic_error("IntervalInversion: zones not sorted, disjoint and within [0, pi]");
    }
  }
  // s-intervals in increasing s: the zones in decreasing x^.
  for (auto z = zones_.rbegin(); z != zones_.rend(); ++z) {
    refs_.push_back({z->hi, z->hi == pi ? -1.0 : std::cos(z->hi), z->hi == pi ? -1 : 1});
    refs_.push_back({z->lo, z->lo == 0 ? 1.0 : std::cos(z->lo), z->lo == 0 ? -1 : 1});
  }
  ends_ = static_cast<int>(refs_.size());
  for (double k : surface_.kinks) refs_.push_back({std::acos(k), k, 0});
  const std::size_t n = refs_.size();
  differences_.resize(n * n);
  for (std::size_t i = 0; i < n; ++i) {
    for (std::size_t j = 0; j < n; ++j) {
      // cos A - cos B = 2 sin((A + B)/2) sin((B - A)/2), without cancellation.
      const double a = refs_[i].angle, b = refs_[j].angle;
      differences_[i * n + j] = i == j ? 0 : 2 * std::sin((a + b) / 2) * std::sin((b - a) / 2);
    }
  }
  const int intervals = static_cast<int>(zones_.size());
  int unbounded = 0;
  for (int e = 0; e < ends_; ++e) unbounded += refs_[e].tau < 0;
  kappa_ = intervals - unbounded;
  for (int k = 0; k < intervals; ++k) {
    int m = 0;
    for (int j = 2 * k + 1; j < ends_; ++j) m += refs_[j].tau;
    rho_.push_back(((m + 1) / 2) % 2 == 0 ? 1 : -1);  // i^(m+1), m odd
  }
  const int last = ends_ - 1;
  center_ = (refs_.front().s + refs_[last].s) / 2;
  half_span_ = difference(last, 0) / 2;
  for (int k = 0; k < intervals; ++k) add_nodes(interval(k), -1, rho_[k], nodes_, order_);
  for (Node& node : nodes_) node.from_center = (difference(node.ref, 0) + difference(node.ref, last)) / 2 + node.offset;
  std::vector<std::size_t> per_ref(n, 0);
  for (const Node& node : nodes_) ++per_ref[static_cast<std::size_t>(node.ref)];
  std::vector<int> block_of(n, -1);
  for (std::size_t r = 0; r < n; ++r) {
    if (per_ref[r] == 0) continue;
    block_of[r] = static_cast<int>(blocks_.size());
    NodeBlock& block = blocks_.emplace_back(NodeBlock{static_cast<int>(r), {}, {}, {}});
    block.offset.reserve(per_ref[r]), block.f.reserve(per_ref[r]), block.weight.reserve(per_ref[r]);
  }
  for (const Node& node : nodes_) {
    NodeBlock& block = blocks_[static_cast<std::size_t>(block_of[static_cast<std::size_t>(node.ref)])];
    block.offset.push_back(node.offset), block.f.push_back(node.f), block.weight.push_back(node.weight);
  }
}

IntervalInversion::Region IntervalInversion::interval(int k) const {
  return {refs_[2 * k].s, refs_[2 * k + 1].s, 2 * k, 2 * k + 1, k};
}

std::vector<double> IntervalInversion::free_ends() const {
  std::vector<double> ends;
  for (const Zone& z : zones_) {
    if (z.lo > 0) ends.push_back(z.lo);
    if (z.hi < pi) ends.push_back(z.hi);
  }
  return ends;
}

std::vector<Zone> IntervalInversion::with_free_ends(std::vector<Zone> zones,
                                                    const std::vector<double>& ends) {
  std::size_t i = 0;
  for (Zone& z : zones) {
    if (z.lo > 0) z.lo = ends.at(i++);
    if (z.hi < pi) z.hi = ends.at(i++);
  }
  return zones;
}

IntervalInversion::Point IntervalInversion::point_at_angle(double x) const {
  Point p{std::cos(x), -1, 0, {}};
  p.to_ref.reserve(refs_.size());
  for (const Reference& r : refs_) p.to_ref.push_back(2 * std::sin((r.angle + x) / 2) * std::sin((r.angle - x) / 2));
  return p;
}

IntervalInversion::Point IntervalInversion::point_at_offset(int ref, double offset) const {
  return {refs_[ref].s + offset, ref, offset, {}};
}

IntervalInversion::Point IntervalInversion::panel_point(const Panel& panel, double xi) const {
  const double mid = (panel.wa + panel.wb) / 2, half = (panel.wb - panel.wa) / 2;
  const double w = mid + half * xi;
  if (panel.kink >= 0) {
    const double dw = (mid - panel.wk) + half * xi;  // w - wk without cancellation
    if (std::fabs(dw) < w) return point_at_offset(panel.kink, panel.dir * dw * (w + panel.wk));
  }
  return point_at_offset(panel.anchor, panel.dir * w * w);
}

bool IntervalInversion::locate(const Panel& panel, const Point& p, double& xi) const {
  const double squared = panel.dir * to_ref(p, panel.anchor);
  if (squared < 0) return false;
  // The panel's own ends (0 and pi among them) are in it, whichever way w rounds there.
  const double w = std::sqrt(squared), slack = 4 * std::numeric_limits<double>::epsilon() * panel.wb;
  if (w < panel.wa - slack || w > panel.wb + slack) return false;
  if (panel.kink >= 0) {  // w - wk from the offset to the kink
    const double dw = panel.dir * to_ref(p, panel.kink) / (w + panel.wk);
    xi = (2 * dw - (panel.wa - panel.wk) - (panel.wb - panel.wk)) / (panel.wb - panel.wa);
  } else {
    xi = (2 * w - panel.wa - panel.wb) / (panel.wb - panel.wa);
  }
  xi = std::clamp(xi, -1.0, 1.0);
  return true;
}

double IntervalInversion::product_R(const Point& p, int skip) const {
  double product = 1;
  for (int e = 0; e < ends_; ++e) {
    if (e == skip) continue;
    const double d = std::fabs(to_ref(p, e));
    product = refs_[e].tau > 0 ? product * d : product / d;
  }
  if (std::isnormal(product)) return std::sqrt(product);
  // Many ends can under- or overflow the plain product: mantissa and exponent apart.
  double mantissa = 1;
  long exponent = 0;
  for (int e = 0; e < ends_; ++e) {
    if (e == skip) continue;
    const double d = std::fabs(to_ref(p, e));
    int k;
    mantissa = std::frexp(refs_[e].tau > 0 ? mantissa * d : mantissa / d, &k);
    exponent += k;
  }
  if (exponent % 2 != 0) mantissa *= 2, exponent -= 1;
  return std::ldexp(std::sqrt(mantissa), static_cast<int>(exponent / 2));
}

double IntervalInversion::S(const Point& p, double* terms) const {
  const double fs = f(p.s);
  double sum = 0, magnitude = 0;
  for (const NodeBlock& block : blocks_) {
    const double d = to_ref(p, block.ref);  // t - s = offset - (s - s_ref)
    const std::size_t count = block.offset.size();
    const double* offset = block.offset.data();
    const double* fv = block.f.data();
    const double* weight = block.weight.data();
    double block_sum = 0, block_magnitude = 0;
    if (terms) {
#pragma omp simd reduction(+ : block_sum, block_magnitude)
      for (std::size_t i = 0; i < count; ++i) {
        const double term = weight[i] * (fv[i] - fs) / (offset[i] - d);
        block_sum += term;
        block_magnitude += std::fabs(term);
      }
    } else {
#pragma omp simd reduction(+ : block_sum)
      for (std::size_t i = 0; i < count; ++i) block_sum += weight[i] * (fv[i] - fs) / (offset[i] - d);
    }
    sum += block_sum, magnitude += block_magnitude;
  }
  if (terms) *terms = magnitude / pi + std::fabs(fs * Pi(p.s));
  return sum / pi - fs * Pi(p.s);
}

double IntervalInversion::phase_outside(double s) const {
  int m = 0;
  for (int e = 0; e < ends_; ++e) m += refs_[e].s > s ? refs_[e].tau : 0;
  return (m / 2) % 2 == 0 ? 1 : -1;
}

std::vector<IntervalInversion::Panel> IntervalInversion::panels(const Region& r) const {
  // Split points, as offsets from both ends of r: its ends, the kinks inside, and the
  // midpoint where both ends are anchors.
  struct Split {
    double from_lo, from_hi;
    int kink;
  };
  const bool lo_anchor = r.lo_end >= 0, hi_anchor = r.hi_end >= 0;
  double length;
  if (lo_anchor && hi_anchor) {
    length = difference(r.hi_end, r.lo_end);
  } else if (lo_anchor) {  // up to s = 1: 1 - cos(angle) = 2 sin^2(angle/2)
    const double h = std::sin(refs_[r.lo_end].angle / 2);
    length = 2 * h * h;
  } else {  // from s = -1: 1 + cos(angle) = 2 cos^2(angle/2)
    const double h = std::cos(refs_[r.hi_end].angle / 2);
    length = 2 * h * h;
  }
  if (!(length > 0)) return {};
  std::vector<Split> splits{{0, length, -1}, {length, 0, -1}};
  for (int k = ends_; k < static_cast<int>(refs_.size()); ++k) {
    const double s = refs_[k].s;
    if (s > r.lo && s < r.hi) {
      splits.push_back({lo_anchor ? difference(k, r.lo_end) : s - r.lo,
                        hi_anchor ? difference(r.hi_end, k) : r.hi - s, k});
    }
  }
  if (lo_anchor && hi_anchor) splits.push_back({length / 2, length / 2, -1});
  std::sort(splits.begin(), splits.end(), [](const Split& a, const Split& b) {
    return a.from_lo < b.from_lo || (a.from_lo == b.from_lo && a.kink > b.kink);
  });
  // A kink at the midpoint is one split, the kink.
  splits.erase(std::unique(splits.begin(), splits.end(),
                           [](const Split& a, const Split& b) { return a.from_lo == b.from_lo; }),
               splits.end());

  std::vector<Panel> result;
  std::vector<std::vector<Panel>> hi_pieces;
  int piece_index = 0;
  for (std::size_t i = 0; i + 1 < splits.size(); ++i) {
    const Split a = splits[i], b = splits[i + 1];
    if (!(b.from_lo > a.from_lo)) continue;
    const std::pair<int, int> key{r.id, piece_index++};
    const bool from_lo = lo_anchor && (!hi_anchor || b.from_lo <= length / 2);
    const int anchor = from_lo ? r.lo_end : r.hi_end;
    const double dir = from_lo ? 1 : -1;
    const double w0 = std::sqrt(from_lo ? a.from_lo : b.from_hi);
    const double w1 = std::sqrt(from_lo ? b.from_lo : a.from_hi);
    const double s_anchor = refs_[anchor].s;
    // Singular points in w (both square roots of dir (t - s_anchor)): the other ends; the
    // kinks, where S is s log|s - kink| and divided differences across have a pole close by;
    // the profile's singular points for this piece. Grading stops at panels narrowest_ wide.
    std::vector<std::complex<double>> singular;
    auto add_singular = [&](std::complex<double> z) {
      const std::complex<double> w = std::sqrt(z);
      singular.push_back(w);
      singular.push_back(-w);
    };
    for (int e = 0; e < static_cast<int>(refs_.size()); ++e) {
      if (e != anchor) add_singular(dir * difference(e, anchor));
    }
    if (surface_.singularities) {
      for (std::complex<double> c : surface_.singularities(r.lo + a.from_lo, r.lo + b.from_lo)) {
        add_singular(dir * (c - s_anchor));
      }
    }
    // Points next to a bounding kink are held from it.
    const int kink = (from_lo ? b : a).kink >= 0 ? (from_lo ? b : a).kink : (from_lo ? a : b).kink;
    const double wk = kink < 0 ? 0 : kink == (from_lo ? b : a).kink ? w1 : w0;
    auto angle_at = [&](double w) { return std::acos(std::clamp(s_anchor + dir * w * w, -1.0, 1.0)); };
    std::vector<Panel> piece;
    const auto recorded = layout_->find(key);
    if (recorded != layout_->end()) {  // replay the layout
      const std::vector<double>& f = recorded->second;
      for (std::size_t k = 0; k + 1 < f.size(); ++k) {
        piece.push_back({anchor, dir, w0 + f[k] * (w1 - w0), k + 2 == f.size() ? w1 : w0 + f[k + 1] * (w1 - w0), kink, wk});
      }
      if (from_lo) {
        result.insert(result.end(), piece.begin(), piece.end());
      } else {
        hi_pieces.push_back(piece);
      }
      continue;
    }
    std::vector<std::pair<std::pair<double, double>, int>> todo{{{w0, w1}, 0}};
    while (!todo.empty()) {
      const auto [range, depth] = todo.back();
      const auto [wa, wb] = range;
      todo.pop_back();
      double nearest = std::numeric_limits<double>::infinity();
      for (const auto& z : singular) nearest = std::min(nearest, distance(wa, wb, z));
      const bool resolved = (wb - wa) * (wb + wa) < narrowest_;
      const bool too_long = (wb - wa > panel_ratio * nearest && !resolved) ||
                            std::fabs(angle_at(wb) - angle_at(wa)) > surface_.resolution;
      if (too_long && depth < max_panel_depth) {
        const double mid = wa + (wb - wa) / 2;
        todo.push_back({{mid, wb}, depth + 1});
        todo.push_back({{wa, mid}, depth + 1});
        continue;
      }
      piece.push_back({anchor, dir, wa, wb, kink, wk});
    }
    std::vector<double>& fractions = (*layout_)[key];
    for (const Panel& p : piece) fractions.push_back((p.wa - w0) / (w1 - w0));
    fractions.push_back(1);
    if (from_lo) {
      result.insert(result.end(), piece.begin(), piece.end());
    } else {
      hi_pieces.push_back(piece);
    }
  }
  // Panels of the upper anchor outwards: its pieces in decreasing s.
  for (auto p = hi_pieces.rbegin(); p != hi_pieces.rend(); ++p) result.insert(result.end(), p->begin(), p->end());
  return result;
}

void IntervalInversion::add_nodes(const Region& r, int weight_power, double sign,
                                  std::vector<Node>& out, int order) const {
  const std::vector<Panel> region_panels = panels(r);
  out.reserve(out.size() + region_panels.size() * static_cast<std::size_t>(order));
  for (const Panel& panel : region_panels) add_panel_nodes(panel, weight_power, sign, out, order);
}

void IntervalInversion::add_panel_nodes(const Panel& panel, int weight_power, double sign,
                                        std::vector<Node>& out, int order) const {
  const GaussLegendre& rule = gauss_legendre(order);
  // dt = 2w dw and |t - anchor|^(1/2) = w: F/R dt = 2 w^(1 - tau) F/R_rest dw,
  // F R dt = 2 w^(1 + tau) F R_rest dw.
  const int power = 1 + weight_power * refs_[panel.anchor].tau;
  const double half = (panel.wb - panel.wa) / 2;
  for (std::size_t q = 0; q < rule.x.size(); ++q) {
    const double w = (panel.wa + panel.wb) / 2 + half * rule.x[q];
    const Point p = panel_point(panel, rule.x[q]);
    const double rest = product_R(p, panel.anchor);
    const double weight = sign * half * rule.w[q] * 2 * power_of(w, power) *
                          (weight_power < 0 ? 1 / rest : rest);
    out.push_back({p.offset, f(p.s), weight, 0, p.ref});
  }
}

std::vector<IntervalInversion::Region> IntervalInversion::regions_off() const {
  std::vector<Region> regions;
  const int last = ends_ - 1;
  if (refs_.front().tau > 0) regions.push_back({-1, refs_.front().s, -1, 0, 0});
  for (int k = 1; k + 1 <= last; k += 2) regions.push_back({refs_[k].s, refs_[k + 1].s, k, k + 1, 0});
  if (refs_[last].tau > 0) regions.push_back({refs_[last].s, 1, last, -1, 0});
  for (std::size_t i = 0; i < regions.size(); ++i) regions[i].id = 1000 + static_cast<int>(i);
  return regions;
}

IntervalInversion::Moments IntervalInversion::moments() const {
  // M_j with T_j((t - center)/half_span), j < kappa, and the monic h^j 2^(1-j) T_j for the
  // load (j = kappa), all by one pass of the three-term recurrence; with the sums of the
  // terms' magnitudes.
  const std::size_t count = static_cast<std::size_t>(std::max(kappa_, 0)) + 1;
  Moments m{std::vector<double>(count, 0.0), std::vector<double>(count, 0.0)};
  const double monic = kappa_ > 0 ? std::pow(half_span_, kappa_) * std::ldexp(1.0, 1 - kappa_) : 1;
  for (const Node& n : nodes_) {
    const double x = n.from_center / half_span_, base = n.weight * n.f;
    double previous = 0, T = 1;  // T_(j-1), T_j
    for (std::size_t j = 0; j < count; ++j) {
      if (j > 0) {
        const double next = j == 1 ? x : 2 * x * T - previous;
        previous = T, T = next;
      }
      const double term = base * (j + 1 == count && j > 0 ? T * monic : T);
      m.sum[j] += term, m.magnitude[j] += std::fabs(term);
    }
  }
  return m;
}

std::vector<double> IntervalInversion::residuals(double P) const {
  const Moments m = moments();
  std::vector<double> r;
  for (int j = 0; j <= kappa_; ++j) {
    const double sum = m.sum[static_cast<std::size_t>(j)], magnitude = m.magnitude[static_cast<std::size_t>(j)];
    if (j < kappa_) {
      r.push_back(magnitude > 0 ? sum / magnitude : 0);
    } else {
      r.push_back((2 * sum - P) / std::max(P, 2 * magnitude));
    }
  }
  for (const Region& region : regions_off()) {
    if (region.lo_end < 0 || region.hi_end < 0) continue;  // the outer regions close by symmetry
    std::vector<Node> nodes;
    add_nodes(region, +1, 1, nodes, order_);
    double sum = 0, magnitude = 0;
    for (const Node& n : nodes) {
      double terms;
      sum += n.weight * S(point_at_offset(n.ref, n.offset), &terms);
      magnitude += std::fabs(n.weight) * terms;
    }
    r.push_back(magnitude > 0 ? sum / magnitude : 0);
  }
  return r;
}

double IntervalInversion::half_load() const {
  if (kappa_ < 0) throw std::logic_error("IntervalInversion::half_load: full contact carries any load");
  return moments().sum.back();
}

void IntervalInversion::shift_full_contact_load(double P) {
  if (kappa_ >= 0) throw std::logic_error("IntervalInversion::shift_full_contact_load: not full contact");
  const double shift = (P - load_) / (2 * pi);
  full_contact_constant_ += shift, load_ = P;
  for (Sample& s : pressure_samples_) s.value += shift;
}

void IntervalInversion::prepare(double P) {
  load_ = P;
  const int M = order_ + 2;
  const std::vector<double>& cheb = ChebyshevPanel::cached_points(M);
  zone_tables_.clear(), gap_tables_.clear();
  pressure_samples_.clear(), gap_samples_.clear();
  const int intervals = static_cast<int>(zones_.size());
  if (kappa_ < 0) {  // p = C - S, C from the load: P = 2 Int (C - S) R ds
    std::vector<Node> nodes;
    add_nodes(interval(0), +1, 1, nodes, order_ + 1);
    double RS = 0;
    for (const Node& n : nodes) RS += n.weight * S(point_at_offset(n.ref, n.offset));
    full_contact_constant_ = (P + 2 * RS) / (2 * pi);
  }
  // S on every zone panel, with the pressure and its rounding at the table's points.
  std::vector<double> amplification;
  for (int k = 0; k < intervals; ++k) {
    for (const Panel& panel : panels(interval(k))) {
      std::vector<double> values;
      for (double xi : cheb) {
        const Point p = panel_point(panel, xi);
        double terms;
        const double S_at = S(p, &terms);
        const double x = std::acos(std::clamp(p.s, -1.0, 1.0));
        values.push_back(S_at);
        pressure_samples_.push_back({x, pressure_from_S(p, x, k, S_at)});
        amplification.push_back(amplification_from_S(S_at, terms));
      }
      zone_tables_.push_back({panel, 0, {}, ChebyshevPanel(values)});
    }
  }
  double highest = 0;
  for (const Sample& s : pressure_samples_) highest = std::max(highest, std::fabs(s.value));
  rounding_ = 0;
  for (std::size_t i = 0; i < pressure_samples_.size(); ++i) {
    const double value = std::fabs(pressure_samples_[i].value);
    if (value != 0) rounding_ = std::max(rounding_, amplification[i] * value / highest);
  }
  const double scale = 2 / surface_.E;
  for (const Region& region : regions_off()) {
    const double phase = phase_outside((region.lo + region.hi) / 2);
    double running = 0;
    int anchor = -1;
    for (const Panel& panel : panels(region)) {
      if (panel.anchor != anchor) running = 0, anchor = panel.anchor;  // gap = 0 at a zone end
      // d gap/dw = (2/E*) phase R S dt/dw = (2/E*) phase dir 2 w^2 R_rest S.
      std::vector<double> values;
      for (double xi : cheb) {
        const double w = (panel.wa + panel.wb) / 2 + (panel.wb - panel.wa) / 2 * xi;
        const Point p = panel_point(panel, xi);
        values.push_back(scale * phase * panel.dir * 2 * w * w * product_R(p, panel.anchor) * S(p));
      }
      PanelTable table{panel, running, ChebyshevPanel(values).antiderivative(), {}};
      const double half = (panel.wb - panel.wa) / 2;
      for (double xi : cheb) {
        const double x = std::acos(std::clamp(panel_point(panel, xi).s, -1.0, 1.0));
        gap_samples_.push_back({x, running + half * ChebyshevPanel::chebyshev_sum(table.B, xi)});
      }
      running += half * ChebyshevPanel::chebyshev_sum(table.B, 1.0);
      gap_tables_.push_back(std::move(table));
    }
  }
}

double IntervalInversion::pressure(double x) const {
  x = std::fabs(x);
  const int intervals = static_cast<int>(zones_.size());
  for (int k = 0; k < intervals; ++k) {
    const Zone& z = zones_[intervals - 1 - k];
    if (x < z.lo || x > z.hi) continue;
    const Point p = point_at_angle(x);
    double xi;
    for (const PanelTable& table : zone_tables_) {
      const Panel& panel = table.panel;
      if ((panel.anchor == 2 * k || panel.anchor == 2 * k + 1) && locate(panel, p, xi)) {
        return pressure_from_S(p, x, k, table.values(xi));
      }
    }
    return pressure_from_S(p, x, k, 0);
  }
  return 0;
}

double IntervalInversion::pressure_from_S(const Point& p, double x, int k, double S_at) const {
  if (kappa_ < 0) return full_contact_constant_ - S_at;
  // R~ = R sqrt(1 - s^2): the ends' factors, with those of s = +-1 cancelled.
  double mantissa = 1;
  long exponent = 0;
  bool top = false, valley = false;
  for (int e = 0; e < ends_; ++e) {
    if (refs_[e].tau < 0) {
      (refs_[e].s > 0 ? top : valley) = true;
      continue;
    }
    int ex;
    mantissa = std::frexp(mantissa * std::fabs(to_ref(p, e)), &ex);
    exponent += ex;
  }
  const double h = std::sin(x / 2), c = std::cos(x / 2);
  if (!top) mantissa *= 2 * h * h;     // 1 - s
  if (!valley) mantissa *= 2 * c * c;  // 1 + s
  if (exponent % 2 != 0) mantissa *= 2, exponent -= 1;
  return -rho_[k] * std::ldexp(std::sqrt(mantissa), static_cast<int>(exponent / 2)) * S_at;
}

double IntervalInversion::gap(double x) const {
  const Point p = point_at_angle(std::fabs(x));
  double xi;
  for (const PanelTable& table : gap_tables_) {
    if (locate(table.panel, p, xi)) {
      const Panel& panel = table.panel;
      return table.start + (panel.wb - panel.wa) / 2 * ChebyshevPanel::chebyshev_sum(table.B, xi);
    }
  }
  return 0;  // on a zone
}

double IntervalInversion::zone_load(std::size_t k) const {
  if (zone_tables_.empty()) throw std::logic_error("IntervalInversion::zone_load: not prepared");
  const int i = static_cast<int>(zones_.size()) - 1 - static_cast<int>(k);
  // Int R S over the interval's panels, with S from their tables (order_ + 1 points, between
  // the tables' own).
  const GaussLegendre& rule = gauss_legendre(order_ + 1);
  double sum = 0;
  std::vector<Node> nodes;
  for (const PanelTable& table : zone_tables_) {
    if (table.panel.anchor != 2 * i && table.panel.anchor != 2 * i + 1) continue;
    nodes.clear();
    add_panel_nodes(table.panel, +1, 1, nodes, order_ + 1);
    for (std::size_t q = 0; q < nodes.size(); ++q) {
      const double s = table.values(rule.x[q]);
      // q = -rho R S, or (C - S) R in full contact.
      sum += nodes[q].weight * (kappa_ < 0 ? full_contact_constant_ - s : -rho_[i] * s);
    }
  }
  return sum;
}

double IntervalInversion::rounding_amplification(double x) const {
  double terms;
  const double S_at = S(point_at_angle(std::fabs(x)), &terms);
  return amplification_from_S(S_at, terms);
}

double IntervalInversion::amplification_from_S(double S_at, double terms) const {
  if (kappa_ < 0) {
    return eps * (terms + std::fabs(full_contact_constant_)) / std::fabs(full_contact_constant_ - S_at);
  }
  return eps * terms / std::fabs(S_at);
}

}  // namespace wavecontact::detail
