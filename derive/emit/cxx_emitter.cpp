#include "cxx_emitter.hpp"

#include <algorithm>
#include <cstdio>
#include <map>
#include <set>
#include <sstream>
#include <stdexcept>
#include <tuple>

#include "core/canonical.hpp"

namespace wavecontact::derive {

using GiNaC::ex;
using GiNaC::numeric;

std::string double_literal(const numeric& q) {
  if (!q.is_rational()) throw std::invalid_argument("double_literal: not rational");
  const numeric limit = GiNaC::ex_to<numeric>(GiNaC::pow(numeric(2), 53));
  const numeric p = q.numer(), d = q.denom();
  if (GiNaC::abs(p) <= limit && d <= limit) {
    // Both exact in double: the compiler's division is correctly rounded.
    std::ostringstream os;
    os << p << ".0";
    if (d != 1) os << "/" << d << ".0";
    return d == 1 ? os.str() : "(" + os.str() + ")";
  }
  // Otherwise print enough digits to round-trip (q evaluated at 40 digits first).
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%.17g", GiNaC::ex_to<numeric>(q.evalf()).to_double());
  return buffer;
}

namespace {

enum class Op { Constant, Input, Add, Sub, Mul, Div, Neg, Sqrt, Call };

struct Node {
  Op op;
  std::string text;                    // Constant literal, Input name, or a Call's function and leading arguments
  int a = -1, b = -1, c = -1, d = -1;  // operands; a Call's arguments (two to four)
  bool operator<(const Node& o) const {
    return std::tie(op, text, a, b, c, d) < std::tie(o.op, o.text, o.a, o.b, o.c, o.d);
  }
};

// Inputs by name, with their position (Horner picks the earliest among equals).
using InputIndex = std::map<std::string, int>;

// The symbols of an expression.
void collect_symbols(const ex& e, std::map<std::string, ex>& symbols) {
  if (GiNaC::is_a<GiNaC::symbol>(e)) {
    symbols.emplace(GiNaC::ex_to<GiNaC::symbol>(e).get_name(), e);
    return;
  }
  for (const ex& operand : e) collect_symbols(operand, symbols);
}

class Graph {
 public:
  explicit Graph(const InputIndex& inputs) : inputs_(inputs) {}

  int lower(const ex& e) {
    auto [negative, node] = lower_signed(e);
    return negative ? make(Op::Neg, node) : node;
  }

  const std::vector<Node>& nodes() const { return nodes_; }

 private:
  int intern(Node n) {
    if ((n.op == Op::Add || n.op == Op::Mul) && n.a > n.b) std::swap(n.a, n.b);
    auto [it, inserted] = index_.emplace(n, static_cast<int>(nodes_.size()));
    if (inserted) nodes_.push_back(n);
    return it->second;
  }
  int make(Op op, int a, int b = -1) { return intern({op, "", a, b}); }
  int constant(const std::string& literal) { return intern({Op::Constant, literal}); }

