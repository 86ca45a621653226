// The intermediate representation between the AST and the two bytecode programs.
//
// Structured three-address code: a tree of blocks, each a sequence of instructions and ifs.
// Every Value is defined once on any path (lowering renames variables at each assignment and
// places merge copies at the end of both branches of an if), so a uniform Value has one value
// per instance and can be passed from the setup program to the pixel program as it is.
// Each Value knows whether it is varying: that is the setup / per-pixel split.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "compiler/diagnostics.h"
#include "compiler/isa.h"
#include "compiler/types.h"

namespace pf {

enum class ValueClass : uint8_t { F32, I32, Bool, Interp };

struct Value {
  ValueClass cls = ValueClass::F32;
  bool varying = false;
  // FieldPoint: a component of a field unit's point (index 0, 1, 2: x, y, z), never in programs.
  enum class Origin : uint8_t { Temp, Const, Param, Builtin, FieldPoint } origin = Origin::Temp;
  uint32_t bits = 0;   // Const: the 32-bit pattern
  int index = -1;      // Param: slot in the parameter block; Builtin: its register; FieldPoint: axis
};

struct IrInst {
  Op op;
  int dst = -1;
  int a = -1, b = -1, c = -1, d = -1;  // Value ids (d: 4th operand of Bound)
  int imm = 0;
  SourceLoc loc;
};

struct IrNode;
using IrBlock = std::vector<IrNode>;

// An instruction, an if, or a loop. A loop runs cond_block, leaves when `cond` is false, runs
// body_block then step_block (a `continue` goes to step_block), and repeats. Values carried from
// one iteration to the next are merge values assigned before the loop and at the end of body,
// step, `continue` and `break` (Op::Break / Op::Continue).
struct IrNode {
  enum class Kind { Inst, If, Loop } kind = Kind::Inst;
  IrInst inst;
  int cond = -1;  // If, Loop: a Bool value
  std::unique_ptr<IrBlock> then_block, else_block;   // If
  std::unique_ptr<IrBlock> cond_block, body_block, step_block;  // Loop
  bool varying_loop = false;  // Loop: the iteration count can differ between pixels
};

// A parameter of a primitive, as the API must supply it.
struct ParamInfo {
  std::string name;
  Type type;                // declared type (for per-sequence-point params: with the [n])
  bool per_sequence_point;  // array parameters: outermost index = sequence point
  int offset;               // first float of this parameter in the instance's parameter block;
                            // parameter-sized: floats per sequence point of those before it
  int components;           // floats per sequence point (or in total, for per-primitive ones)
  bool parameter_sized = false;  // `T name[]`: after the fixed part (CompiledPrimitive::paramOffset)
};

struct IrFunction {
  std::string name;
  std::vector<Value> values;
  IrBlock body;
  std::vector<ParamInfo> params;
  int param_floats = 0;       // size of the parameter block
  int sequence_points = 1;    // sequence points per instance; 0: as many as given (`[]` arrays)
  int count_slot = -1;        // sequence_points == 0: the int slot that receives the count
  int sized_floats = 0;       // sequence_points == 0: floats per sequence point of `[]` arrays
  std::vector<std::string> callees;  // primitives it calls: Op::Emit's imm indexes this
  bool has_interp_data = false;
  InterpKindSet kinds_handled = 0;  // labels of its interpolation construct
  // Shared interpolators it computes itself (`spherical:` labels): Op::HasNamed's and
  // Op::InterpNamedReturn's imm indexes this.
  std::vector<std::string> named_interpolators;
  bool writes_normal = false;       // sets N: lit per pixel (Op::SurfaceCommit)
};

// Calls fn(inst) for every instruction of `b`, nested ifs and loops included, in program order.
template <class Fn>
void forEachInst(const IrBlock& b, Fn&& fn) {
  for (const IrNode& n : b) {
    if (n.kind == IrNode::Kind::If) {
      forEachInst(*n.then_block, fn);
      forEachInst(*n.else_block, fn);
    } else if (n.kind == IrNode::Kind::Loop) {
      forEachInst(*n.cond_block, fn);
      forEachInst(*n.body_block, fn);
      forEachInst(*n.step_block, fn);
    } else {
      fn(n.inst);
    }
  }
}

std::string dumpIr(const IrFunction& f);
// A value as the dumps show it: u%N / v%N (uniform / varying), a constant, param[i], X, Y, Z.
std::string irValueName(const IrFunction& f, int v);

}  // namespace pf
