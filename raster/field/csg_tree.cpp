// CSG trees of polynomial leaves (csg_tree.h): recognising the sign-preserving forms on a tape,
// and the first hit along a ray from the leaves' roots.
#include "raster/field/csg_tree.h"

#include <algorithm>
#include <cmath>
#include <unordered_map>

#include "raster/field/polynomial_roots.h"

namespace pf::field {
namespace {

constexpr int kMaxDepth = 1000;  // deeper trees are left to the other methods

double nanIgnoringMin(double a, double b) { return (a < b || b != b) ? a : b; }

class TreeBuilder {
 public:
  TreeBuilder(const FieldTape& tape, size_t max_leaves)
      : in_(tape.instrs), max_leaves_(max_leaves), degree_(polynomialDegrees(tape)) {
    tree_.tape = tape;
  }

  std::optional<CsgTree> build(uint32_t root) {
    if (!node(root, 0) || tree_.leaf_count < 2) return std::nullopt;
    return std::move(tree_);
  }

 private:
  const std::vector<FieldInstr>& in_;
  size_t max_leaves_;
  std::vector<int> degree_;  // of the original values (appended leaves are checked as built)
  CsgTree tree_;
  std::unordered_map<uint32_t, uint32_t> done_;  // tape value -> node (shared subtrees)
  bool failed_ = false;

  bool isPolynomial(uint32_t v) const { return v < degree_.size() && degree_[v] >= 0 && degree_[v] <= 4; }
  const FieldInstr& at(uint32_t v) const { return in_[v]; }

  uint32_t add(CsgNode n) {
    tree_.nodes.push_back(n);
    return static_cast<uint32_t>(tree_.nodes.size() - 1);
  }
  std::optional<uint32_t> leaf(uint32_t value) {
    if (++tree_.leaf_count > max_leaves_) return std::nullopt;
    return add({CsgNode::Kind::Leaf, 0, 0, value});
  }
  uint32_t negate(uint32_t n) { return add({CsgNode::Kind::Not, n, 0, 0}); }

  // Appends an instruction to the tree's tape (operands: values of that tape).
  uint32_t append(FieldOp op, uint32_t a, uint32_t b = 0, float value = 0.0f) {
    tree_.tape.instrs.push_back({op, a, b, value});
    return static_cast<uint32_t>(tree_.tape.instrs.size() - 1);
  }

  // x * x, as a Square or a Mul of equal operands: its operand, else nullopt.
  std::optional<uint32_t> squareOf(uint32_t v) const {
    const FieldInstr& i = at(v);
    if (i.op == FieldOp::Square) return i.a;
    if (i.op == FieldOp::Mul && i.a == i.b) return i.a;
    return std::nullopt;
  }
  // sqrt(a^2 + b^2) for exactly these a and b (either order)?
  bool isRadius(uint32_t v, uint32_t a, uint32_t b) const {
    const FieldInstr& s = at(v);
    if (s.op != FieldOp::Sqrt) return false;
    const FieldInstr& sum = at(s.a);
    if (sum.op != FieldOp::Add) return false;
    const auto p = squareOf(sum.a), q = squareOf(sum.b);
    return p && q && ((*p == a && *q == b) || (*p == b && *q == a));
  }
  // Whether v >= 0 wherever it is defined, by its form: squares, |.|, non-negative constants,
  // and sums and non-negative multiples of those (the torus's off-axis distance is one).
  bool provablyNonNegative(uint32_t v, int depth = 0) const {
    if (depth > 64) return false;
    const FieldInstr& i = at(v);
    switch (i.op) {
      case FieldOp::Square: case FieldOp::Abs: return true;
      case FieldOp::Const: return i.value >= 0.0f;
      case FieldOp::Add: return provablyNonNegative(i.a, depth + 1) && provablyNonNegative(i.b, depth + 1);
      case FieldOp::Mul:
        return i.a == i.b || (provablyNonNegative(i.a, depth + 1) && provablyNonNegative(i.b, depth + 1));
      default: return false;
    }
  }
  // k * sqrt(B) with B polynomial and never negative: (k, B); k = 1 for a bare sqrt. (Where B
  // could be negative the field is NaN there -- outside for every sampling method -- which no
  // min/max of polynomials reproduces: no tree then.)
  std::optional<std::pair<double, uint32_t>> scaledRoot(uint32_t v) const {
    const FieldInstr& i = at(v);
    const auto rootable = [&](uint32_t b) { return isPolynomial(b) && provablyNonNegative(b); };
    if (i.op == FieldOp::Sqrt && rootable(i.a)) return std::make_pair(1.0, i.a);
    if (i.op != FieldOp::Mul) return std::nullopt;
    for (auto [k, r] : {std::make_pair(i.a, i.b), std::make_pair(i.b, i.a)}) {
      if (at(k).op != FieldOp::Const || at(r).op != FieldOp::Sqrt || !rootable(at(r).a)) continue;
      return std::make_pair(static_cast<double>(at(k).value), at(r).a);
    }
    return std::nullopt;
  }