  // (negative, node) with the value = (negative ? -1 : 1) * node.
  std::pair<bool, int> lower_signed(const ex& e) {
    if (GiNaC::is_a<numeric>(e)) {
      const numeric q = GiNaC::ex_to<numeric>(e);
      return {q.is_negative(), constant(double_literal(GiNaC::abs(q)))};
    }
    if (GiNaC::is_a<GiNaC::constant>(e)) {
      char buffer[64];
      std::snprintf(buffer, sizeof buffer, "%.17g", GiNaC::ex_to<numeric>(e.evalf()).to_double());
      return {false, constant(buffer)};
    }
    if (GiNaC::is_a<GiNaC::symbol>(e)) {
      const auto& name = GiNaC::ex_to<GiNaC::symbol>(e).get_name();
      if (!inputs_.count(name)) throw std::invalid_argument("emit: symbol " + name + " is not an argument");
      return {false, intern({Op::Input, name})};
    }
    if (GiNaC::is_a<GiNaC::function>(e) && (GiNaC::ex_to<GiNaC::function>(e).get_name() == "quadratic_moment" ||
                                            GiNaC::ex_to<GiNaC::function>(e).get_name() == "edge_moment")) {
      // I_{j,l}(z) or I'_{j,l}(z) of the sub-interval moments: wavecontact/detail/quadratic_moment.hpp.
      std::ostringstream call;
      call << "wavecontact::" << GiNaC::ex_to<GiNaC::function>(e).get_name() << "<Scalar>(" << e.op(0) << ", "
           << e.op(1) << ", ";
      return {false, intern({Op::Call, call.str(), lower(e.op(2)), lower(e.op(3))})};
    }
    if (GiNaC::is_a<GiNaC::function>(e) && (GiNaC::ex_to<GiNaC::function>(e).get_name() == "two_factor_moment" ||
                                            GiNaC::ex_to<GiNaC::function>(e).get_name() == "two_factor_edge_moment")) {
      // J_{j,l}(y, z) or J'_{j,l}(y, z) of the sub-interval moments with a Cauchy factor: the same header.
      std::ostringstream call;
      call << "wavecontact::" << GiNaC::ex_to<GiNaC::function>(e).get_name() << "<Scalar>(" << e.op(0) << ", "
           << e.op(1) << ", ";
      return {false, intern({Op::Call, call.str(), lower(e.op(2)), lower(e.op(3)), lower(e.op(4)), lower(e.op(5))})};
    }
    if (GiNaC::is_a<GiNaC::function>(e) && GiNaC::ex_to<GiNaC::function>(e).get_name() == "conjugate_logarithm") {
      // Psi(a, b, a - b) of full contact for a profile built with abs() (full_contact.hpp).
      return {false, intern({Op::Call, "wavecontact::conjugate_logarithm<Scalar>(", lower(e.op(0)), lower(e.op(1)),
                             lower(e.op(2))})};
    }
    if (GiNaC::is_a<GiNaC::add>(e)) return {false, lower_sum(e)};
    if (GiNaC::is_a<GiNaC::mul>(e) || GiNaC::is_a<GiNaC::power>(e)) return lower_product(e);
    std::ostringstream os;
    os << "emit: cannot lower " << e;
    throw std::invalid_argument(os.str());
  }

  // Sums: Horner form in the input of highest degree if that degree is >= 2.
  int lower_sum(const ex& sum) {
    const ex e = sum.expand();
    if (!GiNaC::is_a<GiNaC::add>(e)) return lower(e);
    std::map<std::string, ex> symbols;
    collect_symbols(e, symbols);
    const ex* variable = nullptr;
    int best = 1, position = 0;
    for (const auto& [name, s] : symbols) {
      const auto it = inputs_.find(name);
      if (it == inputs_.end() || !e.is_polynomial(s)) continue;
      const int d = e.degree(s);
      if (d > best || (d == best && variable != nullptr && it->second < position)) {
        best = d, variable = &s, position = it->second;
      }
    }
    if (variable == nullptr) return lower_terms(e);
    const ex x = *variable;
    int acc = lower(e.coeff(x, best));
    const int xnode = lower(x);
    for (int k = best - 1; k >= 0; --k) {
      acc = make(Op::Mul, acc, xnode);
      const ex c = e.coeff(x, k);
      if (c.is_zero()) continue;
      auto [negative, node] = lower_signed(c);
      acc = negative ? make(Op::Sub, acc, node) : make(Op::Add, acc, node);
    }
    return acc;
  }

  // Terms over one denominator share its division: sum n_i/d = (sum n_i)/d.
  int lower_terms(const ex& e) {
    std::vector<std::pair<bool, int>> terms;
    for (const ex& term : sorted_operands(e)) terms.push_back(lower_signed(term));
    std::vector<std::pair<bool, int>> grouped;
    std::map<int, std::vector<std::pair<bool, int>>> over;  // denominator: its terms' numerators
    for (const auto& [negative, node] : terms) {
      if (nodes_[node].op == Op::Div) {
        auto& numerators = over[nodes_[node].b];
        if (numerators.empty()) grouped.push_back({negative, node});  // the group's place
        numerators.push_back({negative, nodes_[node].a});
      } else {
        grouped.push_back({negative, node});
      }
    }
    for (auto& [negative, node] : grouped) {
      if (nodes_[node].op != Op::Div || over[nodes_[node].b].size() < 2) continue;
      const int denominator = nodes_[node].b;
      auto& numerators = over[denominator];
      const bool all_negative =
          std::all_of(numerators.begin(), numerators.end(), [](const auto& t) { return t.first; });
      if (all_negative) {
        for (auto& t : numerators) t.first = false;
      }
      negative = all_negative;
      node = make(Op::Div, signed_sum(numerators), denominator);
    }
    return signed_sum(grouped);
  }

