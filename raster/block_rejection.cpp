// BlockRejection (see block_rejection.h): the pixel program's leading part in interval
// arithmetic over a whole block.
#include "raster/block_rejection.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <limits>

#include "raster/limits.h"

namespace pf {
namespace {

using Range = BlockRejection::Range;

constexpr double kInf = std::numeric_limits<double>::infinity();
const Range kUnknown{-kInf, kInf, true};
const Range kUnknownBool{0.0, 1.0, false};

// Widened past what float rounding of one operation can do to any lane's value (a float result
// is within 2^-24 relative of the exact one, or within the smallest normal near zero; the
// double arithmetic here adds far less).
Range widen(double lo, double hi) {
  if (std::isnan(lo) || std::isnan(hi)) return kUnknown;
  const double tiny = 1.2e-38;
  lo -= std::abs(lo) * 0x1p-22 + tiny;
  hi += std::abs(hi) * 0x1p-22 + tiny;
  return {lo, hi, false};
}
Range point(double v) { return std::isnan(v) ? kUnknown : Range{v, v, false}; }
Range boolean(bool can_be_false, bool can_be_true) {
  return {can_be_false ? 0.0 : 1.0, can_be_true ? 1.0 : 0.0, false};
}
bool certainlyTrue(const Range& r) { return r.lo == 1.0 && !r.maybe_nan; }
bool certainlyFalse(const Range& r) { return r.hi == 0.0 && !r.maybe_nan; }
Range hull(const Range& a, const Range& b) {
  return {std::min(a.lo, b.lo), std::max(a.hi, b.hi), a.maybe_nan || b.maybe_nan};
}

// a + b etc. over ranges; infinities that meet (inf - inf, 0 * inf) may make NaN.
Range add(const Range& a, const Range& b) {
  const double lo = a.lo + b.lo, hi = a.hi + b.hi;
  Range r = widen(std::isnan(lo) ? -kInf : lo, std::isnan(hi) ? kInf : hi);
  // Some lane may add +inf to -inf when one range reaches +inf and the other -inf.
  const bool opposite_infinities = (a.hi == kInf && b.lo == -kInf) || (a.lo == -kInf && b.hi == kInf);
  r.maybe_nan = a.maybe_nan || b.maybe_nan || opposite_infinities;
  return r;
}
Range negate(const Range& a) { return {-a.hi, -a.lo, a.maybe_nan}; }
Range mul(const Range& a, const Range& b) {
  double lo = kInf, hi = -kInf;
  bool nan = a.maybe_nan || b.maybe_nan;
  for (double x : {a.lo, a.hi})
    for (double y : {b.lo, b.hi}) {
      const double p = x * y;
      if (std::isnan(p)) {  // 0 * inf
        nan = true;
        continue;
      }
      lo = std::min(lo, p);
      hi = std::max(hi, p);
    }
  if (lo > hi) return kUnknown;
  // 0 * inf may also arise inside the ranges when one spans 0 and the other reaches infinity.
  if ((a.lo <= 0 && a.hi >= 0 && (std::isinf(b.lo) || std::isinf(b.hi))) ||
      (b.lo <= 0 && b.hi >= 0 && (std::isinf(a.lo) || std::isinf(a.hi))))
    nan = true;
  Range r = widen(lo, hi);
  r.maybe_nan = nan;
  return r;
}
Range square(const Range& a) {
  if (a.lo >= 0 || a.hi <= 0) return mul(a, a);  // one sign: the product's ends are the squares
  Range r = widen(0.0, std::max(a.lo * a.lo, a.hi * a.hi));
  r.lo = 0.0;  // a float square is never negative
  r.maybe_nan = a.maybe_nan;
  return r;
}
Range div(const Range& a, const Range& b) {
  if (b.lo <= 0.0 && b.hi >= 0.0) return kUnknown;  // a divisor that may be 0 (or -0)
  return mul(a, {1.0 / b.hi, 1.0 / b.lo, b.maybe_nan});
}

bool isInterpOp(Op op) {
  return op == Op::XAdd || op == Op::XSub || op == Op::XNeg || op == Op::XMulF || op == Op::XDivF ||
         op == Op::XMov || op == Op::XLoadVertex || op == Op::XSel || op == Op::XLoadVertexAt;
}

}  // namespace

RegionVerdict BlockRejection::verdict(const PixelProgram& program, const uint32_t* record, const RasterState& state,
                                      int x0, int y0, int x1, int y1) {
  if (x1 <= x0 || y1 <= y0) return RegionVerdict::Rejected;  // no pixel at all
  // Acceptance: no coverage Retire (pc <= last_coverage_retire) reached by any lane on the path
  // the uniform branches take, and the walk got past the last of them.
  const size_t coverage_end = program.last_coverage_retire >= 0 ? static_cast<size_t>(program.last_coverage_retire) + 1 : 0;
  bool coverage_retire_may_run = program.last_coverage_retire < 0;
  regs_.assign(program.num_regs, kUnknown);
  if (program.num_regs > kRegY) {
    regs_[kRegX] = {x0 + 0.5, x1 - 0.5, false};
    regs_[kRegY] = {y0 + 0.5, y1 - 0.5, false};
  }
  // An operand read as a float, an int or a bool (the instruction says which).
  enum class As { Float, Int, Bool, Any };
  auto read = [&](uint32_t o, As as) -> Range {
    if (o == kNoOperand) return kUnknown;
    const uint32_t i = operandIndex(o);
    uint32_t bits;
    switch (operandKind(o)) {
      case OperandKind::Reg: return i < regs_.size() ? regs_[i] : kUnknown;
      case OperandKind::Uniform: bits = record[i]; break;
      case OperandKind::Const:
        if (i >= program.constants.size()) return kUnknown;
        bits = program.constants[i];
        break;
      default: return kUnknown;
    }
    switch (as) {
      case As::Float: return point(std::bit_cast<float>(bits));
      case As::Int: return point(static_cast<int32_t>(bits));
      case As::Bool: return point(bits != 0 ? 1.0 : 0.0);
      case As::Any: return kUnknown;  // bits of no known class
    }
    return kUnknown;
  };

  // The masks' nesting: for each open MaskIf, its condition and whether the else part runs.
  struct Frame {
    Range cond;
    bool in_else;
  };
  Frame frames[kMaxProgramNesting];
  int depth = 0;
  // Whether the current instruction certainly runs for every lane still alive (true), certainly
  // for none (dead: skipped), or for some.
  auto regionState = [&](bool& certain) {
    certain = true;
    for (int k = 0; k < depth; ++k) {
      const bool runs_all = frames[k].in_else ? certainlyFalse(frames[k].cond) : certainlyTrue(frames[k].cond);
      const bool runs_none = frames[k].in_else ? certainlyTrue(frames[k].cond) : certainlyFalse(frames[k].cond);
      if (runs_none) return false;  // dead
      if (!runs_all) certain = false;
    }
    return true;
  };

  // Nothing after the last early Retire can reject the block.
  const size_t n = std::min(program.code.size(), static_cast<size_t>(program.last_early_retire) + 1);
  size_t steps = 0;
  size_t pc = 0;
  for (; pc < n && steps < 4 * program.code.size(); ++steps) {
    const Instr& in = program.code[pc++];
    bool certain;
    const bool live = regionState(certain);
    switch (in.op) {
      case Op::MaskIf:
        if (depth >= kMaxProgramNesting) return RegionVerdict::Unknown;
        frames[depth++] = {live ? read(in.b == kNoOperand ? in.a : in.b, As::Bool) : kUnknownBool, false};
        continue;
      case Op::MaskElse:
        if (depth > 0) frames[depth - 1].in_else = true;
        continue;
      case Op::MaskEnd:
        if (depth > 0) --depth;
        continue;
      case Op::JmpIfNone: continue;  // an optimisation of the executor: fall through
      default: break;
    }
    if (!live) continue;
    switch (in.op) {
      case Op::Retire:
        if (certain) return RegionVerdict::Rejected;  // every lane still alive leaves: nothing is drawn
        if (pc <= coverage_end) coverage_retire_may_run = true;  // (pc is already past it)
        continue;
      case Op::Jmp: pc = in.a; continue;
      case Op::JmpIfNot: {  // uniform
        const Range b = read(in.b, As::Bool);
        if (certainlyFalse(b)) pc = in.a;
        else if (!certainlyTrue(b)) return RegionVerdict::Unknown;
        continue;
      }
      case Op::LoopBegin: case Op::LoopTest: case Op::Break: case Op::Continue: case Op::LoopContinue:
      case Op::LoopBack: case Op::LoopEnd:
        return RegionVerdict::Unknown;  // loops are not followed: nothing after them is used
      default: break;
    }
    if (isInterpOp(in.op) || in.dst == kNoOperand || operandKind(in.dst) != OperandKind::Reg) continue;
    const uint32_t dst = operandIndex(in.dst);
    if (dst >= regs_.size()) return RegionVerdict::Unknown;
    auto f = [&](uint32_t o) { return read(o, As::Float); };
    auto iv = [&](uint32_t o) { return read(o, As::Int); };
    auto bv = [&](uint32_t o) { return read(o, As::Bool); };
    Range r = kUnknown;
    switch (in.op) {
      case Op::FAdd: r = add(f(in.a), f(in.b)); break;
      case Op::FSub: r = add(f(in.a), negate(f(in.b))); break;
      case Op::FMul:
        // x * x is a square: never below 0 (as a product of two independent ranges could be).
        r = in.a == in.b ? square(f(in.a)) : mul(f(in.a), f(in.b));
        break;
      case Op::FDiv: r = div(f(in.a), f(in.b)); break;
      case Op::FNeg: r = negate(f(in.a)); break;
      case Op::FAbs: {
        const Range a = f(in.a);
        r = a.lo >= 0 ? a : a.hi <= 0 ? negate(a) : Range{0.0, std::max(-a.lo, a.hi), a.maybe_nan};
        break;
      }
      case Op::FMin: case Op::FMax: {  // the C library's fmin/fmax: a NaN side gives the other
        const Range a = f(in.a), b = f(in.b);
        if (a.maybe_nan || b.maybe_nan) break;
        r = in.op == Op::FMin ? Range{std::min(a.lo, b.lo), std::min(a.hi, b.hi), false}
                              : Range{std::max(a.lo, b.lo), std::max(a.hi, b.hi), false};
        break;
      }
      case Op::FSqrt: {
        const Range a = f(in.a);
        if (a.hi < 0) break;
        r = widen(std::sqrt(std::max(a.lo, 0.0)), std::sqrt(a.hi));
        r.maybe_nan = a.maybe_nan || a.lo < 0;
        break;
      }
      case Op::FLt: case Op::FLe: case Op::FEq: case Op::FNe: {
        const Range a = f(in.a), b = f(in.b);
        const bool nan = a.maybe_nan || b.maybe_nan;
        bool can_true, can_false;
        if (in.op == Op::FLt) {
          can_true = a.lo < b.hi;
          can_false = a.hi >= b.lo || nan;
        } else if (in.op == Op::FLe) {
          can_true = a.lo <= b.hi;
          can_false = a.hi > b.lo || nan;
        } else {
          const bool can_equal = a.lo <= b.hi && b.lo <= a.hi;
          const bool can_differ = !(a.lo == a.hi && b.lo == b.hi && a.lo == b.lo) || nan;
          can_true = in.op == Op::FEq ? can_equal : can_differ;
          can_false = in.op == Op::FEq ? can_differ : can_equal;
        }
        r = boolean(can_false, can_true);
        break;
      }
      case Op::BAnd: case Op::BOr: {
        const Range a = bv(in.a), b = bv(in.b);
        r = in.op == Op::BAnd ? Range{std::min(a.lo, b.lo), std::min(a.hi, b.hi), false}
                              : Range{std::max(a.lo, b.lo), std::max(a.hi, b.hi), false};
        break;
      }
      case Op::BNot: {
        const Range a = bv(in.a);
        r = {1.0 - a.hi, 1.0 - a.lo, false};
        break;
      }
      case Op::IAdd: case Op::ISub: case Op::IMul: {
        const Range a = iv(in.a), b = iv(in.b);
        Range s = in.op == Op::IAdd ? add(a, b) : in.op == Op::ISub ? add(a, negate(b)) : mul(a, b);
        // Wrapping past int32 is not modelled.
        if (s.lo >= -2147483648.0 && s.hi <= 2147483647.0)
          r = {std::ceil(s.lo - 0.5), std::floor(s.hi + 0.5), false};
        break;
      }
      case Op::ILt: case Op::ILe: case Op::IEq: case Op::INe: {
        const Range a = iv(in.a), b = iv(in.b);
        if (in.op == Op::ILt) r = boolean(a.hi >= b.lo, a.lo < b.hi);
        else if (in.op == Op::ILe) r = boolean(a.hi > b.lo, a.lo <= b.hi);
        else {
          const bool can_equal = a.lo <= b.hi && b.lo <= a.hi;
          const bool can_differ = !(a.lo == a.hi && b.lo == b.hi && a.lo == b.lo);
          r = in.op == Op::IEq ? boolean(can_differ, can_equal) : boolean(can_equal, can_differ);
        }
        break;
      }
      case Op::I2F: r = widen(iv(in.a).lo, iv(in.a).hi); break;
      case Op::CrossSign: {
        // sign(a d - b c), exact per lane: the sign of the range of the exact value.
        const Range s = add(mul(f(in.a), f(in.d)), negate(mul(f(in.b), f(in.c))));
        if (s.maybe_nan) break;
        r = {s.lo > 0 ? 1.0 : s.hi < 0 ? -1.0 : (s.lo == 0 ? 0.0 : -1.0),
             s.hi < 0 ? -1.0 : s.lo > 0 ? 1.0 : (s.hi == 0 ? 0.0 : 1.0), false};
        break;
      }
      case Op::Sel: {
        const Range c = bv(in.a);
        const uint32_t pick = certainlyTrue(c) ? in.b : certainlyFalse(c) ? in.c : kNoOperand;
        if (pick != kNoOperand) r = operandKind(pick) == OperandKind::Reg ? read(pick, As::Any) : kUnknown;
        else if (operandKind(in.b) == OperandKind::Reg && operandKind(in.c) == OperandKind::Reg)
          r = hull(read(in.b, As::Any), read(in.c, As::Any));
        break;
      }
      case Op::Mov:
        if (operandKind(in.a) == OperandKind::Reg) r = read(in.a, As::Any);
        break;
      case Op::LoadState: r = point(stateValue(state, in.imm)); break;
      default: break;  // unknown: Z tests, fields, noise, the rest
    }
    // A merge value written under a mask some lanes may not be in keeps their old values.
    regs_[dst] = in.masked_write && !certain ? hull(regs_[dst], r) : r;
  }
  // Accepted when the walk followed the whole leading part (not cut short by the step limit) and
  // no coverage Retire on its path could run.
  if (pc >= n && !coverage_retire_may_run && program.covered) return RegionVerdict::Accepted;
  return RegionVerdict::Unknown;
}

}  // namespace pf
