#include "symbols.hpp"

namespace wavecontact::derive::sym {
namespace {

// All symbols are created together, in this order, the first time any is used:
// GiNaC orders terms by symbol serial numbers, so a fixed creation order keeps
// printed and emitted expressions byte-identical from run to run.
struct All {
  GiNaC::realsymbol x{"x"}, xi{"xi"}, v{"v"}, u{"u"}, alpha{"alpha"}, t{"t"}, s{"s"};
  GiNaC::realsymbol E{"E"}, H1{"H1"}, b1{"b1"}, m{"m"};
  GiNaC::realsymbol Ca{"Ca"}, Sa{"Sa"}, Cx{"Cx"}, Sx{"Sx"}, D{"D"};
  // Appended: earlier symbols keep their serial numbers.
  GiNaC::realsymbol H2{"H2"}, n{"n"}, Cnx{"Cnx"};
};

const All& all() {
  static const All symbols;
  return symbols;
}

}  // namespace

const GiNaC::realsymbol& x() { return all().x; }
const GiNaC::realsymbol& xi() { return all().xi; }
const GiNaC::realsymbol& v() { return all().v; }
const GiNaC::realsymbol& u() { return all().u; }
const GiNaC::realsymbol& alpha() { return all().alpha; }
const GiNaC::realsymbol& t() { return all().t; }
const GiNaC::realsymbol& s() { return all().s; }
const GiNaC::realsymbol& E() { return all().E; }
const GiNaC::realsymbol& H1() { return all().H1; }
const GiNaC::realsymbol& b1() { return all().b1; }
const GiNaC::realsymbol& m() { return all().m; }
const GiNaC::realsymbol& H2() { return all().H2; }
const GiNaC::realsymbol& n() { return all().n; }
const GiNaC::realsymbol& Cnx() { return all().Cnx; }
const GiNaC::realsymbol& Ca() { return all().Ca; }
const GiNaC::realsymbol& Sa() { return all().Sa; }
const GiNaC::realsymbol& Cx() { return all().Cx; }
const GiNaC::realsymbol& Sx() { return all().Sx; }
const GiNaC::realsymbol& D() { return all().D; }

}  // namespace wavecontact::derive::sym