  // sum of (negative ? -node : node), from a positive term when there is one.
  int signed_sum(std::vector<std::pair<bool, int>> terms) {
    std::stable_partition(terms.begin(), terms.end(), [](const auto& t) { return !t.first; });
    int acc = terms.front().first ? make(Op::Neg, terms.front().second) : terms.front().second;
    for (std::size_t i = 1; i < terms.size(); ++i) {
      acc = make(terms[i].first ? Op::Sub : Op::Add, acc, terms[i].second);
    }
    return acc;
  }

  // Products and powers: coefficient * numerator / denominator.
  std::pair<bool, int> lower_product(const ex& e) {
    numeric coefficient = 1;
    ex constants = 1;  // pi and other constants, folded into the coefficient's literal
    bool has_constants = false;
    std::vector<int> numerator, denominator;
    // Each factor base^exponent with the base's sign fixed (GiNaC may store a factor as -(sum)
    // in one run and (-sum) in the next), in the order of the fixed factors' canonical strings.
    std::vector<std::pair<std::string, std::pair<ex, numeric>>> factors;
    for (const ex& f : GiNaC::is_a<GiNaC::mul>(e) ? std::vector<ex>(e.begin(), e.end()) : std::vector<ex>{e}) {
      if (GiNaC::is_a<numeric>(f)) {
        coefficient *= GiNaC::ex_to<numeric>(f);
        continue;
      }
      if (GiNaC::is_a<GiNaC::constant>(f) || (GiNaC::is_a<GiNaC::power>(f) && GiNaC::is_a<GiNaC::constant>(f.op(0)))) {
        constants *= f;
        has_constants = true;
        continue;
      }
      ex base = f;
      numeric exponent = 1;
      if (GiNaC::is_a<GiNaC::power>(f)) {
        if (!GiNaC::is_a<numeric>(f.op(1))) throw std::invalid_argument("emit: symbolic exponent");
        base = f.op(0);
        exponent = GiNaC::ex_to<numeric>(f.op(1));
      }
      if (GiNaC::is_a<GiNaC::add>(base) && exponent.is_integer() && leading_term_negative(base.expand())) {
        base = (-base).expand();
        if (exponent.is_odd()) coefficient = -coefficient;
      }
      factors.push_back({canonical_string(base, exponent), {base, exponent}});
    }
    std::stable_sort(factors.begin(), factors.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
    for (const auto& [key, factor] : factors) {
      const auto& [base, exponent] = factor;
      const int node = power(base, GiNaC::abs(exponent));
      (exponent.is_negative() ? denominator : numerator).push_back(node);
    }
    const bool negative = coefficient.is_negative();  // constants are positive (pi)
    int result = -1;
    auto multiply_into = [&](int& acc, int node) { acc = acc < 0 ? node : make(Op::Mul, acc, node); };
    if (has_constants) {
      // One literal for coefficient * pi...: a single rounding.
      char buffer[64];
      std::snprintf(buffer, sizeof buffer, "%.17g",
                    GiNaC::abs(GiNaC::ex_to<numeric>((coefficient * constants).evalf())).to_double());
      result = constant(buffer);
    } else if (!GiNaC::abs(coefficient).is_equal(1)) {
      result = constant(double_literal(GiNaC::abs(coefficient)));
    }
    for (int node : numerator) multiply_into(result, node);
    int below = -1;
    for (int node : denominator) multiply_into(below, node);
    if (result < 0) result = constant("1.0");
    if (below >= 0) result = make(Op::Div, result, below);
    return {negative, result};
  }

  // base^exponent for exponent a positive integer or half-integer.
  int power(const ex& base, const numeric& exponent) {
    const int b = lower(base);
    if (exponent.is_integer()) return integer_power(b, exponent.to_int());
    if ((2 * exponent).is_integer()) {
      const int root = make(Op::Sqrt, b);
      const int whole = (exponent - numeric(1, 2)).to_int();
      return whole == 0 ? root : make(Op::Mul, integer_power(b, whole), root);
    }
    throw std::invalid_argument("emit: exponent is not an integer or half-integer");
  }

  int integer_power(int b, int n) {
    if (n == 1) return b;
    const int half = integer_power(b, n / 2);
    const int square = make(Op::Mul, half, half);
    return n % 2 == 0 ? square : make(Op::Mul, square, b);
  }

  const InputIndex& inputs_;
  std::vector<Node> nodes_;
  std::map<Node, int> index_;
};

class Printer {
 public:
  Printer(const std::vector<Node>& nodes, int root) : nodes_(nodes), uses_(nodes.size(), 0) { count(root); }

