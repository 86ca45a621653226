// Lowering of the `matrix` type (the Lowerer, lowerer.h): a 4x4 matrix is 16 float values,
// row-major (value 4 r + c is row r, column c), so every operation becomes scalar float
// instructions that the passes fold, share and hoist like any other -- a matrix built from
// uniform values costs nothing per pixel. Products with points, vectors and normals; the
// constructors; transpose, determinant and inverse by cofactors; the context's space transforms
// as matrices (docs/language.md, "Matrices").
#include "compiler/lowerer.h"

#include <array>
#include <optional>
#include <utility>

namespace pf::lowering {

// The sum of a * b over the pairs, as the space transforms do it: a literal 0 on either side
// drops the term, a literal 1 leaves the other factor -- so a matrix of literals (matrix(1.0),
// a translation) costs only the terms that are there.
int Lowerer::sumOfProducts(const std::vector<std::pair<int, int>>& terms) {
  int sum = -1;
  for (const auto& [a, b] : terms) {
    int t;
    if (isConstF(a, 0.0f) || isConstF(b, 0.0f)) t = -1;
    else if (isConstF(a, 1.0f)) t = b;
    else if (isConstF(b, 1.0f)) t = a;
    else t = fmul(a, b);
    sum = sumTerms(sum, t);
  }
  return sum < 0 ? constF(0.0f) : sum;
}

Binding Lowerer::matrixTimes(const Binding& m, const Binding& v, const Type& result) {
  Binding out;
  out.type = result;
  auto at = [&](int r, int c) { return m.comps[static_cast<size_t>(r * 4 + c)]; };
  switch (result.base) {
    case BaseType::Matrix:  // (m v)[r][c] = sum_k m[r][k] v[k][c]
      for (int r = 0; r < 4; ++r)
        for (int c = 0; c < 4; ++c) {
          std::vector<std::pair<int, int>> terms;
          for (int k = 0; k < 4; ++k) terms.push_back({at(r, k), v.comps[static_cast<size_t>(k * 4 + c)]});
          out.comps.push_back(sumOfProducts(terms));
        }
      return out;
    case BaseType::Point:  // homogeneous: all four rows and columns
      for (int r = 0; r < 4; ++r) {
        std::vector<std::pair<int, int>> terms;
        for (int k = 0; k < 4; ++k) terms.push_back({at(r, k), v.comps[static_cast<size_t>(k)]});
        out.comps.push_back(sumOfProducts(terms));
      }
      return out;
    case BaseType::Vector:  // a direction: the upper 3x3 (no translation)
      for (int r = 0; r < 3; ++r) {
        std::vector<std::pair<int, int>> terms;
        for (int k = 0; k < 3; ++k) terms.push_back({at(r, k), v.comps[static_cast<size_t>(k)]});
        out.comps.push_back(sumOfProducts(terms));
      }
      return out;
    default: {  // a normal: the inverse transpose of the upper 3x3, cofactor(m3) / det(m3)
      const std::array<int, 9> cof = cofactors3(m);
      const int det = sumOfProducts({{at(0, 0), cof[0]}, {at(0, 1), cof[1]}, {at(0, 2), cof[2]}});
      for (int r = 0; r < 3; ++r) {
        std::vector<std::pair<int, int>> terms;
        for (int k = 0; k < 3; ++k) terms.push_back({cof[static_cast<size_t>(r * 3 + k)], v.comps[static_cast<size_t>(k)]});
        out.comps.push_back(emit(Op::FDiv, ValueClass::F32, false, sumOfProducts(terms), det));
      }
      return out;
    }
  }
}

// The cofactors of m's upper 3x3, row-major: C[r][c] = (-1)^(r+c) times the minor without row r
// and column c. The inverse transpose is C / det, det = sum_c m[0][c] C[0][c].
std::array<int, 9> Lowerer::cofactors3(const Binding& m) {
  auto at = [&](int r, int c) { return m.comps[static_cast<size_t>(r * 4 + c)]; };
  std::array<int, 9> out;
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) {
      const int r0 = r == 0 ? 1 : 0, r1 = r == 2 ? 1 : 2, c0 = c == 0 ? 1 : 0, c1 = c == 2 ? 1 : 2;
      const int minor = fsub(fmul(at(r0, c0), at(r1, c1)), fmul(at(r0, c1), at(r1, c0)));
      out[static_cast<size_t>(r * 3 + c)] = (r + c) % 2 ? emit(Op::FNeg, ValueClass::F32, false, minor) : minor;
    }
  return out;
}

