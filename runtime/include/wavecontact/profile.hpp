// User profiles: any even periodic shape y(x), rational in cos(k x) and sin(k x), derived
// by `wavecontact-derive --profile EXPR --name NAME` (derive/formulas/user_profile.hpp) into
// profile_<NAME>.hpp, whose evaluators reach the runtime through ProfileEvaluator.
// Examples built in: parametric_wave_curve (eq. 2 as an expression, |cos x| and all) and
// two_harmonic (H1 cos x + H3 cos 3x); others are registered with register_profile().
//
// One contact zone |x| < a per period 2 b1, centred on x = 0 (a top of the profile), with
// the same checks as the built-in wave curve: validation of every argument, admissibility
// (p >= 0 in the zone) and stability (dP/da > 0), in stability.hpp.
#pragma once

#include <map>
#include <string>
#include <vector>

namespace wavecontact {

// The evaluators of a profile built with abs(), such as eq. 2, beyond the point x^_b where
// the branch changes (cos x^_b = cosine, v = tan(x^_b/2) = beta): beyond_branch.hpp of derive/.
// With the zone short of x^_b the profile's own evaluators (its top branch) hold; beyond it
// the load and its slope factor in two forms each, selected by the top piece's argument z
// (load_near_branch where z >= 1, load_slope_factor_by_parts where z >= 0), and for the
// pressure the quadrature of eq. 12 over g of both branches (with the divided differences
// that keep their digits as v -> u, and the jump g_flank(u) - g_top(u) across the kink).
struct BranchEvaluators {
  double cosine = 0, beta = 0;  // beta = 0: the profile has one branch
  double (*load)(const double* q, double E, double Ca, double Sa) = nullptr;
  double (*load_near_branch)(const double* q, double E, double Ca, double Sa) = nullptr;
  double (*top_piece_argument)(const double* q, double Ca, double Sa) = nullptr;
  double (*load_slope_factor)(const double* q, double E, double Ca, double Sa) = nullptr;
  double (*load_slope_factor_by_parts)(const double* q, double E, double Ca, double Sa) = nullptr;
  double (*top_g)(const double* q, double E, double v) = nullptr;
  double (*flank_g)(const double* q, double E, double v) = nullptr;
  // The closed-form pressure beyond the branch point on each side (0: the top, Cx above
  // `cosine`; 1: the flank), in parts: own, own_edge, other_cauchy, other_cauchy_edge, other,
  // other_edge, jump (derive/formulas/beyond_branch.hpp), each from its atoms (atom_counts of them:
  // moments of the zone, or at the Cauchy argument y, 1 + y of the point, derive/emit/shared_pieces.hpp);
  // and each piece's pole argument, which selects the basis.
  void (*cauchy_argument[2])(const double* q, double E, double b1, double Ca, double Sa, double Cx, double Sx, double D,
                             double* y) = {};
  using PartAtoms = void (*)(const double* q, double E, double b1, double Ca, double Sa, double y, double one_plus_y,
                             double* atoms);
  PartAtoms part_atoms[2][7] = {};
  int atom_counts[2][7] = {};
  using PressurePart = double (*)(const double* q, double E, double b1, double Ca, double Sa, double Cx, double Sx,
                                  double D, const double* atoms);
  PressurePart pressure_parts[2][7] = {};
  double (*own_argument[2])(const double* q, double Ca, double Sa) = {};
  double (*other_argument[2])(const double* q, double Ca, double Sa) = {};
  double (*flank_height)(const double* q, double Cx) = nullptr;
  double (*flank_height_slope)(const double* q, double Cx) = nullptr;
  // The poles tau_i = tan^2(x^_i/2) of the flank's g that depend on the parameters.
  void (*flank_pole_squares)(const double* q, double* tau) = nullptr;
  int flank_pole_count = 0;
};

// The generated evaluators of one profile behind a uniform interface; q points to the
// parameters in the order of `parameters`. The angle atoms are those of angles.hpp.
struct ProfileEvaluator {
  std::string name;
  std::string expression;  // y(x^) over the period 2 pi of x^ = pi x/b1
  std::vector<std::string> parameters;
  double (*pressure)(const double* q, double E, double b1, double Ca, double Sa, double Cx, double Sx,
                     double D) = nullptr;
  double (*load)(const double* q, double E, double Ca, double Sa) = nullptr;
  // dP/dSa - dP/dCa: dP/da = (pi/b1) sin(pi a/b1) times this.
  double (*load_slope_factor)(const double* q, double E, double Ca, double Sa) = nullptr;
  // The profile in Cx = cos x^, y(x^) = Y(Cx), and dY/dCx: the surface as the multi-zone
  // contact solver sees it (contact.hpp); harmonic: the highest k of cos(k x), sin(k x).
  double (*height)(const double* q, double Cx) = nullptr;
  double (*height_slope)(const double* q, double Cx) = nullptr;
  int harmonic = 1;
  // Full contact: p_fc(x) in Cx (derive/formulas/full_contact.hpp), p = P/(2 b1) + p_fc, for a profile
  // built with abs() over both branches.
  double (*full_contact_pressure)(const double* q, double E, double b1, double Cx) = nullptr;
  // The poles tau_i = tan^2(x^_i/2) of the profile that depend on the parameters.
  void (*pole_squares)(const double* q, double* tau) = nullptr;
  int pole_count = 0;
  BranchEvaluators branch;  // for a profile built with abs()
};

// Adds (or replaces) the evaluators of evaluator.name.
void register_profile(const ProfileEvaluator& evaluator);

// The evaluators of a profile; throws std::domain_error listing the available ones if the
// name is neither built in nor registered.
ProfileEvaluator profile_evaluator(const std::string& name);

// Every profile name, sorted.
std::vector<std::string> available_profiles();

struct ProfileParams {
  std::string name;                          // a registered profile
  std::map<std::string, double> parameters;  // every parameter of that profile, by name
  double b1;                                 // half-period [length]
  double E;                                  // reduced modulus E* [pressure]
};

// A profile with its parameters bound and checked.
class Profile {
 public:
  // Throws std::domain_error naming the parameter if one is missing, unknown or not finite,
  // if b1 or E is not positive, or if a pole of the profile lies at x = 0.
  explicit Profile(const ProfileParams& params);