  // Temporaries, then `return value;` or, with a target, `const Scalar target = value;`.
  // The temporaries, then `<assignment><value of root>;`, e.g. assignment = "return ".
  // The temporaries come in the post-order of the graph from the root (operands in order), which
  // does not depend on the order in which lowering created the nodes.
  std::string body(int root, OpCounts& counts, const std::string& assignment) {
    std::ostringstream os;
    std::vector<int> order;
    std::vector<bool> visited(nodes_.size(), false);
    post_order(root, visited, order);
    for (int i : order) {
      tally(nodes_[i].op, counts);
      if (uses_[i] >= 2 && i != root && !leaf(i)) {
        const std::string value = expression(i, true);
        names_[i] = "_tmp" + std::to_string(counts.temporaries++);
        os << "  const Scalar " << names_[i] << " = " << value << ";\n";
      }
    }
    os << "  " << assignment << expression(root, true) << ";\n";
    return os.str();
  }

 private:
  bool leaf(int i) const { return nodes_[i].op == Op::Constant || nodes_[i].op == Op::Input; }

  void post_order(int i, std::vector<bool>& visited, std::vector<int>& order) const {
    if (visited[i]) return;
    visited[i] = true;
    for (int operand : {nodes_[i].a, nodes_[i].b, nodes_[i].c, nodes_[i].d}) {
      if (operand >= 0) post_order(operand, visited, order);
    }
    order.push_back(i);
  }

  void count(int i) {
    if (uses_[i]++ > 0) return;
    for (int operand : {nodes_[i].a, nodes_[i].b, nodes_[i].c, nodes_[i].d}) {
      if (operand >= 0) count(operand);
    }
  }

  static void tally(Op op, OpCounts& c) {
    switch (op) {
      case Op::Add:
      case Op::Sub:
        ++c.additions;
        break;
      case Op::Mul:
        ++c.multiplications;
        break;
      case Op::Div:
        ++c.divisions;
        break;
      case Op::Sqrt:
        ++c.square_roots;
        break;
      case Op::Neg:
        ++c.negations;
        break;
      case Op::Call:
        ++c.calls;
        break;
      default:
        break;
    }
  }

  std::string expression(int i, bool top = false) {
    if (auto it = names_.find(i); it != names_.end()) return it->second;
    const Node& n = nodes_[i];
    std::string s;
    switch (n.op) {
      case Op::Constant:
        return "Scalar(" + n.text + ")";
      case Op::Input:
        return n.text;
      case Op::Add:
        s = expression(n.a) + " + " + expression(n.b);
        break;
      case Op::Sub:
        s = expression(n.a) + " - " + expression(n.b);
        break;
      case Op::Mul:
        s = expression(n.a) + " * " + expression(n.b);
        break;
      case Op::Div:
        s = expression(n.a) + " / " + expression(n.b);
        break;
      case Op::Neg:
        return "-" + expression(n.a);
      case Op::Sqrt:
        return "sqrt(" + expression(n.a, true) + ")";
      case Op::Call:
        s = n.text + expression(n.a, true) + ", " + expression(n.b, true);
        if (n.c >= 0) s += ", " + expression(n.c, true);
        if (n.d >= 0) s += ", " + expression(n.d, true);
        return s + ")";
    }
    return top ? s : "(" + s + ")";
  }