// The 3x3 determinant of rows rows[0..2], columns cols[0..2] of m.
int Lowerer::minor3(const Binding& m, const int rows[3], const int cols[3]) {
  auto at = [&](int r, int c) { return m.comps[static_cast<size_t>(rows[r] * 4 + cols[c])]; };
  int sum = -1;
  for (int c = 0; c < 3; ++c) {
    const int c0 = c == 0 ? 1 : 0, c1 = c == 2 ? 1 : 2;
    const int sub = fsub(fmul(at(1, c0), at(2, c1)), fmul(at(1, c1), at(2, c0)));
    const int term = fmul(at(0, c), sub);
    sum = sum < 0 ? term : (c == 1 ? fsub(sum, term) : fadd(sum, term));
  }
  return sum;
}

// transpose(), determinant(), inverse(), the constructors and the space transforms' matrices;
// null where `f` is none of them.
std::optional<Binding> Lowerer::matrixCall(const std::string& f, const Expr& e, const std::vector<Binding>& args) {
  Binding out;
  out.type = e.type;
  auto farg = [&](size_t i) { return toFloat(args[i].comps[0]); };
  if (f == "matrix") {
    if (args.size() == 1) {
      const int s = farg(0), zero = constF(0.0f);
      for (int k = 0; k < 16; ++k) out.comps.push_back(k % 5 == 0 ? s : zero);
    } else {
      for (size_t i = 0; i < 16; ++i) out.comps.push_back(farg(i));
    }
    return out;
  }
  if (f == "transpose") {
    for (int r = 0; r < 4; ++r)
      for (int c = 0; c < 4; ++c) out.comps.push_back(args[0].comps[static_cast<size_t>(c * 4 + r)]);
    return out;
  }
  if (f == "determinant" || f == "inverse") {
    // Laplace expansion along the first row with the 4 cofactors of its elements; inverse()
    // needs all 16: inverse[c][r] = (-1)^(r+c) minor(r, c) / det.
    const Binding& m = args[0];
    auto cofactor = [&](int r, int c) {
      int rows[3], cols[3];
      for (int k = 0, i = 0; k < 4; ++k)
        if (k != r) rows[i++] = k;
      for (int k = 0, i = 0; k < 4; ++k)
        if (k != c) cols[i++] = k;
      const int minor = minor3(m, rows, cols);
      return (r + c) % 2 ? emit(Op::FNeg, ValueClass::F32, false, minor) : minor;
    };
    int first_row[4];
    for (int c = 0; c < 4; ++c) first_row[c] = cofactor(0, c);
    std::vector<std::pair<int, int>> terms;
    for (int c = 0; c < 4; ++c) terms.push_back({m.comps[static_cast<size_t>(c)], first_row[c]});
    const int det = sumOfProducts(terms);
    if (f == "determinant") return scalar(e.type, det);
    out.comps.assign(16, -1);
    for (int r = 0; r < 4; ++r)
      for (int c = 0; c < 4; ++c)
        out.comps[static_cast<size_t>(c * 4 + r)] =
            emit(Op::FDiv, ValueClass::F32, false, r == 0 ? first_row[c] : cofactor(r, c), det);
    return out;
  }
  if (f == "object_matrix" || f == "eye_from_object_matrix" || f == "eye_matrix" || f == "clip_matrix") {
    // The context's column-major matrices (as object(), eye_from_object(), eye(), clip() use).
    const StateValue s = f == "object_matrix"            ? StateValue::InvModelview
                         : f == "eye_from_object_matrix" ? StateValue::Modelview
                         : f == "eye_matrix"             ? StateValue::InvProjection
                                                         : StateValue::Projection;
    for (int r = 0; r < 4; ++r)
      for (int c = 0; c < 4; ++c) out.comps.push_back(state(static_cast<StateValue>(static_cast<int>(s) + c * 4 + r)));
    return out;
  }
  if (f == "screen_matrix") {
    // screen(): x' = sx x + ox w, y' = sy y + oy w, z' = sz z + oz w, w' = w.
    const int zero = constF(0.0f);
    out.comps.assign(16, zero);
    out.comps[0] = state(StateValue::ViewportScaleX);
    out.comps[3] = state(StateValue::ViewportOffsetX);
    out.comps[5] = state(StateValue::ViewportScaleY);
    out.comps[7] = state(StateValue::ViewportOffsetY);
    out.comps[10] = state(StateValue::DepthScale);
    out.comps[11] = state(StateValue::DepthOffset);
    out.comps[15] = constF(1.0f);
    return out;
  }
  return std::nullopt;
}

}  // namespace pf::lowering
