// The instruction set that compiled primitives run on: one bytecode for both programs a
// primitive compiles to. The setup program runs it scalar, once per instance; the pixel program
// runs it over wide registers (one value per lane of a pixel block) under an execution mask.
// The executors are in raster/ (setup_executor.cpp; pixel_executor.cpp, whose interpreter is pixel_interpreter.cpp).
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "compiler/types.h"

namespace pf {

enum class Op : uint8_t {
  // float arithmetic
  FAdd, FSub, FMul, FDiv, FMin, FMax, FNeg, FAbs, FFloor, FCeil, FSqrt, FSign,
  // float functions, as C's (NaN outside their domain); FNoise: improved Perlin noise of (a, b, c)
  FSin, FCos, FTan, FAsin, FAcos, FAtan, FAtan2, FPow, FExp, FLog, FNoise,
  // int arithmetic (division and remainder by zero give 0: a masked-off lane must not trap)
  IAdd, ISub, IMul, IDiv, IMod, INeg, IMin, IMax, IAbs,
  I2F, F2I,
  // comparisons produce bool (0 or 1)
  FLt, FLe, FEq, FNe, ILt, ILe, IEq, INe,
  BAnd, BOr, BNot,
  Sel,  // dst = a ? b : c  (any 32-bit class)
  CrossSign,  // dst = sign(a * d - b * c) as -1, 0, 1, exact (evaluated in double)
  // fixed<bits,frac> (compiler/fixed_point.h has the rules): a value is two words, its raw
  // integer's low and high 32 bits; operands are the pairs (a, b) and (c, d). Each instruction
  // gives one word of its result: imm = fixedImm(result format, half).
  QAdd, QSub, QMul, QDiv, QNeg, QAbs,
  QLt, QLe, QEq,  // bool (both operands of one format; imm unused)
  QFromF, QFromI,  // float / int a converted
  QToF, QToI,      // (a, b) of imm's frac converted to float / int (imm's half unused)
  QConv,           // (a, b) of frac c (an int constant) converted to imm's format
  Mov,
  // interpolator_data: one value per shading-parameter channel of the instance
  XAdd, XSub, XNeg, XMulF, XDivF, XMov,
  XLoadVertex,  // dst = the channels of sequence point `imm`
  XSel,         // dst = a ? b : c, per channel of kinds `imm` (a is a bool)
  // parameter-sized arrays (setup only): reads at an index computed at run time; an index
  // outside the instance's parameters or sequence points reads zeros
  LoadParamAt,    // dst = parameter slot a + imm (a is an int; a < 0: outside)
  XLoadVertexAt,  // dst = the channels of sequence point a (an int)
  // state of the instance's GL context: imm = StateValue
  LoadState,
  HasKinds,  // dst = the instance has shading channels of a kind in set imm (bool)
  HasNamed,  // dst = the instance has channels bound to shared interpolator named_interpolators[imm]
  // effects
  Bound,         // setup: screen bound (a, b, c, dst) = (xmin, ymin, xmax, ymax)
  Kill,          // setup: the instance draws nothing
  Retire,        // pixel: the active lanes leave the program without writing anything
  ZTest,         // pixel: dst = the context's depth test of a against the depth buffer (and the
                 // clip planes); imm 1: a polygon's fragment, which the polygon stipple tests too
  InterpReturn,  // pixel: write channels of kinds `imm` (bit set) from interp operand a
  InterpShared,  // pixel: run the shared interpolators bound to channels of kinds `imm`, with
                 // the surface point P = (a, b, c, d)
  ShadeOut,      // pixel, in a shared interpolator: its value (a, b, c, d)
  InterpNamedReturn,  // pixel: write (a, b, c, d) into the channels bound to the shared
                      // interpolator named_interpolators[imm] (the primitive computes it)
  ZCommit,       // pixel: a is the Z to write for lanes alive at the end
  SurfaceCommit, // pixel: the surface for per-pixel lighting: imm 0: P = (a, b, c, d); 1: N = (a, b, c)
  // implicit surfaces (raster/field/ray_caster.h): a field of the context (its id, uniform) along
  // each pixel's object-space ray from the near plane (t = 0) to the far plane (t = 1)
  FieldBox,      // pixel: the box of the next FieldHit: imm 0: its minimum (a, b, c); 1: its maximum
  FieldHit,      // pixel: dst = t of the first surface point in the box (+inf: none), for field a,
                 // root-finding method b (0 auto, 1 analytic, 2 interval, 3 march, 4 sphere), its
                 // parameter c
  FieldGradient, // pixel: dst = component (imm & 3) of the gradient of field d at (a, b, c);
                 // imm & 4: by central differences instead of the derived gradient form
  FieldColor,    // pixel: dst = component imm (0 red, 1 green, 2 blue) of the colour field d's
                 // attributes give at (a, b, c) (field_color(); HyperFun's s[1..3])
  // calls of one primitive from another (setup; paper section 5: polygon -> screen_triangle):
  // the arguments fill an outgoing parameter block, then Emit submits the callee's instance
  OutParam,      // setup: outgoing parameter slot imm = a
  OutVertex,     // setup: outgoing sequence point imm's channels = interp register a
  Emit,          // setup: submit an instance of callee imm with the outgoing parameters
  BackFacing,    // setup: a (bool) says the instance shows its back (two-sided lighting)
  DepthBound,    // setup: every depth the instance's pixels ztest() lies in [a, b] (window Z):
                 // the renderer skips blocks where no such depth can pass (raster/coarse_depth.h)
  // loops (setup: jumps and a counter; pixel: masks). LoopBegin pushes a loop frame; LoopTest
  // removes the lanes whose b is false from the loop; Break / Continue remove the active lanes
  // for good / for this iteration; LoopContinue brings the continuing lanes back; LoopBack
  // counts an iteration (past the context's cap the remaining lanes, or the instance, stop and
  // the hit is reported) and jumps to a; LoopEnd pops the frame.
  LoopBegin, LoopTest, Break, Continue, LoopContinue, LoopBack, LoopEnd,
  // control flow (targets are instruction indices)
  Jmp,           // to a
  JmpIfNot,      // if uniform b is false, to a
  MaskIf,        // push: active &= varying b
  MaskElse,      // active = enclosing & !b
  MaskEnd,       // pop
  JmpIfNone,     // if no lane is active, to a
  OpCount
};

const char* opName(Op op);
// The op as listings show it: its name, and for a fixed-point instruction the word and format
// its imm selects (qmul.hi<16,8>; qtof<frac 8>).
std::string opText(Op op, int imm);

// Values of the GL context that programs can read (screen() and depth_range() use these).
enum class StateValue : uint16_t {
  ViewportScaleX, ViewportOffsetX, ViewportScaleY, ViewportOffsetY, DepthScale, DepthOffset,
  DepthNear, DepthFar,
  // 1 or 0: culled() and flat_shading() read these
  CullFront, CullBack, FrontFaceCCW, FlatShading,
  // The rasterized width of lines and size of points (line_width(), point_size()): glLineWidth
  // and glPointSize as the API rounds and clamps them (api/src/raster_modes.h), whole pixels
  LineWidth, PointSize,
  // glLineStipple (line_stipple()): the pattern (0 - 65535), the repeat factor (1 - 256), and 1
  // or 0 for GL_LINE_STIPPLE
  LineStipplePattern, LineStippleFactor, LineStippleOn,
  // glPolygonMode per face (polygon_mode(): 0 fill, 1 line, 2 point) and glPolygonOffset
  // (polygon_offset(): the factor, the units times the depth buffer's resolution;
  // polygon_offset_modes(): 1 or 0 for GL_POLYGON_OFFSET_FILL, _LINE, _POINT)
  PolygonModeFront, PolygonModeBack, OffsetFactor, OffsetUnits, OffsetFill, OffsetLine, OffsetPoint,
  // 1 or 0 for GL_POLYGON_STIPPLE (polygon_stipple(); polygon_ztest() applies the pattern)
  PolygonStippleOn,
  // 16 elements each (column-major): InvProjection + k (eye()), Projection + k (clip()),
  // InvModelview + k (object(), eye_normal()), Modelview + k (eye_from_object())
  InvProjection, Projection = InvProjection + 16, InvModelview = Projection + 16, Modelview = InvModelview + 16
};
// How many state values there are (the last matrix's 16 included).
constexpr int kStateValueCount = static_cast<int>(StateValue::Modelview) + 16;

// An operand: a kind in the top 2 bits, an index below.
enum class OperandKind : uint32_t { Reg = 0, Uniform = 1, Const = 2, Param = 3 };
constexpr uint32_t kNoOperand = 0xffffffffu;
inline uint32_t makeOperand(OperandKind k, uint32_t index) {
  return (static_cast<uint32_t>(k) << 30) | index;
}
inline OperandKind operandKind(uint32_t o) { return static_cast<OperandKind>(o >> 30); }
inline uint32_t operandIndex(uint32_t o) { return o & 0x3fffffffu; }

struct Instr {
  Op op;
  uint16_t imm = 0;
  uint32_t dst = kNoOperand;
  uint32_t a = kNoOperand, b = kNoOperand, c = kNoOperand, d = kNoOperand;
  // Pixel program: the destination is a merge value (written in several places, under
  // different masks), so only the active lanes may change. Every other value is written once,
  // and its lanes outside the mask are never read (a retired or masked-off lane never reads a
  // value defined while it was off): those instructions write all lanes, without a blend.
  // This rests on the IR's discipline -- a value read under a wider mask than its definition's
  // goes through a merge copy -- which any future hoisting or cross-scope CSE must keep.
  bool masked_write = false;
};

// How deep calls of primitives from primitives may nest (each level is an executor in setup).
constexpr int kMaxPrimitiveCallDepth = 8;
// How deep a program's loops and varying ifs may nest (the executors' frame stacks); deeper
// source is a compile error.
constexpr int kMaxProgramNesting = 64;

// The registers of the pixel program that hold the built-ins before the first instruction:
// X, Y, Z, P's 4 components (in a shared interpolator, the point its primitive set) and N's 3.
constexpr uint32_t kRegX = 0, kRegY = 1, kRegZ = 2, kRegP = 3, kRegN = 7, kFirstFreePixelReg = 10;

struct Bytecode {
  std::vector<Instr> code;
  std::vector<uint32_t> constants;  // 32-bit patterns: float, int or bool (0/1)
  uint32_t num_regs = 0;            // scalar registers (setup) or wide registers (pixel)
  uint32_t num_interp_regs = 0;     // interpolator_data registers (each: one per channel)
};

// Where the setup program leaves a value for the pixel program: the instance's uniform record
// holds `scalar_exports.size()` 32-bit slots, then `interp_exports.size()` channel vectors.
struct SetupProgram : Bytecode {
  std::vector<uint32_t> scalar_exports;  // setup operand whose value fills record slot i
  std::vector<uint32_t> interp_exports;  // setup interp register for interp record slot i
};

struct PixelProgram : Bytecode {
  uint32_t num_uniform_slots = 0;
  uint32_t num_interp_uniform_slots = 0;
  bool reads_surface = false;  // reads the built-in P or N registers (else they are not set up)
  // Has a FieldHit: its rays are those of an aligned block's pixels (raster/field/ray_caster.h),
  // so it never runs on packed lanes (PixelExecutor::runPackedBlock).
  bool casts_block_rays = false;
  // May run in a gang block (PixelExecutor::runGangBlock): lanes of several instances at once,
  // each reading its own instance's uniforms as a wide register. True unless the program reads
  // a uniform as one value for the whole block -- field searches and gradients (their field,
  // box, method), or a conditional jump on a register (a value uniform per instance, computed
  // in a loop). Its conditional jumps on record slots are fine where every instance of the gang
  // agrees on them: those slots are `branch_slots`.
  bool gangs = false;
  std::vector<uint32_t> branch_slots;
  // The last Retire before the first loop (-1: none): how far block rejection needs to look.
  int32_t last_early_retire = -1;
  // The last Retire before anything block rejection cannot follow (a depth test, a field
  // search, a loop; -1: none): the Retires that decide coverage.
  int32_t last_coverage_retire = -1;
  // The program for blocks where block rejection proves that no Retire up to
  // last_coverage_retire runs: without them and what only they read
  // (compiler/covered_program.h); null if there is none.
  std::shared_ptr<const PixelProgram> covered;
};

// Readable listing, used by `pfc --emit=setup|pixel` and tests.
std::string disassemble(const Bytecode& b, bool pixel);

}  // namespace pf
