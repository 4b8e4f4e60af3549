#include "field_tree.hpp"

#include <array>
#include <cmath>
#include <limits>

#include "constants.hpp"

namespace wavecontact::detail {

namespace {

constexpr double separation = 0.4;  // the largest radius/distance at which a node's moments act
constexpr std::size_t leaf_zones = 2;

// C(k, i) for k < order, as doubles (exact: below 2^53).
template <int order>
const std::array<std::array<double, order>, order>& binomials() {
  static const auto table = [] {
    std::array<std::array<double, order>, order> c{};
    for (int k = 0; k < order; ++k) {
      c[k][0] = 1;
      for (int i = 1; i <= k; ++i) c[k][i] = c[k - 1][i - 1] + (i < k ? c[k - 1][i] : 0.0);
    }
    return c;
  }();
  return table;
}

// Moments about a new centre: `from` holds mu_i / r^i about c'; adds mu_k / R^k about c to
// `to`, delta = c' - c. Every term is at most |mu|: (r + |delta|) <= R.
template <int order>
void shift(const std::vector<double>& from, double r, double delta, double R, std::vector<double>& to) {
  const auto& C = binomials<order>();
  std::array<double, order> rp{}, dp{};
  rp[0] = dp[0] = 1;
  for (int k = 1; k < order; ++k) rp[k] = rp[k - 1] * (r / R), dp[k] = dp[k - 1] * (delta / R);
  for (int k = 0; k < order; ++k) {
    double sum = 0;
    for (int i = 0; i <= k; ++i) sum += C[k][i] * from[static_cast<std::size_t>(i)] * rp[i] * dp[k - i];
    to[static_cast<std::size_t>(k)] += sum;
  }
}

}  // namespace

Abscissa Abscissa::of_angle(const HalfAngle& x) {
  const double sh = x.sin_half, ch = x.cos_half;
  return {std::cos(x.x), 2 * sh * sh, 2 * ch * ch};
}

Abscissa Abscissa::midpoint(const Abscissa& a, const Abscissa& b) {
  return {(a.s + b.s) / 2, (a.from_top + b.from_top) / 2, (a.from_valley + b.from_valley) / 2};
}

double difference(const Abscissa& a, const Abscissa& b) {
  if (a.s >= 0 && b.s >= 0) return b.from_top - a.from_top;
  if (a.s < 0 && b.s < 0) return a.from_valley - b.from_valley;
  return a.s - b.s;
}

FieldTree::FieldTree(const Configuration& c) : zones_(c.zones) {
  for (const ZoneUnknowns& z : c.zones) {
    upper_.push_back(Abscissa::of_angle(z.geometry.end_a));
    lower_.push_back(Abscissa::of_angle(z.geometry.end_b));
  }
  if (!c.zones.empty()) {
    nodes_.reserve(2 * c.zones.size());
    build(0, c.zones.size());
  }
  moments_computed_ = std::make_unique<std::once_flag[]>(nodes_.size());
}

std::size_t FieldTree::build(std::size_t first, std::size_t last) {
  const std::size_t at = nodes_.size();
  nodes_.emplace_back();
  Node node;
  node.first = first, node.last = last;
  node.centre = Abscissa::midpoint(upper_[first], lower_[last - 1]);
  node.radius = difference(upper_[first], lower_[last - 1]) / 2;
  if (last - first > leaf_zones) {
    const std::size_t middle = first + (last - first) / 2;
    node.children[0] = build(first, middle);
    node.children[1] = build(middle, last);
  }
  nodes_[at] = std::move(node);
  return at;
}

const FieldTree::Node& FieldTree::with_moments(std::size_t at) const {
  std::call_once(moments_computed_[at], [&] { compute_moments(nodes_[at]); });
  return nodes_[at];
}

void FieldTree::compute_moments(const Node& node) const {
  const std::size_t first = node.first, last = node.last;
  node.moments.assign(order, 0.0);
  if (node.children[0] == 0) {
    // A zone's moments about its centre m: mu_k = h^{k+1} I_k, I_k = sum_j d_j Int T_j tau^k
    // / sqrt(1 - tau^2) dtau = sum_j d_j pi 2^-k C(k, (k - j)/2) (k - j even, >= 0).
    const auto& C = binomials<order>();
    for (std::size_t l = first; l < last; ++l) {
      const ZoneUnknowns& z = zones_[l];
      const std::size_t count = z.d.size();
      std::vector<double> own(order, 0.0);
      double power = pi;  // pi 2^-k
      for (int k = 0; k < order; ++k, power /= 2) {
        double sum = 0;
        for (int j = k % 2; j <= k && static_cast<std::size_t>(j) < count; j += 2)
          sum += z.d[static_cast<std::size_t>(j)] * C[k][(k - j) / 2];
        own[static_cast<std::size_t>(k)] = z.geometry.h * power * sum;  // mu_k / h^k
      }
      const double delta = difference(Abscissa::midpoint(upper_[l], lower_[l]), node.centre);
      shift<order>(own, z.geometry.h, delta, node.radius, node.moments);
    }
  } else {
    for (std::size_t child : node.children) {
      const Node& n = with_moments(child);
      shift<order>(n.moments, n.radius, difference(n.centre, node.centre), node.radius, node.moments);
    }
  }
  node.moments_over_k = node.moments;
  for (int k = 1; k < order; ++k) node.moments_over_k[static_cast<std::size_t>(k)] /= k;
}

FieldTree::Batch FieldTree::evaluate(std::size_t skip, const std::vector<double>& x, double x_ref, bool slopes,
                                     const double* offsets) const {
  const std::size_t count = x.size();
  Batch out;
  out.difference.assign(count, 0.0);
  if (slopes) out.slope.assign(count, 0.0);
  if (nodes_.empty()) return out;
  const HalfAngle half_reference = HalfAngle::of(x_ref);
  const Abscissa reference = Abscissa::of_angle(half_reference);
  std::vector<HalfAngle> half(count);
  std::vector<FieldValue> field;              // of one leaf's zone, when one acts directly
  std::vector<double> from_reference(count);  // s_i - s_ref
  for (std::size_t i = 0; i < count; ++i) {
    half[i] = HalfAngle::of(x[i]);
    from_reference[i] = offsets ? offsets[i] : difference(Abscissa::of_angle(half[i]), reference);
  }
  // The moments' part, before the factor -1/pi.
  double moment_reference = 0;
  std::vector<double> moment_difference(count, 0.0), moment_slope(slopes ? count : 0, 0.0), d(count);
  std::size_t stack[128];
  std::size_t depth = 0;
  stack[depth++] = 0;
  while (depth > 0) {
    const std::size_t at = stack[--depth];
    const Node& node = nodes_[at];
    const double d_ref = difference(reference, node.centre);
    double nearest = std::fabs(d_ref);
    for (std::size_t i = 0; i < count; ++i) {
      d[i] = d_ref + from_reference[i];
      nearest = std::min(nearest, std::fabs(d[i]));
    }
    if (nearest * separation >= node.radius) {
      // P(t) = sum_{k>=1} A_k t^k / k at t = R/d: at the reference by Horner's rule, and
      // P(t_i) - P(t_ref) = (t_i - t_ref) D_i by the divided differences of the same
      // recurrence (D <- D t_i + u_ref); the logarithm's difference as log1p.
      const double ratio = node.radius / nearest;
      const int terms =
          ratio > 0 ? std::min(order - 1, static_cast<int>(std::ceil(-39.1439465808987777 / std::log(ratio)))) : 0;
      with_moments(at);
      const double* A = node.moments.data();
      const double* A_over_k = node.moments_over_k.data();
      const double t_ref = node.radius / d_ref;
      double partial[order + 1];  // u_ref after each coefficient, from the highest
      partial[terms + 1] = 0;
      double u = 0;
      for (int k = terms; k >= 1; --k) u = u * t_ref + A_over_k[k], partial[k] = u;
      const double P_ref = u * t_ref;
      moment_reference += A[0] * std::log(std::fabs(d_ref)) - P_ref;
      constexpr std::size_t lanes = 8;  // points at a time: the accumulators stay in registers
      for (std::size_t first = 0; first < count; first += lanes) {
        const std::size_t n = std::min(lanes, count - first);
        double t[lanes] = {}, D[lanes] = {}, S[lanes] = {};
        for (std::size_t j = 0; j < n; ++j) t[j] = node.radius / d[first + j];
        // Over k = terms .. 1 of u_k = u_{k+1} t + A_k/k, then the final u_0 = u_1 t (c_0 = 0).
        for (int k = terms; k >= 1; --k) {
          const double previous = partial[k + 1], a = A[k];
          for (std::size_t j = 0; j < lanes; ++j) {
            D[j] = D[j] * t[j] + previous;
            S[j] = (S[j] + a) * t[j];
          }
        }
        for (std::size_t j = 0; j < n; ++j) {
          const std::size_t i = first + j;
          const double Dj = D[j] * t[j] + partial[1];
          const double t_minus = -node.radius * from_reference[i] / (d[i] * d_ref);  // t_i - t_ref
          moment_difference[i] += A[0] * std::log1p(from_reference[i] / d_ref) - t_minus * Dj;
          if (slopes) moment_slope[i] += (A[0] + S[j]) / d[i];
        }
      }
    } else if (node.children[0] == 0) {
      for (std::size_t l = node.first; l < node.last; ++l) {
        if (l == skip) continue;
        const ZoneUnknowns& z = zones_[l];
        const int n = static_cast<int>(z.d.size());
        const double at_reference = far_potential(z.geometry, z.d.data(), n, half_reference);
        out.at_reference += at_reference;
        field.resize(count);
        // The differences from the reference taken as the moments' are, not as differences of
        // two potentials, whose rounding (one ulp of each) was noise at every node (campaign
        // seed 2028, sweep 365: two zones of thousands of nodes beside a gap of 3.1e-5, whose
        // right-hand side's noise this took from 2.4e-17 to 5e-18).
        far_field_differences(z.geometry, z.d.data(), n, half_reference, half.data(), from_reference.data(), count,
                              field.data());
        for (std::size_t i = 0; i < count; ++i) {
          out.difference[i] += field[i].potential;
          if (slopes) out.slope[i] += field[i].slope;
        }
      }
    } else {
      stack[depth++] = node.children[0];
      stack[depth++] = node.children[1];
    }
  }
  out.at_reference -= moment_reference / pi;
  for (std::size_t i = 0; i < count; ++i) {
    out.difference[i] -= moment_difference[i] / pi;
    if (slopes) out.slope[i] -= moment_slope[i] / pi;
  }
  return out;
}

}  // namespace wavecontact::detail
