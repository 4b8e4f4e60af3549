#include "roughness_programs.hpp"

#include <string>
#include <vector>

#include "core/symbols.hpp"
#include "formulas/roughness.hpp"

namespace wavecontact::derive {

using GiNaC::ex;
using GiNaC::numeric;

namespace {

// Statements P_2..P_last at Ca (P_0 = 1, P_1 = Ca); returns P_0..P_last.
std::vector<ex> legendre_statements(int last, std::vector<Statement>& statements) {
  std::vector<ex> P{1, sym::Ca()};
  for (int k = 1; k < last; ++k) {
    const GiNaC::realsymbol target("P" + std::to_string(k + 1));
    statements.push_back({target, numeric(2 * k + 1, k + 1) * sym::Ca() * P[k] - numeric(k, k + 1) * P[k - 1]});
    P.push_back(target);
  }
  P.resize(last + 1);
  return P;
}

std::string program_name(int n, const char* quantity) { return "roughness_n" + std::to_string(n) + "_" + quantity; }

}  // namespace

EmittedFunction roughness_pressure_program(int n) {
  require_even(n, "roughness_pressure_program");
  std::vector<Statement> statements;
  const std::vector<ex> P = legendre_statements(n - 1, statements);
  // sum_{j<n} c_j V_j(Cx), c_j = P_{n-1-j}: Clenshaw-Reinsch from j = n-1 down to 0.
  ex b = 0, d = 0;
  for (int j = n - 1; j >= 0; --j) {
    const ex& c = P[n - 1 - j];
    const GiNaC::realsymbol d_j("d" + std::to_string(j));
    statements.push_back({d_j, c - 2 * sym::Sx() * b + d});
    d = d_j;
    if (j == 0) break;
    const GiNaC::realsymbol b_j("sum" + std::to_string(j));
    statements.push_back({b_j, d_j + b});
    b = b_j;
  }
  const ex value = GiNaC::Pi / sym::b1() * sym::E() * sym::H2() * n / 2 * GiNaC::sqrt(sym::D() * (1 + sym::Cx())) * d;
  return {program_name(n, "pressure"),
          "Exact pressure of the roughness harmonic, n = " + std::to_string(n) +
              " (eq. 17 solved exactly, Legendre-Dirichlet form), |x| < a <= b1/2.",
          {sym::E(), sym::H2(), sym::b1(), sym::Ca(), sym::Sa(), sym::Cx(), sym::Sx(), sym::D()},
          value,
          statements};
}

EmittedFunction roughness_legendre_program(int n) {
  require_even(n, "roughness_legendre_program");
  std::vector<Statement> statements;
  const std::vector<ex> P = legendre_statements(n - 1, statements);
  EmittedFunction f{program_name(n, "legendre"),
                    "P_0..P_{n-1}(cos a^), n = " + std::to_string(n) +
                        ": the coefficients c_j = P_{n-1-j} of the pressure series, which\n"
                        "depend only on the zone (same recurrence as roughness_n" +
                        std::to_string(n) + "_pressure); out[k] = P_k.",
                    {sym::Ca()},
                    0,
                    statements};
  f.outputs = P;
  return f;
}

EmittedFunction roughness_load_program(int n) {
  require_even(n, "roughness_load_program");
  std::vector<Statement> statements;
  const std::vector<ex> P = legendre_statements(n - 1, statements);
  ex D = sym::Sa();  // D_1 = P_0 - P_1
  for (int k = 1; k < n; ++k) {
    const GiNaC::realsymbol target("D" + std::to_string(k + 1));
    statements.push_back({target, numeric(k, k + 1) * D + numeric(2 * k + 1, k + 1) * sym::Sa() * P[k]});
    D = target;
  }
  return {program_name(n, "load"),
          "Load of the roughness harmonic, n = " + std::to_string(n) +
              ": (pi/2) E* H2 n [P_{n-1}(cos a^) - P_n(cos a^)] (docs/mathematics.md fact 6).",
          {sym::E(), sym::H2(), sym::Ca(), sym::Sa()},
          GiNaC::Pi / 2 * sym::E() * sym::H2() * n * D,
          statements};
}

EmittedFunction roughness_full_contact_program() {
  return {"roughness_full_contact_pressure",
          "Eq. 15: pressure of the roughness harmonic in full contact, at its onset\n"
          "(mean pressure p*_r = pi E* H2 n/(2 b1)); Cnx = cos(n pi x/b1).",
          {sym::E(), sym::H2(), sym::b1(), sym::n(), sym::Cnx()},
          GiNaC::Pi * sym::E() * sym::H2() * sym::n() / (2 * sym::b1()) * (sym::Cnx() + 1)};
}

}  // namespace wavecontact::derive
