// Optimization passes (see passes.h).
//
// Lowering gives most values one definition; the exceptions are the merge values of ifs and
// loops, defined in several places and, in loops, changing from one iteration to the next. An
// instruction that reads such a value is never folded or shared: two equal-looking uses of it
// may see different values.
#include "compiler/passes.h"

#include <algorithm>
#include <map>
#include <set>
#include <tuple>

#include "compiler/scalar_ops.h"

namespace pf {
namespace {

bool isEffect(Op op) {
  switch (op) {
    case Op::Bound: case Op::Kill: case Op::Retire: case Op::InterpReturn: case Op::InterpShared: case Op::ShadeOut: case Op::InterpNamedReturn:
    case Op::SurfaceCommit: case Op::FieldBox:
    case Op::FieldHit:  // reads the box FieldBox staged: never merged with another, never moved
    case Op::ZCommit: case Op::Break: case Op::Continue: case Op::OutParam: case Op::OutVertex:
    case Op::Emit: case Op::BackFacing: case Op::DepthBound:
      return true;
    default:
      return false;
  }
}

// Pure scalar instructions that evalScalar defines (foldable when their operands are constant).
bool isFoldable(Op op) { return static_cast<int>(op) <= static_cast<int>(Op::Mov) && op != Op::Mov; }

bool isCommutative(Op op) {
  switch (op) {
    case Op::FAdd: case Op::FMul: case Op::FMin: case Op::FMax: case Op::IAdd: case Op::IMul:
    case Op::IMin: case Op::IMax: case Op::FEq: case Op::FNe: case Op::IEq: case Op::INe:
    case Op::BAnd: case Op::BOr: case Op::XAdd:
      return true;
    default:
      return false;
  }
}

class Optimizer {
 public:
  Optimizer(IrFunction& f, std::vector<std::string>* explain) : f_(f), explain_(explain) {}

  PassStats run() {
    countDefs(f_.body);
    scopes_.emplace_back();
    rewrite(f_.body);
    removeDead();
    return stats_;
  }

 private:
  using Key = std::tuple<int, int, int, int, int, int>;  // op, imm, a, b, c, d
  IrFunction& f_;
  std::vector<std::string>* explain_;
  PassStats stats_;
  std::map<int, int> defs_;       // value -> number of definitions
  std::map<int, int> subst_;      // value -> the value that replaces it
  std::vector<std::map<Key, int>> scopes_;  // available expressions, innermost last
  std::map<std::pair<int, uint32_t>, int> constants_;

  void countDefs(const IrBlock& b) {
    forEachInst(b, [&](const IrInst& in) {
      if (in.dst >= 0) ++defs_[in.dst];
    });
  }

  int resolve(int v) {
    while (v >= 0) {
      auto it = subst_.find(v);
      if (it == subst_.end()) break;
      v = it->second;
    }
    return v;
  }
  bool singleDef(int v) const {
    if (v < 0) return true;
    if (f_.values[v].origin != Value::Origin::Temp) return true;
    auto it = defs_.find(v);
    return it != defs_.end() && it->second == 1;
  }
  bool isConst(int v) const { return v >= 0 && f_.values[v].origin == Value::Origin::Const; }

  int constant(ValueClass cls, uint32_t bits) {
    auto key = std::make_pair(static_cast<int>(cls), bits);
    auto it = constants_.find(key);
    if (it != constants_.end()) return it->second;
    for (size_t i = 0; i < f_.values.size(); ++i) {  // reuse lowering's constants
      const Value& v = f_.values[i];
      if (v.origin == Value::Origin::Const && v.cls == cls && v.bits == bits) return constants_[key] = static_cast<int>(i);
    }
    Value v;
    v.cls = cls;
    v.origin = Value::Origin::Const;
    v.bits = bits;
    f_.values.push_back(v);
    return constants_[key] = static_cast<int>(f_.values.size()) - 1;
  }

  void note(const IrInst& in, const std::string& what) {
    if (!explain_) return;
    std::string where = in.loc.file ? std::to_string(in.loc.line) + ":" + std::to_string(in.loc.col) + ": " : "";
    explain_->push_back(where + what);
  }

  std::string text(const IrInst& in) const {
    std::string s = opText(in.op, in.imm);
    bool first = true;
    for (int o : {in.a, in.b, in.c, in.d}) {
      if (o < 0) continue;
      s += (first ? " " : ", ") + irValueName(f_, o);
      first = false;
    }
    return s;
  }

  void rewrite(IrBlock& b) {
    for (IrNode& n : b) {
      if (n.kind == IrNode::Kind::If) {
        n.cond = resolve(n.cond);
        scoped(*n.then_block);
        scoped(*n.else_block);
        continue;
      }
      if (n.kind == IrNode::Kind::Loop) {
        // cond dominates the body; the step does not see the body (a continue may skip it).
        scopes_.emplace_back();
        rewrite(*n.cond_block);
        n.cond = resolve(n.cond);
        scoped(*n.body_block);
        scoped(*n.step_block);
        scopes_.pop_back();
        continue;
      }
      instruction(n.inst);
    }
  }

