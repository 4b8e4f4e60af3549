// The files of a user profile: profile_<name>.hpp (evaluators and the runtime adapter)
// and profile_<name>_manifest.txt (every derived expression, for regression tests).
#include <cstdio>
#include <regex>
#include <sstream>

#include "core/canonical.hpp"
#include "core/symbols.hpp"
#include "emit/cxx_emitter.hpp"
#include "emit/file_contents.hpp"
#include "emit/shared_pieces.hpp"
#include "formulas/user_profile.hpp"

namespace wavecontact::derive {

using GiNaC::ex;

namespace {

std::string quoted(const std::string& text) {
  std::string q = "\"";
  for (char c : text) {
    if (c == '"' || c == '\\') q += '\\';
    q += c;
  }
  return q + "\"";
}

std::vector<ex> with_parameters(std::vector<ex> leading, const ProfileDerivation& d, const std::vector<ex>& trailing) {
  for (const auto& p : d.parameters) leading.push_back(p);
  leading.insert(leading.end(), trailing.begin(), trailing.end());
  return leading;
}

// q[0], q[1], ...: the parameters as the adapter receives them.
std::string parameter_array(const ProfileDerivation& d) {
  std::string list;
  for (std::size_t i = 0; i < d.parameters.size(); ++i) list += "q[" + std::to_string(i) + "], ";
  return list;
}

// The names of arguments, comma-separated.
std::string names(const std::vector<ex>& arguments) {
  std::string list;
  for (const ex& a : arguments) {
    list += (list.empty() ? "" : ", ") + GiNaC::ex_to<GiNaC::symbol>(a).get_name();
  }
  return list;
}

// An evaluator of a profile with a harmonic part: the cosine sum's coefficients from
// <name>_cosine_coefficients, summed by runtime/include/wavecontact/detail/harmonic_series.hpp, plus
// <name>_rational_<quantity>, the closed form of the rest, when `rest`. `series` is the call
// of the sum; `work` gives it K scratch values.
std::string harmonic_wrapper(const std::string& quantity, const std::string& doc, const std::vector<ex>& arguments,
                             const ProfileDerivation& d, const std::string& series, bool rest, bool work) {
  const std::string& name = d.spec.name;
  const int K = static_cast<int>(d.forms.cosine.size()) - 1;
  std::vector<ex> parameters(d.parameters.begin(), d.parameters.end());
  std::string body = "  Scalar A[" + std::to_string(K + 1) + "];\n";
  if (work) body += "  Scalar work[" + std::to_string(K) + "];\n";
  body += "  " + name + "_cosine_coefficients<Scalar>(" + names(parameters) + (parameters.empty() ? "" : ", ") +
          "A);\n  return wavecontact::" + series;
  if (rest) body += " +\n         " + name + "_rational_" + quantity + "<Scalar>(" + names(arguments) + ")";
  body += ";\n";
  std::ostringstream os;
  std::istringstream lines(doc);
  for (std::string line; std::getline(lines, line);) os << "// " << line << "\n";
  os << "template <typename Scalar>\ninline Scalar " << name << "_" << quantity << "(";
  for (std::size_t i = 0; i < arguments.size(); ++i) {
    const std::string argument = GiNaC::ex_to<GiNaC::symbol>(arguments[i]).get_name();
    const bool used = std::regex_search(body, std::regex("\\b" + argument + "\\b"));
    os << (i ? ", " : "") << "const Scalar& " << (used ? argument : "/*" + argument + "*/");
  }
  os << ") {\n" << body << "}\n";
  return os.str();
}

// The arguments of the evaluators of a pressure, of a load and of the profile's height.
struct EvaluatorArguments {
  std::vector<ex> pressure, load, height, full_contact;
};

EvaluatorArguments evaluator_arguments(const ProfileDerivation& d) {
  return {with_parameters({sym::E(), sym::b1()}, d, {sym::Ca(), sym::Sa(), sym::Cx(), sym::Sx(), sym::D()}),
          with_parameters({sym::E()}, d, {sym::Ca(), sym::Sa()}), with_parameters({}, d, {sym::Cx()}),
          with_parameters({sym::E(), sym::b1()}, d, {sym::Cx()})};
}

// The five evaluators of a profile with a cosine sum, each the sum plus R's closed form.
std::string harmonic_evaluators(const ProfileDerivation& d, bool rational) {
  const std::string K = std::to_string(d.forms.cosine.size() - 1);
  const EvaluatorArguments arguments = evaluator_arguments(d);
  const std::string plus_rest = rational ? ", plus the closed form of R" : "";
  const std::string linear = "\nCost: O(K) operations, K = " + K + ".";
  std::ostringstream os;
  os << "\n"
     << harmonic_wrapper("pressure",
                         "Contact pressure p(x), |x| < a: eq. 12 solved exactly, the cosine sum in the "
                         "Legendre-Dirichlet form" +
                             plus_rest + "." + linear,
                         arguments.pressure, d,
                         "harmonic_series_pressure<Scalar>(A, " + K + ", work, E, b1, Ca, Cx, Sx, D)", rational, true)
     << "\n"
     << harmonic_wrapper("load", "Load per unit length P (eq. 6)" + plus_rest + "." + linear, arguments.load, d,
                         "harmonic_series_load<Scalar>(A, " + K + ", work, E, Ca, Sa)", rational, true)
     << "\n"
     << harmonic_wrapper("load_slope_factor",
                         "dP/dSa - dP/dCa, so that dP/da = (pi/b1) sin(a^) times this" + plus_rest + "." + linear,
                         arguments.load, d, "harmonic_series_load_slope_factor<Scalar>(A, " + K + ", work, E, Ca)",
                         rational, true)
     << "\n"
     << (d.branches.branched
             ? ""
             : harmonic_wrapper("full_contact_pressure",
                                "p_fc(x) of full contact: p = P/(2 b1) + p_fc, the cosine sum's sum_k k A_k cos(k x^)" +
                                    plus_rest + "." + linear,
                                arguments.full_contact, d,
                                "harmonic_series_full_contact_pressure<Scalar>(A, " + K + ", E, b1, Cx)", rational,
                                false) +
                   "\n")
     << harmonic_wrapper("height", "The profile in Cx = cos x^: y(x^) = Y(Cx)" + plus_rest + "." + linear,
                         arguments.height, d, "harmonic_series_height<Scalar>(A, " + K + ", Cx)", rational, false)
     << "\n"
     << harmonic_wrapper(
            "height_slope", "dY/dCx: the right-hand side of the multi-zone contact solver" + plus_rest + "." + linear,
            arguments.height, d, "harmonic_series_height_slope<Scalar>(A, " + K + ", Cx)", rational, false);
  return os.str();
}

// The evaluators of a profile built with abs() beyond its branch point (beyond_branch.hpp):
// load and slope factor in their forms and the argument that selects them; the pressure's parts
// on either side of the branch point (shared_pieces.hpp) and g of each branch, whose ratio at the
// point chooses among them; the flank's height, its slope and its poles.
std::vector<EmittedFunction> branch_functions(const ProfileDerivation& d) {
  const std::string& name = d.spec.name;
  const BeyondBranch& b = d.beyond;
  const ex v = sym::v();
  const std::vector<ex> load = evaluator_arguments(d).load, height = evaluator_arguments(d).height;
  const std::vector<ex> argument = with_parameters({}, d, {sym::Ca(), sym::Sa()});
  std::vector<EmittedFunction> functions{
      {name + "_beyond_branch_load",
       "Load P (eq. 6) once the zone reaches beyond the branch point: the sub-interval moments of both\n"
       "branches (derive/engine/sub_interval.hpp), I_{j,l} from wavecontact/detail/quadratic_moment.hpp.",
       load, as_ex(b.load_angle)},
      {name + "_near_branch_load",
       "The same load with the top piece in its large-argument form: for " + name + "_top_piece_argument >= 1.", load,
       as_ex(b.load_near_branch_angle)},
      {name + "_top_piece_argument",
       "z of the top piece's I_{j,l} beyond the branch point (it grows without bound as the edge comes down\n"
       "to it): selects the forms that hold the digits.",
       argument, b.top_piece_argument},
      {name + "_beyond_branch_load_slope_factor",
       "dP/dSa - dP/dCa of " + name + "_beyond_branch_load, for " + name + "_top_piece_argument < 0.", load,
       as_ex(b.load_slope_factor)},
      {name + "_beyond_branch_load_slope_factor_by_parts",
       "The same from the moments of (1 + v^2) g' + v g (no end point differentiated), for\n" + name +
           "_top_piece_argument >= 0.",
       load, as_ex(b.load_slope_factor_by_parts)},
      {name + "_top_g", "g(v) of eq. 5 on the top branch (|v| < beta).", with_parameters({sym::E()}, d, {v}), b.top_g},
      {name + "_flank_g", "g(v) of eq. 5 on the flank (|v| > beta).", with_parameters({sym::E()}, d, {v}), b.flank_g},
      {name + "_flank_height", "The flank's profile in Cx = cos x^ (Cx < the branch point's cosine).", height,
       d.flank_height},
      {name + "_flank_height_slope", "dY/dCx on the flank.", height, d.flank_height_slope},
      {name + "_full_contact_pressure",
       "p_fc(x) of full contact over the whole period, both branches (derive/formulas/full_contact.hpp): p = P/(2 b1) "
       "+\n"
       "p_fc, while it is >= 0; Psi from wavecontact/detail/conjugate_logarithm.hpp. Its terms cancel next to a pole "
       "of\n"
       "the other branch's formula: beyond twice the own slope there, the side's form below.",
       evaluator_arguments(d).full_contact, d.full_contact_pressure},
      {name + "_full_contact_pressure_top",
       "The same for Cx above the branch point's cosine, the flank's moment with its Cauchy factor (J'_{j,l}).",
       evaluator_arguments(d).full_contact, d.full_contact_pressure_top},
      {name + "_full_contact_pressure_flank",
       "The same for Cx below the branch point's cosine, the top's moment with its Cauchy factor (J'_{j,l}).",
       evaluator_arguments(d).full_contact, d.full_contact_pressure_flank}};
  for (const EmittedFunction& f :
       pressure_beyond_branch(name + "_beyond_branch_pressure", b, evaluator_arguments(d).pressure)) {
    functions.push_back(f);
  }
  for (std::size_t i = 0; i < d.flank_pole_squares.size(); ++i) {
    functions.push_back({name + "_flank_pole_square_" + std::to_string(i),
                         "A pole v^2 of the flank's g; where real and > beta^2 the contact cannot reach it.",
                         with_parameters({}, d, {}), d.flank_pole_squares[i]});
  }
  return functions;
}

// `  e.<field> = [](const double* q, <signature>) { return <function><double>(<call>); };`
std::string adapter(const ProfileDerivation& d, const std::string& field, const std::string& signature,
                    const std::string& function, const std::string& call) {
  return "  e." + field + " = [](const double* " + (d.parameters.empty() ? "/*q*/" : "q") +
         (signature.empty() ? "" : ", " + signature) + ") {\n    return " + d.spec.name + "_" + function + "<double>(" +
         call + ");\n  };\n";
}

// e.full_contact_pressure. For a profile built with abs(): the whole form (jump apart) where the
// other branch's formula is no steeper than twice the own one, the side's form (Cauchy factor kept)
// where it is, next to its poles; the whole form at the branch point itself, where the side forms'
// logarithms are infinite.
std::string full_contact_adapter(const ProfileDerivation& d) {
  const std::string q = parameter_array(d);
  if (!d.branches.branched) {
    return adapter(d, "full_contact_pressure", "double E, double b1, double Cx", "full_contact_pressure",
                   "E, b1, " + q + "Cx");
  }
  const std::string name = d.spec.name, c = double_literal(d.branches.cosine), call = "<double>(E, b1, " + q + "Cx)";
  const std::string slope = "<double>(" + q + "Cx))";
  return "  e.full_contact_pressure = [](const double* " + std::string(d.parameters.empty() ? "/*q*/" : "q") +
         ", double E, double b1, double Cx) {\n"
         "    const double top = std::fabs(" +
         name + "_height_slope" + slope + ", flank = std::fabs(" + name + "_flank_height_slope" + slope +
         ";\n"
         "    if (Cx > " +
         c + " && flank > 2 * top) return " + name + "_full_contact_pressure_top" + call +
         ";\n"
         "    if (Cx < " +
         c + " && top > 2 * flank) return " + name + "_full_contact_pressure_flank" + call +
         ";\n"
         "    return " +
         name + "_full_contact_pressure" + call + ";\n  };\n";
}

// e.height, e.height_slope: the top's, or for a profile built with abs() the branch of Cx.
std::string height_adapter(const ProfileDerivation& d, const std::string& field) {
  const std::string q = parameter_array(d), name = d.spec.name;
  std::string body = name + "_" + field + "<double>(" + q + "Cx)";
  if (d.branches.branched) {
    body = "Cx >= " + double_literal(d.branches.cosine) + " ? " + body +
           "\n                                  : " + name + "_flank_" + field + "<double>(" + q + "Cx)";
  }
  return "  e." + field + " = [](const double* " + (d.parameters.empty() ? "/*q*/" : "q") +
         ", double Cx) {\n    return " + body + ";\n  };\n";
}

// The fields of ProfileEvaluator::branch.
std::string branch_adapters(const ProfileDerivation& d) {
  const std::string q = parameter_array(d), E = "E, " + q;
  const std::string load = "double E, double Ca, double Sa";
  char beta[32];
  std::snprintf(beta, sizeof beta, "%.17g", GiNaC::ex_to<GiNaC::numeric>(d.branches.beta.evalf()).to_double());
  std::ostringstream os;
  os << "  e.branch.cosine = " << double_literal(d.branches.cosine) << ";\n  e.branch.beta = " << beta << ";\n"
     << adapter(d, "branch.load", load, "beyond_branch_load", E + "Ca, Sa")
     << adapter(d, "branch.load_near_branch", load, "near_branch_load", E + "Ca, Sa")
     << adapter(d, "branch.top_piece_argument", "double Ca, double Sa", "top_piece_argument", q + "Ca, Sa")
     << adapter(d, "branch.load_slope_factor", load, "beyond_branch_load_slope_factor", E + "Ca, Sa")
     << adapter(d, "branch.load_slope_factor_by_parts", load, "beyond_branch_load_slope_factor_by_parts", E + "Ca, Sa")
     << adapter(d, "branch.top_g", "double E, double v", "top_g", E + "v")
     << adapter(d, "branch.flank_g", "double E, double v", "flank_g", E + "v")
     << adapter(d, "branch.flank_height", "double Cx", "flank_height", q + "Cx")
     << adapter(d, "branch.flank_height_slope", "double Cx", "flank_height_slope", q + "Cx");
  const std::string unused = d.parameters.empty() ? "/*q*/" : "q";
  for (int side = 0; side < 2; ++side) {
    const std::string prefix = d.spec.name + "_beyond_branch_pressure_" + (side == 0 ? "top" : "flank") + "_";
    os << "  e.branch.cauchy_argument[" << side << "] = [](const double* " << unused
       << ", double E, double b1, double Ca, double Sa, double Cx, double Sx, double D, double* y) {\n    " << prefix
       << "cauchy_argument<double>(E, b1, " << q << "Ca, Sa, Cx, Sx, D, y);\n  };\n";
    for (int k = 0; k < 7; ++k) {
      os << "  e.branch.part_atoms[" << side << "][" << k << "] = [](const double* " << unused
         << ", double E, double b1, double Ca, double Sa, double y, double one_plus_y, double* atoms) {\n    " << prefix
         << branch_part_names[k] << "_atoms<double>(E, b1, " << q << "Ca, Sa, y, one_plus_y, atoms);\n  };\n"
         << "  e.branch.atom_counts[" << side << "][" << k << "] = " << prefix << branch_part_names[k]
         << "_atoms_outputs;\n"
         << "  e.branch.pressure_parts[" << side << "][" << k << "] = [](const double* " << unused
         << ", double E, double b1, double Ca, double Sa, double Cx, double Sx, double D, const double* atoms) {\n"
         << "    return " << prefix << branch_part_names[k] << "<double>(E, b1, " << q
         << "Ca, Sa, Cx, Sx, D, atoms);\n  };\n";
    }
    for (const char* argument : {"own_argument", "other_argument"}) {
      os << "  e.branch." << argument << "[" << side << "] = [](const double* " << unused
         << ", double Ca, double Sa) {\n    return " << prefix << argument << "<double>(0.0, 0.0, " << q
         << "Ca, Sa);\n  };\n";
    }
  }
  const bool poles = !d.flank_pole_squares.empty();
  os << "  e.branch.flank_pole_squares = [](const double* " << (poles && !d.parameters.empty() ? "q" : "/*q*/")
     << ", double* " << (poles ? "tau" : "/*tau*/") << ") {\n";
  const std::string args = q.empty() ? "" : q.substr(0, q.size() - 2);
  for (std::size_t i = 0; i < d.flank_pole_squares.size(); ++i) {
    os << "    tau[" << i << "] = " << d.spec.name << "_flank_pole_square_" << i << "<double>(" << args << ");\n";
  }
  os << "  };\n  e.branch.flank_pole_count = " << d.flank_pole_squares.size() << ";\n";
  return os.str();
}

std::string header(const ProfileDerivation& d, const std::string& command) {
  const std::string& name = d.spec.name;
  const ClosedForms& forms = d.forms;
  const bool harmonic = !forms.cosine.empty();
  const bool rational = !harmonic || !forms.rational_height_slope.is_zero();
  const int K = static_cast<int>(forms.cosine.size()) - 1;
  const std::string rest = harmonic ? name + "_rational" : name;
  const std::string of_rest = harmonic ? " of the part R that is not a cosine sum" : "";
  const EvaluatorArguments arguments = evaluator_arguments(d);
  std::vector<EmittedFunction> functions;
  if (rational) {
    functions.push_back({rest + "_pressure",
                         "Contact pressure p(x)" + of_rest + ", |x| < a: eq. 12 solved exactly for this profile.",
                         arguments.pressure, single_term(forms.pressure_angle)});
    functions.push_back({rest + "_load", "Load per unit length P (eq. 6)" + of_rest + ".", arguments.load,
                         single_term(forms.load_angle)});
    functions.push_back({rest + "_load_slope_factor",
                         "dP/dSa - dP/dCa" + of_rest + ", so that dP/da = (pi/b1) sin(a^) times this.", arguments.load,
                         single_term(forms.load_slope_factor)});
    if (!d.branches.branched) {
      functions.push_back({rest + "_full_contact_pressure",
                           "p_fc(x) of full contact" + of_rest +
                               " (derive/formulas/full_contact.hpp): p = P/(2 b1) + p_fc, while it is >= 0.",
                           arguments.full_contact, d.full_contact_pressure});
    }
    functions.push_back({rest + "_height", "The profile" + of_rest + " in Cx = cos x^: y(x^) = Y(Cx).",
                         arguments.height, forms.rational_height});
    functions.push_back({rest + "_height_slope",
                         "dY/dCx" + of_rest + ": the right-hand side of the multi-zone contact solver.",
                         arguments.height, forms.rational_height_slope});
  }
  if (harmonic) {
    EmittedFunction cosine{name + "_cosine_coefficients",
                           "The cosine sum of the profile, y = sum_k A_k cos(k x^) + R(cos x^): out[k] = A_k, "
                           "k = 0.." +
                               std::to_string(K) + ".",
                           with_parameters({}, d, {}), 0};
    cosine.outputs = forms.cosine;
    functions.push_back(cosine);
  }
  if (d.branches.branched) {
    for (EmittedFunction& f : branch_functions(d)) functions.push_back(std::move(f));
  }
  for (std::size_t i = 0; i < d.pole_squares.size(); ++i) {
    functions.push_back({name + "_pole_square_" + std::to_string(i),
                         "A pole v^2 = tan^2(x^/2) of g; where real and > 0 the contact "
                         "cannot reach it.",
                         with_parameters({}, d, {}), d.pole_squares[i]});
  }

  std::ostringstream os;
  os << banner("//", command) << "//\n// Profile " << name << ": y(x^) = " << d.spec.expression
     << " over the period 2 pi of x^ = pi x/b1";
  if (!d.parameters.empty()) {
    os << ",\n// parameters:";
    for (const auto& p : d.spec.parameters) os << " " << p.name;
  }
  os << ".\n// Derived by the Block-Keer change of variables and the bounded inversion (seed "
        "eqs. 4-6, 11, 12)";
  if (harmonic) {
    os << ".\n// Its cosine sum, y = sum_{k<=" << K
       << "} A_k cos(k x^) + R(cos x^), has the "
          "Legendre-Dirichlet form\n// (derive/profile/harmonic_part.hpp), summed by wavecontact/"
          "harmonic_series.hpp; "
       << (rational ? "R(Cx) = " + canonical_rational(forms.rational_height) + " has" : "it is the whole profile.\n");
  }
  if (rational) os << (harmonic ? "" : ":") << "\n//   g(v) = " << canonical_rational(d.forms.g) << "\n";
  if (d.branches.branched) {
    os << "// This is its top branch, for cos x^ >= " << d.branches.cosine << ", where its abs() are "
       << canonical_string(d.branches.top) << ";\n// beyond, the flank y = " << canonical_string(d.branches.flank)
       << " (derive/profile/branches.hpp).\n";
  }
  os << "// Evaluators in the angle atoms of runtime/include/wavecontact/angles.hpp. Register "
        "with the runtime:\n//   wavecontact::register_profile(wavecontact::generated::"
     << name << "_profile_evaluator());\n"
     << "#pragma once\n\n#include <cmath>\n\n"
     << (harmonic ? "#include \"wavecontact/detail/harmonic_series.hpp\"\n" : "")
     << (d.branches.branched ? "#include \"wavecontact/detail/conjugate_logarithm.hpp\"\n#include "
                               "\"wavecontact/detail/quadratic_moment.hpp\"\n"
                             : "")
     << "#include \"wavecontact/profile.hpp\"\n\n"
        "namespace wavecontact::generated {\n";
  for (const auto& f : functions) os << "\n" << emit_function(f);
  if (harmonic) os << harmonic_evaluators(d, rational);

  const std::string q = parameter_array(d);
  os << "\n// The evaluators above behind the runtime's uniform interface.\n"
     << "inline ProfileEvaluator " << name << "_profile_evaluator() {\n"
     << "  ProfileEvaluator e;\n  e.name = " << quoted(name) << ";\n  e.expression = " << quoted(d.spec.expression)
     << ";\n  e.parameters = {";
  for (std::size_t i = 0; i < d.spec.parameters.size(); ++i) {
    os << (i ? ", " : "") << quoted(d.spec.parameters[i].name);
  }
  const std::string unused = d.parameters.empty() ? "/*q*/" : "q";
  os << "};\n"
     << "  e.pressure = [](const double* " << unused
     << ", double E, double b1, double Ca, double Sa, double Cx, double Sx, double D) {\n"
     << "    return " << name << "_pressure<double>(E, b1, " << q << "Ca, Sa, Cx, Sx, D);\n  };\n"
     << "  e.load = [](const double* " << unused << ", double E, double Ca, double Sa) {\n"
     << "    return " << name << "_load<double>(E, " << q << "Ca, Sa);\n  };\n"
     << "  e.load_slope_factor = [](const double* " << unused << ", double E, double Ca, double Sa) {\n"
     << "    return " << name << "_load_slope_factor<double>(E, " << q << "Ca, Sa);\n  };\n"
     << height_adapter(d, "height") << height_adapter(d, "height_slope") << full_contact_adapter(d)
     << "  e.harmonic = " << d.forms.harmonic << ";\n"
     << "  e.pole_squares = [](const double* " << (d.pole_squares.empty() ? "/*q*/" : unused) << ", double* "
     << (d.pole_squares.empty() ? "/*tau*/" : "tau") << ") {\n";
  for (std::size_t i = 0; i < d.pole_squares.size(); ++i) {
    const std::string args = q.empty() ? "" : q.substr(0, q.size() - 2);
    os << "    tau[" << i << "] = " << name << "_pole_square_" << i << "<double>(" << args << ");\n";
  }
  os << "  };\n  e.pole_count = " << d.pole_squares.size() << ";\n"
     << (d.branches.branched ? branch_adapters(d) : "") << "  return e;\n}\n"
     << "\n}  // namespace wavecontact::generated\n";
  return os.str();
}

std::string manifest(const ProfileDerivation& d, const std::string& command) {
  std::ostringstream os;
  os << banner("#", command) << "#\n# Profile " << d.spec.name
     << ", every derived expression in GiNaC syntax (symbols as\n"
        "# in manifest.txt; the parameters are listed with the sample values that fixed signs).\n";
  os << "profile.expression = " << d.spec.expression << "\n";
  for (const auto& p : d.spec.parameters) os << "parameter." << p.name << ".sample = " << p.sample << "\n";
  os << "profile.y = " << canonical_string(d.forms.profile) << "\n";
  for (std::size_t k = 0; k < d.forms.cosine.size(); ++k) {
    if (d.forms.cosine[k].is_zero()) continue;
    os << "profile.cosine[" << k << "] = " << canonical_rational(d.forms.cosine[k]) << "\n";
  }
  if (!d.forms.cosine.empty()) {
    os << "profile.rational = " << canonical_rational(d.forms.rational_height) << "\n";
  }
  os << "profile.g = " << canonical_rational(d.forms.g) << "\n";
  const Radicals& radicals = d.forms.radicals;
  for (unsigned i = 0; i < radicals.size(); ++i) {
    os << radicals.symbol(i).get_name() << ".pole = " << canonical_rational(radicals.pole(i)) << "\n";
  }
  write_sum(os, "profile.inversion", d.forms.inversion, radicals);
  write_sum(os, "profile.load", d.forms.load, radicals);
  write_terms(os, "profile.pressure.angle", d.forms.pressure_angle);
  write_terms(os, "profile.load.angle", d.forms.load_angle);
  write_terms(os, "profile.load_slope_factor.angle", d.forms.load_slope_factor);
  os << "profile.height = " << canonical_rational(d.forms.height) << "\n";
  os << "profile.height_slope = " << canonical_rational(d.forms.height_slope) << "\n";
  os << "profile.harmonic = " << d.forms.harmonic << "\n";
  if (!d.branches.branched) {
    os << "profile.full_contact_pressure = " << canonical_string(d.full_contact_pressure) << "\n";
  } else {  // atoms in the numerators: canonical_rational fixes the signs of numerator and denominator
    os << "profile.full_contact_pressure = " << canonical_rational(d.full_contact_pressure) << "\n"
       << "profile.full_contact_pressure.top = " << canonical_rational(d.full_contact_pressure_top) << "\n"
       << "profile.full_contact_pressure.flank = " << canonical_rational(d.full_contact_pressure_flank) << "\n";
  }
  if (d.branches.branched) {
    const BeyondBranch& b = d.beyond;
    os << "branch.cosine = " << d.branches.cosine << "\n"
       << "branch.top = " << canonical_string(d.branches.top) << "\n"
       << "branch.flank = " << canonical_string(d.branches.flank) << "\n"
       << "branch.flank.g = " << canonical_rational(b.flank_g) << "\n"
       << "branch.flank.height = " << canonical_rational(d.flank_height) << "\n";
    for (std::size_t i = 0; i < d.flank_pole_squares.size(); ++i) {
      os << "branch.flank.pole[" << i << "] = " << canonical_rational(d.flank_pole_squares[i]) << "\n";
    }
    write_moment_terms(os, "branch.load", b.load_v);
    write_moment_terms(os, "branch.load.angle", b.load_angle);
    write_moment_terms(os, "branch.load.near_branch.angle", b.load_near_branch_angle);
    write_moment_terms(os, "branch.load_slope_factor.angle", b.load_slope_factor);
    write_moment_terms(os, "branch.load_slope_factor.by_parts", b.load_slope_factor_by_parts_v);
    write_moment_terms(os, "branch.load_slope_factor.by_parts.angle", b.load_slope_factor_by_parts);
    os << "branch.top_piece_argument = " << canonical_rational(b.top_piece_argument) << "\n";
  }
  return os.str();
}

}  // namespace

std::vector<ProfileSpec> example_profiles() {
  return {
      {"parametric_wave_curve", "H1*(m+1)*cos(x)/(m*abs(cos(x))+1)", {{"H1", 1}, {"m", GiNaC::numeric(1, 2)}}},
      {"two_harmonic", "H1*cos(x)+H3*cos(3*x)", {{"H1", 1}, {"H3", GiNaC::numeric(1, 10)}}},
  };
}

std::vector<GeneratedFile> generate_profile(const ProfileSpec& spec, const std::string& command) {
  const ProfileDerivation d = derive_profile(spec);
  return {{"profile_" + spec.name + ".hpp", header(d, command)},
          {"profile_" + spec.name + "_manifest.txt", manifest(d, command)}};
}

std::string profile_registry(const std::vector<ProfileSpec>& specs) {
  std::ostringstream os;
  os << banner("//", regeneration_command())
     << "//\n// The example profiles compiled into the runtime (wavecontact --profile-name).\n"
        "#pragma once\n\n";
  for (const auto& spec : specs) os << "#include \"profile_" << spec.name << ".hpp\"\n";
  os << "\nnamespace wavecontact::generated {\n\n"
        "// Calls visit(evaluator) for every example profile.\n"
        "template <typename Visitor>\nvoid for_each_profile_evaluator(Visitor&& visit) {\n";
  for (const auto& spec : specs) os << "  visit(" << spec.name << "_profile_evaluator());\n";
  os << "}\n\n}  // namespace wavecontact::generated\n";
  return os.str();
}

}  // namespace wavecontact::derive