  std::optional<uint32_t> both(CsgNode::Kind kind, uint32_t a, uint32_t b, int depth, bool negate_b = false) {
    const auto x = node(a, depth + 1);
    if (!x) return std::nullopt;
    auto y = node(b, depth + 1);
    if (!y) return std::nullopt;
    if (negate_b) y = negate(*y);
    return add({kind, *x, *y, 0});
  }

  // A + k sqrt(B) (sign +1) or A - k sqrt(B) (sign -1), k > 0 after folding the sign in:
  // A + k sqrt(B) >= 0  <=>  A >= 0 OR k^2 B - A^2 >= 0;  A - k sqrt(B) >= 0  <=>  A >= 0 AND
  // A^2 - k^2 B >= 0. Needs A of degree <= 2 (A^2 is a leaf) and B of degree <= 4.
  std::optional<uint32_t> rootForm(uint32_t A, double k, uint32_t B, int sign) {
    if (k < 0) {
      k = -k;
      sign = -sign;
    }
    if (!(k > 0) || !std::isfinite(k) || degree_[A] > 2) return std::nullopt;
    const uint32_t a2 = append(FieldOp::Square, A);
    const uint32_t kb = append(FieldOp::Mul, append(FieldOp::Const, 0, 0, static_cast<float>(k * k)), B);
    const uint32_t other = sign > 0 ? append(FieldOp::Sub, kb, a2) : append(FieldOp::Sub, a2, kb);
    // k^2 in float: the leaf is exact only where k * k is; otherwise the boundary moves by the
    // rounding of k^2 (relative 6e-8), which the tests' tolerance for such fields states.
    const auto x = leaf(A);
    if (!x) return std::nullopt;
    const auto y = leaf(other);
    if (!y) return std::nullopt;
    return add({sign > 0 ? CsgNode::Kind::Or : CsgNode::Kind::And, *x, *y, 0});
  }

  std::optional<uint32_t> node(uint32_t v, int depth) {
    if (failed_ || depth > kMaxDepth) return std::nullopt;
    if (auto it = done_.find(v); it != done_.end()) return it->second;
    std::optional<uint32_t> n = classify(v, depth);
    if (!n) {
      failed_ = true;
      return std::nullopt;
    }
    done_[v] = *n;
    return n;
  }

