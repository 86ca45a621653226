// IR dump (pfc --emit=ir): values as %N, u/v marking uniform or varying.
#include "compiler/ir.h"

#include <cstring>

namespace pf {

std::string irValueName(const IrFunction& f, int v) {
  if (v < 0) return "";
  const Value& x = f.values[v];
  switch (x.origin) {
    case Value::Origin::Const: {
      if (x.cls == ValueClass::F32) {
        float fl;
        std::memcpy(&fl, &x.bits, 4);
        char buf[32];
        std::snprintf(buf, sizeof buf, "%g", static_cast<double>(fl));
        return buf;
      }
      return std::to_string(static_cast<int32_t>(x.bits));
    }
    case Value::Origin::Param: return "param[" + std::to_string(x.index) + "]";
    case Value::Origin::Builtin: return x.index == 0 ? "X" : x.index == 1 ? "Y" : "Z";
    case Value::Origin::FieldPoint: return x.index == 0 ? "p.x" : x.index == 1 ? "p.y" : "p.z";
    case Value::Origin::Temp: break;
  }
  return std::string(x.varying ? "v%" : "u%") + std::to_string(v);
}

namespace {

std::string valueName(const IrFunction& f, int v) { return irValueName(f, v); }

void dumpBlock(const IrFunction& f, const IrBlock& b, int depth, std::string& out) {
  std::string pad(static_cast<size_t>(depth) * 2 + 2, ' ');
  for (const IrNode& n : b) {
    if (n.kind == IrNode::Kind::Loop) {
      out += pad + (n.varying_loop ? "loop  (varying: masked)\n" : "loop  (uniform)\n");
      dumpBlock(f, *n.cond_block, depth + 1, out);
      out += pad + "  while " + valueName(f, n.cond) + "\n";
      dumpBlock(f, *n.body_block, depth + 1, out);
      out += pad + "continue:\n";
      dumpBlock(f, *n.step_block, depth + 1, out);
      out += pad + "end loop\n";
      continue;
    }
    if (n.kind == IrNode::Kind::If) {
      out += pad + "if " + valueName(f, n.cond) + (f.values[n.cond].varying ? "  (varying: masked)" : "  (uniform: branch)") + "\n";
      dumpBlock(f, *n.then_block, depth + 1, out);
      out += pad + "else\n";
      dumpBlock(f, *n.else_block, depth + 1, out);
      out += pad + "end\n";
      continue;
    }
    const IrInst& in = n.inst;
    out += pad;
    if (in.dst >= 0) out += valueName(f, in.dst) + " = ";
    out += opText(in.op, in.imm);
    bool first = true;
    for (int o : {in.a, in.b, in.c, in.d}) {
      if (o < 0) continue;
      out += (first ? " " : ", ") + valueName(f, o);
      first = false;
    }
    if (in.op == Op::XLoadVertex || in.op == Op::LoadState || in.op == Op::InterpReturn || in.op == Op::InterpShared ||
        in.op == Op::HasKinds || in.op == Op::HasNamed || in.op == Op::InterpNamedReturn)
      out += (first ? " imm=" : ", imm=") + std::to_string(in.imm);
    out += "\n";
  }
}

}  // namespace

std::string dumpIr(const IrFunction& f) {
  std::string out;
  dumpBlock(f, f.body, 0, out);
  return out;
}

}  // namespace pf
