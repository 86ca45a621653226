// Names and listings of the bytecode instructions (isa.h).
#include "compiler/isa.h"

#include <cstring>

#include "compiler/fixed_point.h"

namespace pf {

const char* opName(Op op) {
  static const char* names[] = {
      "fadd", "fsub", "fmul", "fdiv", "fmin", "fmax", "fneg", "fabs", "ffloor", "fceil", "fsqrt",
      "fsign", "fsin", "fcos", "ftan", "fasin", "facos", "fatan", "fatan2", "fpow", "fexp", "flog",
      "fnoise", "iadd", "isub", "imul", "idiv", "imod", "ineg", "imin", "imax", "iabs", "i2f",
      "f2i", "flt", "fle", "feq", "fne", "ilt", "ile", "ieq", "ine", "band", "bor", "bnot", "sel", "cross_sign",
      "qadd", "qsub", "qmul", "qdiv", "qneg", "qabs", "qlt", "qle", "qeq", "qfromf", "qfromi", "qtof",
      "qtoi", "qconv", "mov", "xadd", "xsub", "xneg", "xmulf", "xdivf", "xmov", "xloadvertex", "xsel", "loadparamat", "xloadvertexat", "loadstate", "haskinds", "hasnamed",
      "bound", "kill", "retire", "ztest", "interp_return", "interp_shared", "shadeout", "interp_named_return", "zcommit", "surfacecommit", "fieldbox", "fieldhit", "fieldgradient", "fieldcolor", "outparam", "outvertex", "emit", "backfacing", "depthbound",
      "loopbegin", "looptest", "break", "continue", "loopcontinue", "loopback", "loopend", "jmp",
      "jmpifnot", "maskif", "maskelse", "maskend", "jmpifnone"};
  static_assert(sizeof(names) / sizeof(names[0]) == static_cast<size_t>(Op::OpCount));
  return names[static_cast<size_t>(op)];
}

std::string opText(Op op, int imm) {
  std::string s = opName(op);
  if (op == Op::ZTest) return imm ? s + ".polygon" : s;  // polygon_ztest()
  if (op < Op::QAdd || op > Op::QConv || op == Op::QLt || op == Op::QLe || op == Op::QEq) return s;
  const FixedFormat f = fixedFormatOf(static_cast<uint32_t>(imm));
  if (op == Op::QToF || op == Op::QToI) return s + "<frac " + std::to_string(f.frac) + ">";
  return s + (fixedHalfOf(static_cast<uint32_t>(imm)) ? ".hi<" : ".lo<") + std::to_string(f.bits) + "," +
         std::to_string(f.frac) + ">";
}

namespace {

bool isInterpOp(Op op) {
  return op == Op::XAdd || op == Op::XSub || op == Op::XNeg || op == Op::XMulF ||
         op == Op::XDivF || op == Op::XMov || op == Op::XLoadVertex || op == Op::InterpReturn ||
         op == Op::XSel || op == Op::XLoadVertexAt || op == Op::OutVertex;
}

std::string operandText(uint32_t o, const Bytecode& b, bool pixel, bool interp) {
  if (o == kNoOperand) return "";
  uint32_t i = operandIndex(o);
  switch (operandKind(o)) {
    case OperandKind::Reg:
      if (pixel && !interp && i == kRegX) return "X";
      if (pixel && !interp && i == kRegY) return "Y";
      if (pixel && !interp && i == kRegZ) return "Z";
      if (pixel && !interp && i >= kRegP && i < kRegP + 4) return std::string("P.") + "xyzw"[i - kRegP];
      if (pixel && !interp && i >= kRegN && i < kRegN + 3) return std::string("N.") + "xyz"[i - kRegN];
      return std::string(interp ? "x" : (pixel ? "v" : "r")) + std::to_string(i);
    case OperandKind::Uniform: return std::string(interp ? "ux" : "u") + std::to_string(i);
    case OperandKind::Param: return "p" + std::to_string(i);
    case OperandKind::Const: {
      uint32_t bits = i < b.constants.size() ? b.constants[i] : 0;
      float f;
      std::memcpy(&f, &bits, 4);
      char buf[48];
      // Constants are untyped bits: small integers (denormal as floats) print as integers.
      if (bits != 0 && bits < 0x00800000u)
        std::snprintf(buf, sizeof buf, "#%u", bits);
      else if (bits >= 0xffff0000u)  // a NaN as a float: a small negative int
        std::snprintf(buf, sizeof buf, "#%d", static_cast<int32_t>(bits));
      else
        std::snprintf(buf, sizeof buf, "#%g", static_cast<double>(f));
      return buf;
    }
  }
  return "?";
}

}  // namespace

std::string disassemble(const Bytecode& b, bool pixel) {
  std::string out;
  for (size_t pc = 0; pc < b.code.size(); ++pc) {
    const Instr& in = b.code[pc];
    char head[32];
    std::snprintf(head, sizeof head, "%4zu  ", pc);
    out += head;
    out += opText(in.op, in.imm);
    bool xi = isInterpOp(in.op);
    std::vector<std::string> parts;
    bool is_jump = in.op == Op::Jmp || in.op == Op::JmpIfNot || in.op == Op::JmpIfNone || in.op == Op::LoopBack;
    if (in.dst != kNoOperand && in.op != Op::Bound)
      parts.push_back(operandText(in.dst, b, pixel, xi && in.op != Op::InterpReturn));
    if (is_jump) {
      parts.push_back("@" + std::to_string(in.a));
    } else if (in.a != kNoOperand) {
      parts.push_back(operandText(in.a, b, pixel, xi && in.op != Op::XLoadVertex && in.op != Op::XSel && in.op != Op::XLoadVertexAt));
    }
    bool b_is_float = in.op == Op::XMulF || in.op == Op::XDivF;
    if (in.b != kNoOperand) parts.push_back(operandText(in.b, b, pixel, xi && !b_is_float));
    if (in.c != kNoOperand) parts.push_back(operandText(in.c, b, pixel, in.op == Op::XSel));
    if (in.d != kNoOperand) parts.push_back(operandText(in.d, b, pixel, false));
    if (in.op == Op::Bound) parts.push_back(operandText(in.dst, b, pixel, false));
    if (in.op == Op::XLoadVertex || in.op == Op::LoadState || in.op == Op::InterpReturn || in.op == Op::HasKinds ||
        in.op == Op::HasNamed || in.op == Op::InterpNamedReturn || in.op == Op::InterpShared || in.op == Op::OutParam || in.op == Op::OutVertex || in.op == Op::Emit ||
        in.op == Op::LoadParamAt)
      parts.push_back("imm=" + std::to_string(in.imm));
    if (in.op == Op::Break && in.imm > 1) parts.push_back("levels=" + std::to_string(in.imm));
    for (size_t k = 0; k < parts.size(); ++k) out += (k ? ", " : " ") + parts[k];
    out += "\n";
  }
  return out;
}

}  // namespace pf