  std::optional<uint32_t> classify(uint32_t v, int depth) {
    if (isPolynomial(v)) return leaf(v);
    const FieldInstr& i = at(v);
    switch (i.op) {
      case FieldOp::Min: return both(CsgNode::Kind::And, i.a, i.b, depth);
      case FieldOp::Max: return both(CsgNode::Kind::Or, i.a, i.b, depth);
      case FieldOp::Neg: {
        const auto x = node(i.a, depth + 1);
        if (!x) return std::nullopt;
        return negate(*x);
      }
      case FieldOp::Mul:
        for (auto [c, x] : {std::make_pair(i.a, i.b), std::make_pair(i.b, i.a)}) {
          if (at(c).op != FieldOp::Const || !(at(c).value != 0.0f)) continue;
          if (scaledRoot(v)) break;  // k sqrt(B) alone: not a CSG form
          const auto n = node(x, depth + 1);
          if (!n) return std::nullopt;
          return at(c).value > 0.0f ? *n : negate(*n);
        }
        return std::nullopt;
      case FieldOp::Add: case FieldOp::Sub: {
        // R-functions: (a + b) + R, (a + b) - R, (a - b) - R with R = sqrt(a^2 + b^2).
        const FieldInstr& l = at(i.a);
        if ((l.op == FieldOp::Add || l.op == FieldOp::Sub) && isRadius(i.b, l.a, l.b))
          return both(i.op == FieldOp::Add ? CsgNode::Kind::Or : CsgNode::Kind::And, l.a, l.b, depth, l.op == FieldOp::Sub);
        if (i.op == FieldOp::Add) {
          const FieldInstr& r = at(i.b);
          if (r.op == FieldOp::Add && isRadius(i.a, r.a, r.b)) return both(CsgNode::Kind::Or, r.a, r.b, depth);
        }
        // Polynomial +- k sqrt(polynomial).
        for (auto [A, S] : {std::make_pair(i.a, i.b), std::make_pair(i.b, i.a)}) {
          if (!isPolynomial(A)) continue;
          const auto root = scaledRoot(S);
          if (!root) continue;
          if (i.op == FieldOp::Sub && A != i.a) {
            // k sqrt(B) - A: the negation of A - k sqrt(B).
            const auto n = rootForm(A, root->first, root->second, -1);
            if (!n) return std::nullopt;
            return negate(*n);
          }
          return rootForm(A, root->first, root->second, i.op == FieldOp::Add ? 1 : -1);
        }
        return std::nullopt;
      }
      default: return std::nullopt;
    }
  }
};

}  // namespace

std::optional<CsgTree> csgTreeOf(const FieldTape& tape, size_t max_leaves) {
  if (tape.instrs.empty()) return std::nullopt;
  return TreeBuilder(tape, max_leaves).build(tape.result);
}

double CsgTree::combine(const std::vector<RayPolynomial>& polys, double t) const {
  thread_local std::vector<double> value;  // per thread: rasterizer threads cast concurrently
  value.resize(nodes.size());
  for (size_t n = 0; n < nodes.size(); ++n) {
    const CsgNode& c = nodes[n];
    switch (c.kind) {
      case CsgNode::Kind::Leaf: value[n] = polys[c.value].evaluate(t); break;
      // NaN-ignoring, as the field's min and max (field_scalar.h).
      case CsgNode::Kind::And: value[n] = nanIgnoringMin(value[c.a], value[c.b]); break;
      case CsgNode::Kind::Or: value[n] = -nanIgnoringMin(-value[c.a], -value[c.b]); break;
      case CsgNode::Kind::Not: value[n] = -value[c.a]; break;
    }
  }
  return value.back();
}

std::optional<double> CsgTree::firstHit(const std::array<double, 3>& origin, const std::array<double, 3>& direction,
                                        double entry, double exit, bool& solved) const {
  solved = false;
  thread_local std::vector<RayPolynomial> polys;  // reused per thread: no allocation per ray
  thread_local std::vector<uint8_t> valid;
  thread_local std::vector<double> roots;
  rayPolynomials(tape, origin, direction, polys, valid);
  for (const CsgNode& c : nodes)
    if (c.kind == CsgNode::Kind::Leaf && !valid[c.value]) return std::nullopt;  // e.g. a division by 0
  solved = true;
  if (!(exit >= entry)) return std::nullopt;
  if (combine(polys, entry) >= 0.0) return entry;
  // The combination changes sign only at a leaf's root: the first root after which it is
  // positive, or at which it reaches zero (a touching ray), is the hit.
  roots.clear();
  for (const CsgNode& c : nodes)
    if (c.kind == CsgNode::Kind::Leaf) {
      const RayPolynomial& p = polys[c.value];
      for (double r : rootsIn(p.c, p.degree, entry, exit)) roots.push_back(r);
    }
  std::sort(roots.begin(), roots.end());
  for (size_t k = 0; k < roots.size(); ++k) {
    const double next = k + 1 < roots.size() ? roots[k + 1] : exit;
    if (combine(polys, roots[k]) >= 0.0 || (next > roots[k] && combine(polys, 0.5 * (roots[k] + next)) > 0.0))
      return roots[k];
  }
  return std::nullopt;
}

}  // namespace pf::field