  const ProfileParams& params() const { return params_; }
  const ProfileEvaluator& evaluator() const { return evaluator_; }
  // The parameters' values in the order of evaluator().parameters.
  const std::vector<double>& parameter_values() const { return q_; }

  // The largest half-width the contact reaches: b1 (full contact), or the first x > 0
  // where the profile (on the branch that holds there) has a pole, which no zone can reach.
  double reach() const { return reach_; }

  // p(x) for the half-width a, 0 < a < reach(); x taken modulo 2 b1, 0 outside the zone.
  double pressure(double a, double x) const;
  // P (eq. 6) and dP/da, 0 < a < reach() (a = b1 too when reach() = b1).
  double load(double a) const;
  double load_slope(double a) const;

  // Full contact (docs/mathematics.md fact 11) in closed form: p(x) = P/(2 b1) + p_fc(x), the solution
  // for the load P while it is >= 0 everywhere (from the onset load -2 b1 min p_fc on).
  // Throws std::domain_error if P is not finite and >= 0, if the profile has a pole on the
  // period (reach() < b1), or if its evaluators were registered without one.
  double full_contact_pressure(double P, double x) const;

 private:
  void check_half_width(const char* function, double a, bool closed) const;
  // Whether the zone |x| < a reaches beyond the change of branch of a profile built with abs().
  bool beyond_branch(double Ca) const;
  ProfileParams params_;
  ProfileEvaluator evaluator_;
  std::vector<double> q_;
  double reach_;
};

}  // namespace wavecontact
