// A field as a tape: the straight-line SSA form every implicit-surface evaluator runs.
//
// One expression, several evaluators (libfive, Fidget): a field f(x, y, z) -- from the language,
// a HyperFun model or a Fidget .vm file -- becomes one FieldTape, and raster/field/ evaluates it
// as floats over a pixel block, as intervals over a box, as values with gradients, and as a
// polynomial in t along a ray. Convention (HyperFun's): f >= 0 inside, f < 0 outside.
//
// A tape is in SSA form: instruction i defines value i, and its operands are earlier values.
// FieldTapeBuilder shares equal instructions (hash-consing) and folds constants, so a tape has
// no duplicate work; simplify() drops the unchosen side of min/max where an interval evaluation
// proved one side dominates (Keeter 2020, "tape simplification"), then removes dead code.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

namespace pf::field {

class SampledGrid;  // compiler/field/sampled_grid.h

// The longest tape a front end builds (a HyperFun model or a language field unrolls its loops
// and calls): past it, compiling is an error -- a hostile or runaway model must not take
// seconds and gigabytes before it is refused (the largest shipped model, Prospero, has 7,866).
constexpr size_t kMaxFieldTapeSize = 1u << 18;

// The operations every evaluator implements. Unary ops read `a`; binary ops read `a` and `b`;
// Select reads all three.
//
// Floor is a step function (HyperFun's floor, int and the attribute library's patterns need it):
// its derivative is 0 wherever it is defined (everywhere but at the integers, where it jumps),
// and its interval over [lo, hi] is [floor(lo), floor(hi)] -- exact in float, no rounding.
//
// NoisePerm and NoiseGradX/Y/Z are look-ups in HyperFun's Perlin noise tables
// (compiler/field/perlin_tables.h) at index floor(a): step functions like Floor (derivative 0,
// constant between the integers), whose interval is the least and greatest entry the index
// interval reaches. hfA_NoiseP and hfA_Turbulence build noise3 from them and the arithmetic.
//
// Point-dependent choices (HyperFun's `if` on x, the language's `if` on p): Less and LessEq give
// 1 where a < b (a <= b) and 0 elsewhere, NaN included (C's comparisons); Select gives b where
// a != 0 and c elsewhere -- only the chosen operand's value, so an unchosen branch's inf or NaN
// (a guarded division) never reaches the result. Every evaluator computes both branches; the
// interval form decides a Select over a box when its condition's interval excludes 0 or is 0,
// and tape simplification then drops the other branch, as it drops a min/max side.
enum class FieldOp : uint8_t {
  X, Y, Z, Const,                               // leaves
  Neg, Abs, Square, Sqrt, Exp, Log, Sin, Cos,   // unary
  Atan,                                         // unary (after the others: Fidget has no atan)
  Floor,                                        // unary: the largest integer <= a (not Fidget's)
  NoisePerm, NoiseGradX, NoiseGradY, NoiseGradZ,  // unary: HyperFun's Perlin tables at floor(a)
  Add, Sub, Mul, Div, Min, Max,                 // binary
  Less, LessEq,                                 // binary: 1 or 0
  Select,                                       // ternary: a != 0 ? b : c
  Sample,                                       // leaf: the tape's grid number `value` at the point
};

// 0, 1, 2 or 3 (inline: tape simplification and the slot programs ask it of every instruction).
constexpr int fieldOpArity(FieldOp op) {
  switch (op) {
    case FieldOp::X: case FieldOp::Y: case FieldOp::Z: case FieldOp::Const: case FieldOp::Sample: return 0;
    case FieldOp::Neg: case FieldOp::Abs: case FieldOp::Square: case FieldOp::Sqrt:
    case FieldOp::Exp: case FieldOp::Log: case FieldOp::Sin: case FieldOp::Cos: case FieldOp::Atan:
    case FieldOp::Floor: case FieldOp::NoisePerm: case FieldOp::NoiseGradX: case FieldOp::NoiseGradY:
    case FieldOp::NoiseGradZ: return 1;
    case FieldOp::Select: return 3;
    default: return 2;
  }
}
std::string_view fieldOpName(FieldOp op);     // "add", "var-x", ... (Fidget's spelling)
// The four table look-ups (NoisePerm ... NoiseGradZ).
constexpr bool isNoiseTable(FieldOp op) {
  return op == FieldOp::NoisePerm || op == FieldOp::NoiseGradX || op == FieldOp::NoiseGradY || op == FieldOp::NoiseGradZ;
}

struct FieldInstr {
  FieldOp op = FieldOp::Const;
  uint32_t a = 0, b = 0;  // operand value indices (earlier instructions)
  float value = 0.0f;     // Const: the constant; Sample: the grid's number in FieldTape::grids
  uint32_t c = 0;         // Select's third operand
  bool operator==(const FieldInstr&) const = default;
};

// Which operand of a min or max an interval evaluation proved to be the result over a box
// (for a Select: Left is its `b`, the value where the condition holds, Right its `c`).
enum class Choice : uint8_t { Both = 0, Left = 1, Right = 2 };

struct FieldTape {
  std::vector<FieldInstr> instrs;  // SSA: value i is instrs[i]
  uint32_t result = 0;             // the field's value
  // The sampled fields (voxel arrays, seed 000 section 3) the tape's Sample leaves read.
  std::vector<std::shared_ptr<const SampledGrid>> grids;