  const std::vector<Node>& nodes_;
  std::vector<int> uses_;
  std::map<int, std::string> names_;
};

}  // namespace

GiNaC::ex array_element(const std::string& array, int k) {
  // One symbol per name (GiNaC compares symbols by identity), so that expressions built apart agree.
  static std::map<std::string, GiNaC::symbol> elements;
  const std::string name = array + "[" + std::to_string(k) + "]";
  return elements.try_emplace(name, name).first->second;
}

std::string emit_function(const EmittedFunction& f, OpCounts* out_counts) {
  // Each statement is lowered on its own (its CSE is local); earlier targets are inputs.
  InputIndex inputs;
  for (const ex& argument : f.arguments) {
    inputs.emplace(GiNaC::ex_to<GiNaC::symbol>(argument).get_name(), static_cast<int>(inputs.size()));
  }
  // The arrays' elements that the expressions use, as inputs; and which arrays they use.
  std::set<std::string> used_arrays;
  const auto add_elements = [&](const ex& e) {
    for (GiNaC::const_preorder_iterator i = e.preorder_begin(); i != e.preorder_end(); ++i) {
      if (!GiNaC::is_a<GiNaC::symbol>(*i)) continue;
      const std::string& name = GiNaC::ex_to<GiNaC::symbol>(*i).get_name();
      for (const std::string& array : f.arrays) {
        if (name.rfind(array + "[", 0) == 0) {
          inputs.emplace(name, static_cast<int>(inputs.size()));
          used_arrays.insert(array);
        }
      }
    }
  };
  add_elements(f.value);
  for (const auto& statement : f.statements) add_elements(statement.value);
  for (const auto& output : f.outputs) add_elements(output);
  OpCounts counts;
  std::string body;
  auto lower_and_print = [&](const ex& value, const std::string& assignment) {
    Graph graph(inputs);
    const int root = graph.lower(value);
    body += Printer(graph.nodes(), root).body(root, counts, assignment);
  };
  for (const auto& statement : f.statements) {
    const std::string& target = GiNaC::ex_to<GiNaC::symbol>(statement.target).get_name();
    if (inputs.count(target)) {
      throw std::invalid_argument("emit: statement " + target + " shadows a name in " + f.name);
    }
    lower_and_print(statement.value, "const Scalar " + target + " = ");
    inputs.emplace(target, static_cast<int>(inputs.size()));
  }
  const bool returns_value = f.outputs.empty();
  if (returns_value) lower_and_print(f.value, "return ");
  for (std::size_t k = 0; k < f.outputs.size(); ++k) {
    lower_and_print(f.outputs[k], "out[" + std::to_string(k) + "] = ");
  }

  std::ostringstream os;
  std::istringstream doc(f.doc);
  for (std::string line; std::getline(doc, line);) os << "// " << line << "\n";
  os << "// Total ops: " << counts.total() << " (" << counts.additions << " add, " << counts.multiplications << " mul, "
     << counts.divisions << " div, " << counts.square_roots << " sqrt, " << counts.negations << " neg"
     << (counts.calls > 0 ? ", " + std::to_string(counts.calls) + " moment calls" : "") << "), " << counts.temporaries
     << " temporaries\n";
  std::vector<std::string> parameters;  // a profile without parameters has none but out
  for (const ex& argument : f.arguments) {
    const std::string& name = GiNaC::ex_to<GiNaC::symbol>(argument).get_name();
    bool used = returns_value && f.value.has(argument);
    for (const auto& statement : f.statements) used = used || statement.value.has(argument);
    for (const auto& output : f.outputs) used = used || output.has(argument);
    parameters.push_back("const Scalar& " + (used ? name : "/*" + name + "*/"));
  }
  for (const std::string& array : f.arrays) {
    parameters.push_back("const Scalar* " + (used_arrays.count(array) ? array : "/*" + array + "*/"));
  }
  if (!returns_value) parameters.push_back("Scalar* out");
  os << "template <typename Scalar>\ninline " << (returns_value ? "Scalar " : "void ") << f.name << "(";
  for (std::size_t i = 0; i < parameters.size(); ++i) os << (i ? ", " : "") << parameters[i];
  os << ") {\n  using std::sqrt;\n" << body << "}\n";
  if (!returns_value) os << "inline constexpr int " << f.name << "_outputs = " << f.outputs.size() << ";\n";
  if (out_counts) *out_counts = counts;
  return os.str();
}

}  // namespace wavecontact::derive
