#include "file_contents.hpp"

#include <sstream>
#include <stdexcept>

#include "core/canonical.hpp"
#include "core/symbols.hpp"
#include "emit/cxx_emitter.hpp"
#include "emit/roughness_programs.hpp"
#include "emit/shared_pieces.hpp"
#include "emit/trigonometry.hpp"
#include "formulas/roughness.hpp"
#include "formulas/wave_curve.hpp"

namespace wavecontact::derive {

using GiNaC::ex;

std::string regeneration_command() { return "wavecontact-derive --out generated"; }

namespace {

std::string roughness_header(int n, const std::string& command) {
  std::ostringstream os;
  os << banner("//", command);
  os << "//\n"
        "// Roughness harmonic r(x) = H2 cos(n pi x/b1), n = "
     << n
     << " (seed eqs. 3, 15-21), in the\n"
        "// angle atoms of runtime/include/wavecontact/angles.hpp. Register with the runtime:\n"
        "//   wavecontact::register_roughness_evaluator({"
     << n << ", &wavecontact::generated::roughness_n" << n
     << "_pressure<double>,\n"
        "//                                            &wavecontact::generated::roughness_n"
     << n
     << "_load<double>,\n"
        "//                                            &wavecontact::generated::roughness_n"
     << n
     << "_legendre<double>});\n"
        "#pragma once\n\n#include <cmath>\n\nnamespace wavecontact::generated {\n";
  for (const auto& f : {roughness_pressure_program(n), roughness_load_program(n), roughness_legendre_program(n)}) {
    os << "\n" << emit_function(f);
  }
  os << "\n}  // namespace wavecontact::generated\n";
  return os.str();
}

// The built-in evaluators, for the runtime's registry.
std::string roughness_registry(const std::vector<int>& ns) {
  std::ostringstream os;
  os << banner("//", regeneration_command());
  os << "//\n// The roughness evaluators compiled into the runtime.\n#pragma once\n\n";
  for (int n : ns) os << "#include \"roughness_n" << n << ".hpp\"\n";
  os << "\nnamespace wavecontact::generated {\n\n"
     << emit_function(roughness_full_contact_program())
     << "\n"
        "// Calls visit(n, pressure, load, legendre) for every built-in n.\n"
        "template <typename Visitor>\nvoid for_each_roughness_evaluator(Visitor&& visit) {\n";
  for (int n : ns) {
    os << "  visit(" << n << ", &roughness_n" << n << "_pressure<double>, &roughness_n" << n
       << "_load<double>, &roughness_n" << n << "_legendre<double>);\n";
  }
  os << "}\n\n}  // namespace wavecontact::generated\n";
  return os.str();
}

// Exact k_j of eq. 18 for every n, each checked against its Chebyshev closed form and
// the product form of eq. 16/17.
std::string roughness_manifest(const std::vector<int>& ns) {
  std::ostringstream os;
  os << banner("#", regeneration_command());
  os << "#\n# Eq. 18 coefficients k_1..k_n (exact), per n. Each table is checked by the derivation\n"
        "# against k_j = (-1)^(n-j) C(n-1+j, n-j) 2^(2j-1)/n, and the product form of eq. 16/17\n"
        "# against de Moivre at n/2 + 1 points to 50 digits.\n";
  for (int n : ns) {
    const auto k = expansion_coefficients(n);
    for (int j = 1; j <= n; ++j) {
      if (k[j - 1] != chebyshev_coefficient(n, j)) {
        throw std::logic_error("k_j of eq. 18 disagrees with the Chebyshev form at n = " + std::to_string(n) +
                               ", j = " + std::to_string(j));
      }
    }
    if (!(product_form_deviation(n, 60) < 1e-50)) {
      throw std::logic_error("the product form of eq. 16/17 disagrees with de Moivre at n = " + std::to_string(n));
    }
    os << "n" << n << ".k =";
    for (const auto& kj : k) os << " " << kj;
    os << "\n";
  }
  return os.str();
}

std::string waviness_header(const WavinessDerivation& d) {
  const std::vector<ex> point_arguments{sym::E(),  sym::H1(), sym::b1(), sym::m(), sym::Ca(),
                                        sym::Sa(), sym::Cx(), sym::Sx(), sym::D()};
  std::vector<EmittedFunction> functions{
      {"waviness_pressure_exact",
       "Exact contact pressure p(x) of the parametric wave curve (eq. 12 solved exactly;\n"
       "the exact counterpart of eq. 13/14), valid for |x| < a <= b1/2.",
       point_arguments, single_term(d.pressure_angle)},
      {"waviness_pressure_paper", "Contact pressure as printed in the seed's eq. 13/14 (exact only for m = 0).",
       point_arguments, single_term(d.paper_pressure_angle)},
      {"waviness_load",
       "Load per unit length P (eq. 6) of the exact pressure, in closed form; the printed\n"
       "eq. 13 integrates to the same load (proven in derive/, see manifest).",
       {sym::E(), sym::H1(), sym::m(), sym::Ca(), sym::Sa()},
       single_term(d.load_angle)},
      {"waviness_load_slope_factor",
       "dP/dSa - dP/dCa of the load: dP/da = (pi/b1) sin(pi a/b1) times this (a <= b1/2).",
       {sym::E(), sym::H1(), sym::m(), sym::Ca(), sym::Sa()},
       single_term(d.load_slope_factor)},
      {"waviness_pa_over_pstar",
       "Dimensionless mean pressure pa/p* = P/(pi E* H1), p* = pi E* H1/(2 b1).",
       {sym::m(), sym::Ca(), sym::Sa()},
       single_term(d.pa_over_pstar_angle)},
      {"waviness_load_beyond_half",
       "Load per unit length P (eq. 6) for b1/2 < a < b1, where the zone reaches the |cos|\n"
       "branch of eq. 2: the sub-interval moments of both branches (derive/engine/sub_interval.hpp),\n"
       "I_{j,l} from wavecontact/detail/quadratic_moment.hpp.",
       {sym::E(), sym::H1(), sym::m(), sym::Ca(), sym::Sa()},
       as_ex(d.beyond_half.load_angle)},
      {"waviness_load_slope_factor_beyond_half",
       "dP/dSa - dP/dCa of waviness_load_beyond_half: dP/da = (pi/b1) sin(pi a/b1) times this.\n"
       "For waviness_top_piece_argument < 0 (its terms cancel as a -> b1/2+).",
       {sym::E(), sym::H1(), sym::m(), sym::Ca(), sym::Sa()},
       as_ex(d.beyond_half.load_slope_factor)},
      {"waviness_load_slope_factor_by_parts",
       "The same slope factor from the moments of (1 + v^2) g' + v g (no end point differentiated):\n"
       "for waviness_top_piece_argument >= 0 (its pieces cancel as m (-cos(pi a/b1)) grows).",
       {sym::E(), sym::H1(), sym::m(), sym::Ca(), sym::Sa()},
       as_ex(d.beyond_half.load_slope_factor_by_parts)},
      {"waviness_top_piece_argument",
       "z of the top piece's I_{j,l} beyond b1/2 (it grows without bound towards b1/2): it selects\n"
       "the forms that hold the digits, waviness_load_near_half where z >= 1 and\n"
       "waviness_load_slope_factor_by_parts where z >= 0.",
       {sym::m(), sym::Ca(), sym::Sa()},
       d.beyond_half.top_piece_argument},
      {"waviness_load_near_half",
       "waviness_load_beyond_half with the top piece in its large-argument form (I_{j,l}(z) =\n"
       "K z^-(j+1/2) - z^-l I_{l-j-1,l}(1/z)): for waviness_top_piece_argument >= 1.",
       {sym::E(), sym::H1(), sym::m(), sym::Ca(), sym::Sa()},
       as_ex(d.beyond_half.load_near_branch_angle)},
      {"waviness_height",
       "The profile of eq. 2 in Cx = cos x^ >= 0: w = Y(Cx) (eq. 2 is odd in Cx: Y(-|Cx|) = -Y(|Cx|)).",
       {sym::H1(), sym::m(), sym::Cx()},
       d.height},
      {"waviness_height_slope",
       "dY/dCx of waviness_height, Cx >= 0 (even in Cx): the contact solver's right-hand side.",
       {sym::H1(), sym::m(), sym::Cx()},
       d.height_slope},
  };
  for (const auto& f : pressure_beyond_branch("waviness_pressure_beyond_half", d.beyond_half, point_arguments)) {
    functions.push_back(f);
  }

  std::ostringstream os;
  os << banner("//", regeneration_command());
  os << "//\n"
        "// Evaluators of the parametric wave curve (seed eq. 2), in the angle atoms of\n"
        "// runtime/include/wavecontact/angles.hpp:\n"
        "//   Ca = cos a^, Sa = 1 - cos a^, Cx = cos x^, Sx = 1 - cos x^, D = cos x^ - cos a^,\n"
        "// a^ = pi a/b1, x^ = pi x/b1. Every function is a template on the scalar type.\n"
        "#pragma once\n\n#include <cmath>\n\n#include \"wavecontact/detail/quadratic_moment.hpp\"\n\n"
        "namespace wavecontact::generated {\n";
  for (const auto& f : functions) os << "\n" << emit_function(f);
  os << "\n}  // namespace wavecontact::generated\n";
  return os.str();
}

std::string manifest(const WavinessDerivation& d) {
  std::ostringstream os;
  os << banner("#", regeneration_command());
  os << "#\n"
        "# Every derived expression in GiNaC syntax, for the symbolic regression tests.\n"
        "# Symbols: x (normalised coordinate), v = tan(x/2), s = u^2, alpha = tan(a^/2), m, E, H1,\n"
        "# b1, angle atoms Ca Sa Cx Sx D, and kappaN = sqrt(kappaN.square).\n"
        "# Sums of radicals are listed per monomial: name[kappa1*kappa2] = coefficient.\n"
        "# Root forms are rational * sqrt(radicand).\n";
  for (unsigned i = 0; i < d.radicals.size(); ++i) {
    const std::string k = d.radicals.symbol(i).get_name();
    os << k << ".pole = " << canonical_rational(d.radicals.pole(i)) << "\n";
    os << k << ".square = " << canonical_rational(d.radicals.square(i)) << "\n";
  }
  os << "waviness.profile = " << canonical_string(d.profile) << "\n";
  os << "waviness.g = " << canonical_rational(d.g) << "\n";
  write_sum(os, "waviness.inversion.exact", d.inversion, d.radicals);
  write_sum(os, "waviness.inversion.paper", d.paper_inversion, d.radicals);
  write_sum(os, "waviness.load.exact", d.load, d.radicals);
  write_sum(os, "waviness.load.paper", d.paper_load, d.radicals);
  write_terms(os, "waviness.pressure.exact.angle", d.pressure_angle);
  write_terms(os, "waviness.pressure.paper.angle", d.paper_pressure_angle);
  write_terms(os, "waviness.load.angle", d.load_angle);
  write_terms(os, "waviness.pa_over_pstar.angle", d.pa_over_pstar_angle);
  write_terms(os, "waviness.load_slope_factor.angle", d.load_slope_factor);
  os << "waviness.flank.g = " << canonical_rational(d.beyond_half.flank_g) << "\n";
  write_moment_terms(os, "waviness.load.beyond_half", d.beyond_half.load_v);
  write_moment_terms(os, "waviness.load.beyond_half.angle", d.beyond_half.load_angle);
  write_moment_terms(os, "waviness.load_slope_factor.beyond_half.angle", d.beyond_half.load_slope_factor);
  write_moment_terms(os, "waviness.load_slope_factor.by_parts", d.beyond_half.load_slope_factor_by_parts_v);
  write_moment_terms(os, "waviness.load_slope_factor.by_parts.angle", d.beyond_half.load_slope_factor_by_parts);
  write_moment_terms(os, "waviness.load.near_half.angle", d.beyond_half.load_near_branch_angle);
  write_pressure_beyond_branch(os, "waviness.pressure.beyond_half", d.beyond_half);
  os << "waviness.top_piece_argument = " << canonical_rational(d.beyond_half.top_piece_argument) << "\n";
  os << "waviness.height = " << canonical_rational(d.height) << "\n";
  os << "waviness.height_slope = " << canonical_rational(d.height_slope) << "\n";
  return os.str();
}

}  // namespace

std::vector<int> default_roughness_n() {
  std::vector<int> ns;
  for (int n = 2; n <= 64; n += 2) ns.push_back(n);
  ns.push_back(128);
  ns.push_back(256);
  return ns;
}

std::vector<GeneratedFile> generate_all() {
  const WavinessDerivation waviness = derive_waviness();
  std::vector<GeneratedFile> files{{"waviness_evaluators.hpp", waviness_header(waviness)},
                                   {"manifest.txt", manifest(waviness)}};
  const std::vector<int> ns = default_roughness_n();
  for (int n : ns) {
    files.push_back({"roughness_n" + std::to_string(n) + ".hpp", roughness_header(n, regeneration_command())});
  }
  files.push_back({"roughness_evaluators.hpp", roughness_registry(ns)});
  files.push_back({"roughness_manifest.txt", roughness_manifest(ns)});
  const std::vector<ProfileSpec> profiles = example_profiles();
  for (const auto& spec : profiles) {
    for (auto& file : generate_profile(spec, regeneration_command())) files.push_back(std::move(file));
  }
  files.push_back({"profiles.hpp", profile_registry(profiles)});
  files.push_back({"bounded_trigonometry.hpp", trigonometry_header(kernel_sine(), regeneration_command())});
  return files;
}

std::vector<GeneratedFile> generate_roughness(const std::vector<int>& ns) {
  constexpr int largest = 4096;  // about 3n lines per evaluator; beyond this, nobody's compiler
  std::vector<GeneratedFile> files;
  for (int n : ns) {
    if (n < 2 || n % 2 != 0 || n > largest) {
      throw std::invalid_argument("--n " + std::to_string(n) +
                                  ": n must be even, 2 <= n <= " + std::to_string(largest));
    }
    const std::string command = "wavecontact-derive --n " + std::to_string(n) + " --out DIR";
    files.push_back({"roughness_n" + std::to_string(n) + ".hpp", roughness_header(n, command)});
  }
  return files;
}

}  // namespace wavecontact::derive