  void scoped(IrBlock& b) {
    scopes_.emplace_back();
    rewrite(b);
    scopes_.pop_back();
  }

  void instruction(IrInst& in) {
    for (int* o : {&in.a, &in.b, &in.c, &in.d}) *o = resolve(*o);
    if (in.dst < 0 || isEffect(in.op) || !singleDef(in.dst)) return;
    bool plain = singleDef(in.a) && singleDef(in.b) && singleDef(in.c) && singleDef(in.d);
    if (!plain) return;  // reads a merge value: leave it be
    // Copy propagation.
    if (in.op == Op::Mov || in.op == Op::XMov) {
      if (in.op == Op::XMov && in.imm != static_cast<int>(kAllInterpKinds)) return;
      note(in, irValueName(f_, in.dst) + " = " + text(in) + ": a copy, uses read " + irValueName(f_, in.a));
      subst_[in.dst] = in.a;
      in.dst = -1;  // dead
      ++stats_.copies;
      return;
    }
    // Constant folding.
    if (isFoldable(in.op) && (in.a < 0 || isConst(in.a)) && (in.b < 0 || isConst(in.b)) &&
        (in.c < 0 || isConst(in.c)) && (in.d < 0 || isConst(in.d))) {
      auto bits = [&](int v) { return v < 0 ? 0u : f_.values[v].bits; };
      uint32_t r = evalScalar(in.op, bits(in.a), bits(in.b), bits(in.c), bits(in.d), static_cast<uint32_t>(in.imm));
      int c = constant(f_.values[in.dst].cls, r);
      note(in, irValueName(f_, in.dst) + " = " + text(in) + ": constant operands, folded to " + irValueName(f_, c));
      subst_[in.dst] = c;
      in.dst = -1;
      ++stats_.folded;
      return;
    }
    // Common subexpressions.
    int a = in.a, b = in.b;
    if (isCommutative(in.op) && b >= 0 && b < a) std::swap(a, b);
    Key key{static_cast<int>(in.op), in.imm, a, b, in.c, in.d};
    for (auto s = scopes_.rbegin(); s != scopes_.rend(); ++s) {
      auto it = s->find(key);
      if (it == s->end()) continue;
      note(in, irValueName(f_, in.dst) + " = " + text(in) + ": computed before as " + irValueName(f_, it->second) + ", reused");
      subst_[in.dst] = it->second;
      in.dst = -1;
      ++stats_.cse;
      return;
    }
    scopes_.back()[key] = in.dst;
  }

  // ---- dead code ----
  std::set<int> live_;
  std::map<int, std::vector<const IrInst*>> def_insts_;

  void collectDefs(const IrBlock& b) {
    forEachInst(b, [&](const IrInst& in) {
      if (in.dst >= 0) def_insts_[in.dst].push_back(&in);
    });
  }

  void roots(const IrBlock& b, std::vector<int>& work) {
    for (const IrNode& n : b) {
      if (n.kind == IrNode::Kind::If) {
        work.push_back(n.cond);
        roots(*n.then_block, work);
        roots(*n.else_block, work);
      } else if (n.kind == IrNode::Kind::Loop) {
        work.push_back(n.cond);
        roots(*n.cond_block, work);
        roots(*n.body_block, work);
        roots(*n.step_block, work);
      } else if (isEffect(n.inst.op)) {
        for (int o : {n.inst.a, n.inst.b, n.inst.c, n.inst.d}) work.push_back(o);
      }
    }
  }

  void sweep(IrBlock& b) {
    IrBlock kept;
    for (IrNode& n : b) {
      if (n.kind == IrNode::Kind::If) {
        sweep(*n.then_block);
        sweep(*n.else_block);
      } else if (n.kind == IrNode::Kind::Loop) {
        sweep(*n.cond_block);
        sweep(*n.body_block);
        sweep(*n.step_block);
      } else if (!isEffect(n.inst.op) && (n.inst.dst < 0 || !live_.count(n.inst.dst))) {
        if (n.inst.dst >= 0) ++stats_.dead;  // (a rewritten instruction was counted already)
        continue;
      }
      kept.push_back(std::move(n));
    }
    b = std::move(kept);
  }

  void removeDead() {
    collectDefs(f_.body);
    std::vector<int> work;
    roots(f_.body, work);
    while (!work.empty()) {
      int v = work.back();
      work.pop_back();
      if (v < 0 || !live_.insert(v).second) continue;
      for (const IrInst* d : def_insts_[v])
        for (int o : {d->a, d->b, d->c, d->d}) work.push_back(o);
    }
    sweep(f_.body);
  }
};

}  // namespace

PassStats optimize(IrFunction& f, std::vector<std::string>* explain) {
  Optimizer o(f, explain);
  PassStats s = o.run();
  if (explain)
    explain->push_back("primitive " + f.name + ": " + std::to_string(s.folded) + " folded, " + std::to_string(s.cse) +
                       " common subexpressions, " + std::to_string(s.copies) + " copies propagated, " +
                       std::to_string(s.dead) + " dead instructions removed");
  return s;
}

}  // namespace pf
