#include "zone_system.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

#include "chebyshev.hpp"
#include "constants.hpp"
#include "support/parallel.hpp"
#include "zone_field.hpp"

namespace wavecontact::detail {

namespace {

constexpr double tiny = std::numeric_limits<double>::min();

// The scaled residual a zone's rows reach at the rounding of the sums they are formed from
// (layout()): below Newton's 1e-10, where it stops at its first iteration that does not halve.
constexpr double rounding_reach = 1e-11;

// An end's angle from its unknown (end_distance), kept within [0, 2].
double end_angle(double unknown, bool upper) {
  const double half = 2 * std::asin(std::sqrt(std::clamp(unknown, 0.0, 2.0) / 2));
  return upper ? half : pi - half;
}

}  // namespace

std::vector<double> node_angles(const ZoneGeometry& g, int count) { return g.angles_of(chebyshev::nodes(count)); }

std::vector<double> node_offsets(const ZoneGeometry& g, int count, double x_ref) {
  // h tau_i + (m - s_ref), the centre's offset as angles_of places the nodes: (1 - s_ref) -
  // (1 - m), 1 - m = 2 sin^2(a/2) + h, with the reference in the upper half, (1 + m) - (1 +
  // s_ref) in the lower. (From m and cos x_ref themselves, each rounded by 1e-16, it erred by as
  // much, which the angles near the top turn into an error like the root of the distance from
  // it: Chebyshev coefficients of 1e-16 on a top zone 0.0018 wide, where the angles gave 1e-19.
  // From 1 - s_i node by node, each node erred by 1e-16 away from the top.)
  double centre = 0;
  if (x_ref <= pi / 2) {
    const double sa = std::sin(g.a / 2), r = std::sin(x_ref / 2);
    centre = 2 * r * r - (2 * sa * sa + g.h);
  } else {
    const double cb = std::cos(g.b / 2), r = std::cos(x_ref / 2);
    centre = (2 * cb * cb + g.h) - 2 * r * r;
  }
  const std::vector<double>& tau = chebyshev::nodes(count);
  std::vector<double> offsets(tau.size());
  for (std::size_t i = 0; i < tau.size(); ++i) offsets[i] = g.h * tau[i] + centre;
  return offsets;
}

// The field is analytic up to the nearest other zone, a distance g in s beyond the zone's
// nearer end: its series falls like rho^-j, rho = 1 + g/h + sqrt((g/h)(2 + g/h)) (the
// Bernstein ellipse through that end), below 1e-17 after 39.1 / log(rho) terms.
int smooth_field_terms(const std::vector<ZoneUnknowns>& zones, std::size_t k) {
  const ZoneGeometry& g = zones[k].geometry;
  double gap = std::numeric_limits<double>::infinity();
  if (k > 0) gap = std::min(gap, cos_difference(zones[k - 1].geometry.b, g.a));
  if (k + 1 < zones.size()) gap = std::min(gap, cos_difference(g.b, zones[k + 1].geometry.a));
  if (std::isinf(gap)) return 0;
  constexpr int most = 1 << 24;  // beyond any zone's nodes: the field at every node
  const double r = gap / g.h, log_rho = std::log1p(r + std::sqrt(r * (2 + r)));
  if (!(log_rho > 0)) return most;  // zones that touch (or, not a number, overlap)
  const double terms = 2 * 39.1439465808987777 / log_rho;
  int count = 32;
  while (count < terms && count < most) count *= 2;
  return count;
}

double end_distance(double x, bool upper) {
  const double r = upper ? std::sin(x / 2) : std::cos(x / 2);
  return 2 * r * r;
}

double own_potential(const ZoneUnknowns& z) {
  double magnitude = 0;
  for (double v : z.d) magnitude += std::fabs(v);
  return z.geometry.h * magnitude;
}

std::vector<double> row_rounding(const SurfaceModel& surface, const Configuration& c) {
  double others = 0;
  for (const ZoneUnknowns& z : c.zones) others += own_potential(z) * (std::fabs(std::log(z.geometry.h)) + 2);
  std::vector<double> rounding;
  for (const ZoneUnknowns& z : c.zones) {
    const double sum =
        std::fabs(c.C) + surface.E / 2 * std::fabs(surface.depth((z.geometry.a + z.geometry.b) / 2)) + others;
    rounding.push_back(8 * std::numeric_limits<double>::epsilon() * sum);
  }
  return rounding;
}

SystemLayout ZoneSystem::layout(const Configuration& c, bool ends_fixed) const {
  SystemLayout L;
  std::size_t at = 0;
  double largest_row = 0;
  // A zone whose own potential is smaller than its rows' rounding (row_rounding) over
  // rounding_reach (one of 1e-4 of the half period or less, beside large ones) has its rows
  // scaled by that instead: their rounding is then rounding_reach.
  const std::vector<double> rounding = row_rounding(surface_, c);
  for (std::size_t k = 0; k < c.zones.size(); ++k) {
    const ZoneUnknowns& z = c.zones[k];
    SystemLayout::Zone lz;
    lz.at = at;
    lz.a_free = !ends_fixed && !z.geometry.top(), lz.b_free = !ends_fixed && !z.geometry.valley();
    lz.a = z.geometry.a, lz.b = z.geometry.b;
    lz.free_ends = (lz.a_free ? 1 : 0) + (lz.b_free ? 1 : 0);
    lz.count = static_cast<int>(z.d.size());
    lz.kink_window = z.kink_window;
    lz.end_scale = z.geometry.h;
    lz.a_upper = z.geometry.a <= pi / 2, lz.b_upper = z.geometry.b <= pi / 2;
    lz.row_scale = std::max({own_potential(z), z.geometry.h * tiny, rounding[k] / rounding_reach});
    largest_row = std::max(largest_row, lz.row_scale);
    at += static_cast<std::size_t>(lz.block());
    L.zones.push_back(lz);
  }
  L.C_at = at;
  L.size = at + 1;
  L.narrow_gaps = c.narrow_gaps;
  L.C_scale = std::max(std::fabs(c.C), largest_row);
  return L;
}

std::vector<double> ZoneSystem::pack(const Configuration& c, const SystemLayout& L) const {
  std::vector<double> X(L.size);
  for (std::size_t k = 0; k < c.zones.size(); ++k) {
    const SystemLayout::Zone& lz = L.zones[k];
    const ZoneGeometry& g = c.zones[k].geometry;
    std::size_t i = lz.at;
    if (lz.a_free) X[i++] = end_distance(g.a, lz.a_upper) / lz.end_scale;
    if (lz.b_free) X[i++] = end_distance(g.b, lz.b_upper) / lz.end_scale;
    for (double v : c.zones[k].d) X[i++] = g.h * v / lz.row_scale;
  }
  X[L.C_at] = c.C / L.C_scale;
  return X;
}

Configuration ZoneSystem::unpack(const std::vector<double>& X, const SystemLayout& L) const {
  Configuration c;
  for (const SystemLayout::Zone& lz : L.zones) {
    std::size_t i = lz.at;
    const double a = lz.a_free ? end_angle(X[i++] * lz.end_scale, lz.a_upper) : lz.a;
    const double b = lz.b_free ? end_angle(X[i++] * lz.end_scale, lz.b_upper) : lz.b;
    ZoneUnknowns z{ZoneGeometry(a, b), std::vector<double>(static_cast<std::size_t>(lz.count)), lz.kink_window};
    // The solve's kink window, unless the ends moved into it.
    z.kink_window = fitting_window(z.geometry, z.kink_window);
    for (double& v : z.d) v = X[i++] * lz.row_scale / z.geometry.h;
    c.zones.push_back(std::move(z));
  }
  c.C = X[L.C_at] * L.C_scale;
  c.narrow_gaps = L.narrow_gaps;
  return c;
}

ZoneFields::ZoneFields(const SurfaceModel& surface, const Configuration& c) : zones(c.zones), tree(c) {
  for (const ZoneUnknowns& z : c.zones) {
    kinks.push_back(KinkCorrection::of(surface, z.geometry, z.kink_window));
    if (kinks.back()) kinked.push_back(kinks.size() - 1);
  }
}

FieldTree::Batch ZoneFields::evaluate(std::size_t skip, const std::vector<double>& x, double x_ref, bool slopes,
                                      const double* offsets) const {
  FieldTree::Batch batch = tree.evaluate(skip, x, x_ref, slopes, offsets);
  std::vector<double> potential(kinked.empty() ? 0 : x.size());
  for (std::size_t l : kinked) {
    if (l == skip) continue;
    const double at_reference = kinks[l]->potential(x_ref);
    batch.at_reference += at_reference;
    kinks[l]->potentials(x.data(), x.size(), potential.data());
    for (std::size_t i = 0; i < x.size(); ++i) batch.difference[i] += potential[i] - at_reference;
  }
  return batch;
}

FieldTree::Batch ZoneFields::at_nodes(std::size_t k, const std::vector<double>& x, bool slopes) const {
  const int M = static_cast<int>(x.size()), terms = smooth_field_terms(zones, k);
  const double x_ref = x[static_cast<std::size_t>(M / 2)];
  if (terms == 0) {  // no other zone
    FieldTree::Batch none;
    none.difference.assign(x.size(), 0.0);
    if (slopes) none.slope.assign(x.size(), 0.0);
    return none;
  }
  const ZoneGeometry& g = zones[k].geometry;
  if (terms > M / 4) return evaluate(k, x, x_ref, slopes, node_offsets(g, M, x_ref).data());
  const FieldTree::Batch coarse =
      evaluate(k, node_angles(g, terms), x_ref, false, node_offsets(g, terms, x_ref).data());
  const std::vector<double> c = chebyshev::coefficients(coarse.difference);
  // The series' second half must be at the rounding of its largest term (else a field less
  // smooth than its distance promises: the nodes themselves take it).
  double largest = 0, tail = 0;
  for (std::size_t j = 0; j < c.size(); ++j) {
    largest = std::max(largest, std::fabs(c[j]));
    if (2 * j >= c.size()) tail = std::max(tail, std::fabs(c[j]));
  }
  if (!(tail <= 1e-14 * largest)) return evaluate(k, x, x_ref, slopes, node_offsets(g, M, x_ref).data());
  FieldTree::Batch out;
  out.at_reference = coarse.at_reference;
  out.difference.resize(x.size());
  chebyshev::values(c.data(), terms, M, out.difference.data());
  if (slopes) {
    // d/ds = (1/h) d/dtau.
    std::vector<double> dc = chebyshev::derivative(c);
    for (double& v : dc) v /= g.h;
    out.slope.resize(x.size());
    chebyshev::values(dc.data(), static_cast<int>(dc.size()), M, out.slope.data());
  }
  return out;
}

double ZoneFields::potential(double x, std::size_t skip) const { return evaluate(skip, {}, x, false).at_reference; }

double zone_load(const Configuration& c, const ZoneFields& fields, std::size_t k) {
  const double smooth = pi * c.zones[k].geometry.h * c.zones[k].d[0];
  return fields.kinks[k] ? smooth + fields.kinks[k]->load() : smooth;
}

std::vector<double> node_heights(const SurfaceModel& surface, const ZoneGeometry& g, const std::vector<double>& x) {
  const std::size_t M = x.size();
  const double x_ref = x[M / 2];
  // At the nodes m + h tau_i themselves, not at their angles: an angle's rounding (a few ulps)
  // times the heights' slope is noise at every node, which d_j = j G_j / h multiplies by j / h
  // (a zone 4e-6 wide at a tip; n = 60 at H2 = 0.2 next to the kink). From there to the
  // exact nodes by tau_i's rounding alone: on a top zone of 5346 nodes (n = 838 and 302,
  // campaign seed 45, sweep 262), the G_j's noise fell from 1.2e-17 to 2e-18 and the
  // contact's estimate from 1.4e-10 to 4.6e-11. (Adding the offsets' own roundings, of h tau_i
  // and of the sum, made the noise larger: the harmonics' phases follow the nodes' angles,
  // which angles_of forms from the doubles tau_i.)
  const std::vector<double> offsets = node_offsets(g, static_cast<int>(M), x_ref);
  std::vector<double> heights(M), slopes(M);
  surface.height_offsets(x.data(), offsets.data(), M, x_ref, heights.data(), slopes.data());
  const std::vector<double>& rounding = chebyshev::node_roundings(static_cast<int>(M));
  for (std::size_t u = 0; u < M; ++u) heights[u] += slopes[u] * g.h * rounding[u];
  return heights;
}

std::vector<double> right_hand_side(const SurfaceModel& surface, const ZoneGeometry& g, const std::vector<double>& x,
                                    const FieldTree::Batch& others, const KinkCorrection* kink) {
  const std::size_t M = x.size();
  const double half_E = surface.E / 2, x_ref = x[M / 2];
  std::vector<double> values = node_heights(surface, g, x), G(M), kink_potential(kink ? M : 0);
  if (kink) kink->potentials(x.data(), M, kink_potential.data());
  for (std::size_t u = 0; u < M; ++u) {
    values[u] = half_E * values[u] - (others.difference.empty() ? 0.0 : others.difference[u]) -
                (kink ? kink_potential[u] : 0.0);
  }
  chebyshev::coefficients(values.data(), static_cast<int>(M), G.data());
  G[0] += half_E * surface.depth(x_ref) - others.at_reference;
  return G;
}

std::vector<double> ZoneSystem::residual(const Configuration& c, const SystemLayout& L,
                                         std::vector<std::vector<double>>* external_slope) const {
  std::vector<double> F(L.size, 0.0), load(c.zones.size());
  const ZoneFields fields(surface_, c);
  if (external_slope) external_slope->assign(c.zones.size(), {});
  // Each zone's rows from the others' field: independent, so on the array kernels' threads
  // (wavecontact/threads.hpp), each zone's rows computed alike on any of them.
  const auto zone_rows = [&](std::size_t k) {
    const ZoneUnknowns& zk = c.zones[k];
    const SystemLayout::Zone& lz = L.zones[k];
    const int M = lz.count;
    const std::vector<double> x = node_angles(zk.geometry, M);
    FieldTree::Batch others = fields.at_nodes(k, x, external_slope != nullptr);
    std::vector<double> G = right_hand_side(surface_, zk.geometry, x, others, fields.kinks[k].get()),
                        own(static_cast<std::size_t>(M));
    G[0] += c.C;
    if (external_slope) (*external_slope)[k] = std::move(others.slope);
    own_potential(zk.geometry, zk.d.data(), M, own.data());
    std::size_t row = lz.at;
    // Row j >= 1 times j: in units of the coefficient it fixes (own_j = h d_j / j), so that
    // the residual bounds the coefficients' error whatever the nodes.
    for (int j = 0; j < M; ++j) {
      const std::size_t u = static_cast<std::size_t>(j);
      F[row++] = (j == 0 ? 1 : j) * (own[u] - G[u]) / lz.row_scale;
    }
    // q bounded at each free end: sum_j d_j T_j(+-1) = 0 (tau = +1 at x^ = a).
    double plus = 0, minus = 0;
    for (int j = 0; j < M; ++j)
      plus += zk.d[static_cast<std::size_t>(j)], minus += (j % 2 == 0 ? 1 : -1) * zk.d[static_cast<std::size_t>(j)];
    if (lz.a_free) F[row++] = zk.geometry.h * plus / lz.row_scale;
    if (lz.b_free) F[row++] = zk.geometry.h * minus / lz.row_scale;
    load[k] = 2 * zone_load(c, fields, k);
  };
  for_each_index(c.zones.size(), zones_for_threads, zone_rows);
  F[L.C_at] = (std::accumulate(load.begin(), load.end(), 0.0) - P_) / P_;
  return F;
}

double ZoneSystem::fitting_window(const ZoneGeometry& zone, double window) const {
  return KinkCorrection::fits(surface_, zone, window) ? window : KinkCorrection::radius_for(surface_, zone);
}

bool ZoneSystem::windows_fit(const Configuration& c) const {
  // A window chosen while the zone's end lay next to the kink is as narrow as that room, and
  // the density's logarithm beyond it is left to the nodes: continued to a load where the end
  // had moved 4.4e-3 past the kink, a window of 2.8e-5 kept the refinement's estimate at
  // 1.4e-6 on 16384 nodes, where the zone's own window gives 6.5e-11 (the wave curve m = 17.6
  // with n = 10 and 6 at P = 22.9, campaign seed 5, sweep 127 with 64 loads, --max-n 32).
  return std::all_of(c.zones.begin(), c.zones.end(), [&](const ZoneUnknowns& z) {
    return KinkCorrection::fits(surface_, z.geometry, z.kink_window) &&
           KinkCorrection::radius_for(surface_, z.geometry) <= 4 * z.kink_window;
  });
}

std::vector<double> ZoneSystem::residuals(const Configuration& c) const {
  return residual(c, layout(c, false), nullptr);
}

void ZoneSystem::relax(Configuration& c) const {
  // Each zone's coefficients from its collocation rows with the others' field as it is:
  // d_j = j G_j / h (j >= 1), d_0 = (G_0 + C) / (h log(2/h)), and C such that they carry P.
  const ZoneFields fields(surface_, c);
  std::vector<std::vector<double>> next;
  double kink_load = 0, load_of_C = 0, load_without_C = 0;
  for (std::size_t k = 0; k < c.zones.size(); ++k) {
    const ZoneUnknowns& zk = c.zones[k];
    const int M = static_cast<int>(zk.d.size());
    const std::vector<double> x = node_angles(zk.geometry, M);
    const FieldTree::Batch others = fields.at_nodes(k, x, false);
    const std::vector<double> G = right_hand_side(surface_, zk.geometry, x, others, fields.kinks[k].get());
    std::vector<double> d(static_cast<std::size_t>(M));
    const double lambda = self_logarithm(zk.geometry);
    d[0] = G[0] / (zk.geometry.h * lambda);
    for (int j = 1; j < M; ++j) d[static_cast<std::size_t>(j)] = j * G[static_cast<std::size_t>(j)] / zk.geometry.h;
    // The zone carries 2 pi (G_0 + C) / log(2/h) (both halves of the period).
    load_without_C += 2 * pi * G[0] / lambda, load_of_C += 2 * pi / lambda;
    if (fields.kinks[k]) kink_load += 2 * fields.kinks[k]->load();
    next.push_back(std::move(d));
  }
  c.C = (P_ - kink_load - load_without_C) / load_of_C;
  for (std::size_t k = 0; k < c.zones.size(); ++k) {
    next[k][0] += c.C / (c.zones[k].geometry.h * self_logarithm(c.zones[k].geometry));
    c.zones[k].d = std::move(next[k]);
  }
}

}  // namespace wavecontact::detail