  size_t size() const { return instrs.size(); }
  bool usesZ() const;              // false for 2D models (Fidget's without var-z; a grid reads z)
  std::string print() const;       // one "_i op args" line per instruction, Fidget-like
};

// Builds a tape instruction by instruction, sharing repeats and folding constants.
class FieldTapeBuilder {
 public:
  uint32_t x();
  uint32_t y();
  uint32_t z();
  uint32_t constant(float v);
  // The grid's interpolated value at the point (a `sample` leaf; the tape keeps the grid).
  uint32_t sample(std::shared_ptr<const SampledGrid> grid);
  uint32_t unary(FieldOp op, uint32_t a);
  uint32_t binary(FieldOp op, uint32_t a, uint32_t b);
  // cond != 0 ? if_true : if_false (a known condition picks its operand now).
  uint32_t select(uint32_t cond, uint32_t if_true, uint32_t if_false);
  size_t size() const { return tape_.instrs.size(); }

  // The finished tape with `result` as its value, dead instructions removed.
  FieldTape finish(uint32_t result);
  // The tape of `result` built so far, dead instructions removed, leaving the builder as it is:
  // for the other values a front end computes with the field's (HyperFun's attributes).
  FieldTape tapeOf(uint32_t result) const;

 private:
  uint32_t add(const FieldInstr& in);
  struct InstrHash {
    size_t operator()(const FieldInstr& in) const;
  };
  FieldTape tape_;
  std::unordered_map<FieldInstr, uint32_t, InstrHash> known_;
};

// The tape with each min/max/select whose choice is Left or Right replaced by that operand, and every
// instruction the result no longer needs removed. choices has one entry per instruction (only
// min/max entries are read). The simplified tape computes the same value wherever the choices
// hold -- bit for bit, since a min/max that returns one operand returns it unchanged.
FieldTape simplify(const FieldTape& tape, const std::vector<Choice>& choices);

// The working arrays of simplification, kept to simplify the next tape without allocating.
struct SimplifyScratch {
  std::vector<uint32_t> forward, renumber;
  std::vector<char> live;
};
// simplify(tape, choices) into `out` (not `tape` itself), reusing its storage and the scratch's:
// once they have grown to the tapes' size, simplifying allocates nothing. The same tape,
// instruction for instruction.
void simplifyInto(const FieldTape& tape, const std::vector<Choice>& choices, FieldTape& out, SimplifyScratch& scratch);

// The same tape with unreachable instructions removed and values renumbered.
FieldTape removeDeadCode(const FieldTape& tape);

}  // namespace pf::field
