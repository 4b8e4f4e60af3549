// The files of a user profile: profile_<name>.hpp (evaluators and the runtime adapter)
// and profile_<name>_manifest.txt (every derived expression, for regression tests).
#include <sstream>

#include "canonical.hpp"
#include "codegen.hpp"
#include "emit_common.hpp"
#include "generate.hpp"
#include "symbols.hpp"
#include "user_profile.hpp"

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

std::vector<ex> with_parameters(std::vector<ex> leading, const ProfileDerivation& d,
                                const std::vector<ex>& trailing) {
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

std::string header(const ProfileDerivation& d, const std::string& command) {
  const std::string& name = d.spec.name;
  const std::vector<ex> zone{sym::Ca(), sym::Sa()};
  const std::vector<ex> point{sym::Ca(), sym::Sa(), sym::Cx(), sym::Sx(), sym::D()};
  std::vector<EmittedFunction> functions{
      {name + "_pressure",
       "Contact pressure p(x), |x| < a: eq. 12 solved exactly for this profile.",
       with_parameters({sym::E(), sym::b1()}, d, point), single_term(d.forms.pressure_angle)},
      {name + "_load", "Load per unit length P (eq. 6).", with_parameters({sym::E()}, d, zone),
       single_term(d.forms.load_angle)},
      {name + "_load_slope_factor",
       "dP/dSa - dP/dCa, so that dP/da = (pi/b1) sin(a^) times this.",
       with_parameters({sym::E()}, d, zone), single_term(d.forms.load_slope_factor)},
  };
  functions.push_back({name + "_height", "The profile in Cx = cos x^: y(x^) = Y(Cx).",
                       with_parameters({}, d, {sym::Cx()}), d.forms.height});
  functions.push_back({name + "_height_slope",
                       "dY/dCx: the right-hand side of the multi-zone contact solver.",
                       with_parameters({}, d, {sym::Cx()}), d.forms.height_slope});
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
        "eqs. 4-6, 11, 12):\n//   g(v) = "
     << canonical_rational(d.forms.g)
     << "\n// Evaluators in the angle atoms of runtime/include/wavecontact/angles.hpp. Register "
        "with the runtime:\n//   wavecontact::register_profile(wavecontact::generated::"
     << name << "_profile_evaluator());\n"
     << "#pragma once\n\n#include <cmath>\n\n#include \"wavecontact/profile.hpp\"\n\n"
        "namespace wavecontact::generated {\n";
  for (const auto& f : functions) os << "\n" << emit_function(f);

  const std::string q = parameter_array(d);
  os << "\n// The evaluators above behind the runtime's uniform interface.\n"
     << "inline ProfileEvaluator " << name << "_profile_evaluator() {\n"
     << "  ProfileEvaluator e;\n  e.name = " << quoted(name) << ";\n  e.expression = "
     << quoted(d.spec.expression) << ";\n  e.parameters = {";
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
     << "  e.load_slope_factor = [](const double* " << unused
     << ", double E, double Ca, double Sa) {\n"
     << "    return " << name << "_load_slope_factor<double>(E, " << q << "Ca, Sa);\n  };\n"
     << "  e.height = [](const double* " << unused << ", double Cx) {\n"
     << "    return " << name << "_height<double>(" << q << "Cx);\n  };\n"
     << "  e.height_slope = [](const double* " << unused << ", double Cx) {\n"
     << "    return " << name << "_height_slope<double>(" << q << "Cx);\n  };\n"
     << "  e.harmonic = " << d.forms.harmonic << ";\n"
     << "  e.pole_squares = [](const double* " << (d.pole_squares.empty() ? "/*q*/" : unused)
     << ", double* " << (d.pole_squares.empty() ? "/*tau*/" : "tau") << ") {\n";
  for (std::size_t i = 0; i < d.pole_squares.size(); ++i) {
    const std::string args = q.empty() ? "" : q.substr(0, q.size() - 2);
    os << "    tau[" << i << "] = " << name << "_pole_square_" << i << "<double>(" << args
       << ");\n";
  }
  os << "  };\n  e.pole_count = " << d.pole_squares.size() << ";\n  return e;\n}\n"
     << "\n}  // namespace wavecontact::generated\n";
  return os.str();
}

std::string manifest(const ProfileDerivation& d, const std::string& command) {
  std::ostringstream os;
  os << banner("#", command)
     << "#\n# Profile " << d.spec.name << ", every derived expression in GiNaC syntax (symbols as\n"
        "# in manifest.txt; the parameters are listed with the sample values that fixed signs).\n";
  os << "profile.expression = " << d.spec.expression << "\n";
  for (const auto& p : d.spec.parameters) os << "parameter." << p.name << ".sample = " << p.sample << "\n";
  os << "profile.y = " << canonical_string(d.forms.profile) << "\n";
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
  return os.str();
}

}  // namespace

std::vector<ProfileSpec> example_profiles() {
  return {
      {"parametric_wave_curve", "H1*(m+1)*cos(x)/(m*cos(x)+1)", {{"H1", 1}, {"m", GiNaC::numeric(1, 2)}}},
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
