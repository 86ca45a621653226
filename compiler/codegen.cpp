// Code generation (see codegen.h).
#include "compiler/codegen.h"

#include <algorithm>
#include <map>
#include <set>

#include "compiler/covered_program.h"

namespace pf {
namespace {

// The effects of calling another primitive: setup's, in program order (and facing() and
// depth_bound(), setup's too: they set uniform properties of the instance).
bool isCallEffect(Op op) {
  return op == Op::OutParam || op == Op::OutVertex || op == Op::Emit || op == Op::BackFacing || op == Op::DepthBound;
}

// Reads of the instance's parameters at run-time indices: only setup has the parameters.
bool isSetupOnlyLoad(Op op) { return op == Op::LoadParamAt || op == Op::XLoadVertexAt; }

bool isPixelEffect(Op op) {
  return op == Op::Retire || op == Op::ZTest || op == Op::InterpReturn || op == Op::InterpShared ||
         op == Op::ZCommit || op == Op::ShadeOut || op == Op::InterpNamedReturn || op == Op::SurfaceCommit || op == Op::FieldBox ||
         op == Op::FieldHit;
}

class Generator {
 public:
  explicit Generator(const IrFunction& f) : f_(f) {}

  CodegenResult run() {
    findPixelLoops(f_.body, false);
    collect(f_.body, {});
    markNeeded();
    // Setup.
    emitSetup(f_.body, 0);
    // Pixel (assigns the exports as it meets uniform operands).
    pixel_.num_regs = kFirstFreePixelReg;
    emitPixel(f_.body, 0, false);
    // Exports.
    result_.setup.scalar_exports.resize(scalar_slots_.size());
    for (auto& [value, slot] : scalar_slots_) result_.setup.scalar_exports[slot] = setupOperand(value);
    result_.setup.interp_exports.resize(interp_slots_.size());
    for (auto& [value, slot] : interp_slots_) result_.setup.interp_exports[slot] = operandIndex(setupOperand(value));
    pixel_.num_uniform_slots = static_cast<uint32_t>(scalar_slots_.size());
    pixel_.num_interp_uniform_slots = static_cast<uint32_t>(interp_slots_.size());
    // Block rejection (raster/block_rejection.h) follows the program up to its first loop, and
    // no further than its last `return` before it: worth trying only if there is one.
    for (size_t pc = 0; pc < pixel_.code.size() && pixel_.code[pc].op != Op::LoopBegin; ++pc)
      if (pixel_.code[pc].op == Op::Retire) pixel_.last_early_retire = static_cast<int32_t>(pc);
    for (size_t pc = 0; pc < pixel_.code.size(); ++pc) {
      const Op op = pixel_.code[pc].op;
      if (op == Op::LoopBegin || op == Op::ZTest || op == Op::FieldBox || op == Op::FieldHit || op == Op::FieldGradient ||
          op == Op::FieldColor)
        break;
      if (op == Op::Retire) pixel_.last_coverage_retire = static_cast<int32_t>(pc);
    }
    pixel_.gangs = true;
    for (const Instr& ins : pixel_.code) {
      if (ins.op == Op::FieldHit) pixel_.casts_block_rays = true;
      if (ins.op == Op::FieldHit || ins.op == Op::FieldBox || ins.op == Op::FieldGradient || ins.op == Op::FieldColor)
        pixel_.gangs = false;
      if (ins.op == Op::JmpIfNot) {
        if (operandKind(ins.b) == OperandKind::Uniform)
          pixel_.branch_slots.push_back(operandIndex(ins.b));
        else if (operandKind(ins.b) != OperandKind::Const)
          pixel_.gangs = false;
      }
    }
    if (std::optional<PixelProgram> covered = coveredVariant(pixel_))
      pixel_.covered = std::make_shared<const PixelProgram>(std::move(*covered));
    result_.pixel = std::move(pixel_);
    result_.setup.code = std::move(setup_.code);
    result_.setup.constants = std::move(setup_.constants);
    result_.setup.num_regs = setup_.num_regs;
    result_.setup.num_interp_regs = setup_.num_interp_regs;
    // depth_bound() lets the renderer skip pixels where no depth of the range passes the depth
    // test: sound only for a primitive whose pixels are drawn where ztest() passed. One that
    // never tests has nothing for the bound to describe.
    bool pixel_tests_depth = false;
    for (const Instr& ins : result_.pixel.code) pixel_tests_depth = pixel_tests_depth || ins.op == Op::ZTest;
    for (const auto& [in, conds] : roots_)
      if (in->op == Op::DepthBound && !pixel_tests_depth) {
        result_.errors.push_back({in->loc, "depth_bound() describes the depths this primitive tests with ztest(), "
                                           "but it never calls ztest(): blocks skipped by the bound would lose "
                                           "pixels the depth test does not decide"});
        break;
      }
    if (max_nesting_ > kMaxProgramNesting)
      result_.errors.push_back({deepest_, "loops and varying ifs nest " + std::to_string(max_nesting_) +
                                              " deep here (inlined functions count as a loop each); at most " +
                                              std::to_string(kMaxProgramNesting) + " fit"});
    return std::move(result_);
  }

 private:
  const IrFunction& f_;
  CodegenResult result_;
  Bytecode setup_;
  PixelProgram pixel_;
  // For each value, the instructions defining it and the uniform if-conditions around them.
  struct Def {
    const IrInst* inst;
    std::vector<int> conds;
  };
  std::map<int, std::vector<Def>> defs_;
  // What setup must compute for: its own effects (roots_), and the pixel program's operands
  // and conditions (pixel_roots_), except the values the pixel program computes itself.
  std::vector<std::pair<const IrInst*, std::vector<int>>> roots_, pixel_roots_;
  std::set<int> needed_;  // uniform values setup must compute
  // Uniform values defined inside a loop that holds per-pixel work: they change from one
  // iteration to the next, so the pixel program computes them itself.
  std::set<int> pixel_uniform_;
  // Setup loops being emitted: where their break / continue jumps must land (null: a loop
  // flattened because it is varying).
  struct JumpPatches {
    std::vector<size_t> breaks, continues;
  };
  std::vector<JumpPatches*> setup_loops_;
  std::map<int, uint32_t> setup_regs_, pixel_regs_, setup_consts_, pixel_consts_;
  std::map<int, uint32_t> scalar_slots_, interp_slots_;
  // Nesting of the frames the executors keep (setup loops; pixel loops and varying ifs).
  int nesting_ = 0, max_nesting_ = 0;
  SourceLoc deepest_;
  void enter(const IrNode& n) {
    if (++nesting_ > max_nesting_) {
      max_nesting_ = nesting_;
      deepest_ = n.inst.loc;
    }
  }

  const Value& val(int v) const { return f_.values[v]; }
  bool varying(int v) const { return v >= 0 && val(v).varying; }

  // Walks the tree once: definitions, and the roots of what setup must compute.
  void collect(const IrBlock& b, std::vector<int> conds) {
    for (const IrNode& n : b) {
      if (n.kind == IrNode::Kind::If) {
        std::vector<int> inner = conds;
        inner.push_back(n.cond);
        collect(*n.then_block, inner);
        collect(*n.else_block, inner);
        continue;
      }
      if (n.kind == IrNode::Kind::Loop) {
        collect(*n.cond_block, conds);
        std::vector<int> inner = conds;
        inner.push_back(n.cond);
        collect(*n.body_block, inner);
        collect(*n.step_block, inner);
        continue;
      }
      const IrInst& in = n.inst;
      if (in.dst >= 0) defs_[in.dst].push_back({&in, conds});
      bool pixel = (in.dst >= 0 && pixelValue(in.dst)) || isPixelEffect(in.op);
      if (pixel) pixel_roots_.push_back({&in, conds});
      if (in.op == Op::Bound || in.op == Op::Retire || in.op == Op::Break || in.op == Op::Continue ||
          isCallEffect(in.op))
        roots_.push_back({&in, conds});
    }
  }

  void need(int v, std::vector<int>& work) {
    if (v < 0 || varying(v)) return;
    if (val(v).origin != Value::Origin::Temp) return;
    if (needed_.insert(v).second) work.push_back(v);
  }

  void markNeeded() {
    std::vector<int> work;
    for (auto& [in, conds] : roots_) {
      for (int o : {in->a, in->b, in->c, in->d}) need(o, work);
      for (int c : conds) need(c, work);
    }
    for (auto& [in, conds] : pixel_roots_) {
      for (int o : {in->a, in->b, in->c, in->d})
        if (!pixel_uniform_.count(o)) need(o, work);
      for (int c : conds)
        if (!pixel_uniform_.count(c)) need(c, work);
    }
    while (!work.empty()) {
      int v = work.back();
      work.pop_back();
      for (const Def& d : defs_[v]) {
        for (int o : {d.inst->a, d.inst->b, d.inst->c, d.inst->d}) need(o, work);
        for (int c : d.conds) need(c, work);
      }
    }
  }

  static uint32_t constIndex(std::map<int, uint32_t>& pool, Bytecode& code, int v, uint32_t bits) {
    auto it = pool.find(v);
    if (it != pool.end()) return it->second;
    uint32_t idx = static_cast<uint32_t>(code.constants.size());
    code.constants.push_back(bits);
    pool[v] = idx;
    return idx;
  }

  uint32_t setupOperand(int v) {
    if (v < 0) return kNoOperand;
    const Value& x = val(v);
    switch (x.origin) {
      case Value::Origin::Const: return makeOperand(OperandKind::Const, constIndex(setup_consts_, setup_, v, x.bits));
      case Value::Origin::Param: return makeOperand(OperandKind::Param, static_cast<uint32_t>(x.index));
      case Value::Origin::Builtin: return kNoOperand;  // never uniform
      case Value::Origin::FieldPoint: return kNoOperand;  // fields become tapes, not programs
      case Value::Origin::Temp: break;
    }
    auto it = setup_regs_.find(v);
    if (it != setup_regs_.end()) return makeOperand(OperandKind::Reg, it->second);
    uint32_t idx = x.cls == ValueClass::Interp ? setup_.num_interp_regs++ : setup_.num_regs++;
    setup_regs_[v] = idx;
    return makeOperand(OperandKind::Reg, idx);
  }

  uint32_t pixelOperand(int v) {
    if (v < 0) return kNoOperand;
    const Value& x = val(v);
    if (x.origin == Value::Origin::Const)
      return makeOperand(OperandKind::Const, constIndex(pixel_consts_, pixel_, v, x.bits));
    if (x.origin == Value::Origin::Builtin) {
      if (x.index >= static_cast<int>(kRegP)) pixel_.reads_surface = true;  // P or N
      return makeOperand(OperandKind::Reg, static_cast<uint32_t>(x.index));
    }
    if (!x.varying && !pixel_uniform_.count(v)) {
      auto& slots = x.cls == ValueClass::Interp ? interp_slots_ : scalar_slots_;
      auto it = slots.find(v);
      uint32_t slot;
      if (it != slots.end()) {
        slot = it->second;
      } else {
        slot = static_cast<uint32_t>(slots.size());
        slots[v] = slot;
      }
      return makeOperand(OperandKind::Uniform, slot);
    }
    auto it = pixel_regs_.find(v);
    if (it != pixel_regs_.end()) return makeOperand(OperandKind::Reg, it->second);
    uint32_t idx = x.cls == ValueClass::Interp ? pixel_.num_interp_regs++ : pixel_.num_regs++;
    pixel_regs_[v] = idx;
    return makeOperand(OperandKind::Reg, idx);
  }

  // ---- setup ----
  bool setupWork(const IrBlock& b, int varying_depth) const {
    for (const IrNode& n : b) {
      if (n.kind == IrNode::Kind::If) {
        int d = varying_depth + (varying(n.cond) ? 1 : 0);
        if (setupWork(*n.then_block, d) || setupWork(*n.else_block, d)) return true;
        continue;
      }
      if (n.kind == IrNode::Kind::Loop) {
        int d = varying_depth + (n.varying_loop ? 1 : 0);
        if (setupWork(*n.cond_block, d) || setupWork(*n.body_block, d) || setupWork(*n.step_block, d)) return true;
        continue;
      }
      const IrInst& in = n.inst;
      if (in.op == Op::Bound || (in.op == Op::Retire && varying_depth == 0) || isCallEffect(in.op)) return true;
      if (in.dst >= 0 && needed_.count(in.dst)) return true;
    }
    return false;
  }

  void emitSetupLoop(const IrNode& n, int varying_depth) {
    if (n.varying_loop) {
      // Pixels iterate differently: its uniform contents are loop-invariant and pure.
      setup_loops_.push_back(nullptr);
      emitSetup(*n.cond_block, varying_depth + 1);
      emitSetup(*n.body_block, varying_depth + 1);
      emitSetup(*n.step_block, varying_depth + 1);
      setup_loops_.pop_back();
      return;
    }
    if (!setupWork(*n.cond_block, varying_depth) && !setupWork(*n.body_block, varying_depth) &&
        !setupWork(*n.step_block, varying_depth))
      return;
    auto here = [&] { return static_cast<uint32_t>(setup_.code.size()); };
    enter(n);
    setup_.code.push_back(Instr{Op::LoopBegin});
    uint32_t top = here();
    emitSetup(*n.cond_block, varying_depth);
    size_t exit_jump = setup_.code.size();
    setup_.code.push_back(Instr{Op::JmpIfNot, 0, kNoOperand, 0, setupOperand(n.cond)});
    JumpPatches patches;
    setup_loops_.push_back(&patches);
    emitSetup(*n.body_block, varying_depth);
    for (size_t c : patches.continues) setup_.code[c].a = here();
    emitSetup(*n.step_block, varying_depth);
    setup_loops_.pop_back();
    setup_.code.push_back(Instr{Op::LoopBack, 0, kNoOperand, top});
    setup_.code[exit_jump].a = here();
    for (size_t b : patches.breaks) setup_.code[b].a = here();
    setup_.code.push_back(Instr{Op::LoopEnd});
    --nesting_;
  }

  void emitSetup(const IrBlock& b, int varying_depth) {
    for (const IrNode& n : b) {
      if (n.kind == IrNode::Kind::Loop) {
        emitSetupLoop(n, varying_depth);
        continue;
      }
      if (n.kind == IrNode::Kind::If) {
        if (varying(n.cond)) {
          // Varying control: the uniform values inside are pure, so compute them unconditionally.
          emitSetup(*n.then_block, varying_depth + 1);
          emitSetup(*n.else_block, varying_depth + 1);
          continue;
        }
        bool t = setupWork(*n.then_block, varying_depth), e = setupWork(*n.else_block, varying_depth);
        if (!t && !e) continue;
        size_t jf = setup_.code.size();
        setup_.code.push_back(Instr{Op::JmpIfNot, 0, kNoOperand, 0, setupOperand(n.cond)});
        emitSetup(*n.then_block, varying_depth);
        if (e) {
          size_t je = setup_.code.size();
          setup_.code.push_back(Instr{Op::Jmp, 0, kNoOperand, 0});
          setup_.code[jf].a = static_cast<uint32_t>(setup_.code.size());
          emitSetup(*n.else_block, varying_depth);
          setup_.code[je].a = static_cast<uint32_t>(setup_.code.size());
        } else {
          setup_.code[jf].a = static_cast<uint32_t>(setup_.code.size());
        }
        continue;
      }
      const IrInst& in = n.inst;
      if (in.op == Op::Bound) {
        Instr out{Op::Bound, 0, setupOperand(in.d), setupOperand(in.a), setupOperand(in.b), setupOperand(in.c)};
        setup_.code.push_back(out);
      } else if (isCallEffect(in.op)) {
        setup_.code.push_back(
            Instr{in.op, static_cast<uint16_t>(in.imm), kNoOperand, setupOperand(in.a), setupOperand(in.b)});
      } else if (in.op == Op::Retire) {
        if (varying_depth == 0) setup_.code.push_back(Instr{Op::Kill});
      } else if (in.op == Op::Break || in.op == Op::Continue) {
        // Only uniform loops reach here with their own break / continue: a jump.
        // A break of several levels (a function's return inside its loops) pops the inner
        // loops' counters before jumping out of the outermost.
        size_t levels = in.op == Op::Break ? static_cast<size_t>(std::max(in.imm, 1)) : 1;
        bool all_setup = setup_loops_.size() >= levels;
        for (size_t k = 0; all_setup && k < levels; ++k) all_setup = setup_loops_[setup_loops_.size() - 1 - k] != nullptr;
        if (all_setup && varying_depth == 0) {
          JumpPatches* p = setup_loops_[setup_loops_.size() - levels];
          for (size_t k = 1; k < levels; ++k) setup_.code.push_back(Instr{Op::LoopEnd});
          (in.op == Op::Break ? p->breaks : p->continues).push_back(setup_.code.size());
          setup_.code.push_back(Instr{Op::Jmp, 0, kNoOperand, 0});
        }
      } else if (in.dst >= 0 && needed_.count(in.dst)) {
        Instr out{in.op, static_cast<uint16_t>(in.imm), setupOperand(in.dst), setupOperand(in.a),
                  setupOperand(in.b), setupOperand(in.c), setupOperand(in.d)};
        setup_.code.push_back(out);
      }
    }
  }

  // ---- pixel ----
  // A `return` under uniform control flow is the setup program's Kill: the pixel program never
  // runs for an instance that takes it, so it has nothing to do there.
  bool pixelValue(int v) const { return varying(v) || pixel_uniform_.count(v) > 0; }

  // `in_loop`: inside a loop the pixel program runs, whose break / continue it must run too.
  bool pixelInst(const IrInst& in, int varying_depth, bool in_loop) const {
    if (in.op == Op::Retire) return varying_depth > 0;
    if (in.op == Op::Break || in.op == Op::Continue) return in_loop;
    return (in.dst >= 0 && pixelValue(in.dst)) || isPixelEffect(in.op);
  }

  // Marks the uniform values defined inside loops that hold per-pixel work.
  void markDefinedIn(const IrBlock& b) {
    for (const IrNode& n : b) {
      if (n.kind == IrNode::Kind::If) {
        markDefinedIn(*n.then_block);
        markDefinedIn(*n.else_block);
      } else if (n.kind == IrNode::Kind::Loop) {
        markDefinedIn(*n.cond_block);
        markDefinedIn(*n.body_block);
        markDefinedIn(*n.step_block);
      } else if (n.inst.dst >= 0 && !varying(n.inst.dst)) {
        pixel_uniform_.insert(n.inst.dst);
      }
    }
  }

  bool loopHasPixelWork(const IrNode& n, int varying_depth) const {
    int d = varying_depth + (n.varying_loop ? 1 : 0);
    return pixelWork(*n.cond_block, d, false) || pixelWork(*n.body_block, d, false) ||
           pixelWork(*n.step_block, d, false);
  }

  void findPixelLoops(const IrBlock& b, bool inside_pixel_loop) {
    for (const IrNode& n : b) {
      if (n.kind == IrNode::Kind::If) {
        findPixelLoops(*n.then_block, inside_pixel_loop);
        findPixelLoops(*n.else_block, inside_pixel_loop);
      } else if (n.kind == IrNode::Kind::Loop) {
        if (!inside_pixel_loop && loopHasPixelWork(n, 0)) {
          markDefinedIn(*n.cond_block);
          markDefinedIn(*n.body_block);
          markDefinedIn(*n.step_block);
          findPixelLoops(*n.body_block, true);
        } else {
          findPixelLoops(*n.body_block, inside_pixel_loop);
        }
      }
    }
  }

  bool pixelWork(const IrBlock& b, int varying_depth, bool in_loop) const {
    for (const IrNode& n : b) {
      if (n.kind == IrNode::Kind::If) {
        int d = varying_depth + (varying(n.cond) ? 1 : 0);
        if (pixelWork(*n.then_block, d, in_loop) || pixelWork(*n.else_block, d, in_loop)) return true;
        continue;
      }
      if (n.kind == IrNode::Kind::Loop) {
        if (loopHasPixelWork(n, varying_depth)) return true;
        continue;
      }
      if (pixelInst(n.inst, varying_depth, in_loop)) return true;
    }
    return false;
  }

  void emitPixelLoop(const IrNode& n, int varying_depth) {
    if (!loopHasPixelWork(n, varying_depth)) return;
    int d = varying_depth + (n.varying_loop ? 1 : 0);
    auto here = [&] { return static_cast<uint32_t>(pixel_.code.size()); };
    enter(n);
    pixel_.code.push_back(Instr{Op::LoopBegin});
    uint32_t top = here();
    emitPixel(*n.cond_block, d, true);
    pixel_.code.push_back(Instr{Op::LoopTest, 0, kNoOperand, kNoOperand, pixelOperand(n.cond)});
    size_t exit_jump = pixel_.code.size();
    pixel_.code.push_back(Instr{Op::JmpIfNone, 0, kNoOperand, 0});
    emitPixel(*n.body_block, d, true);
    pixel_.code.push_back(Instr{Op::LoopContinue});
    emitPixel(*n.step_block, d, true);
    pixel_.code.push_back(Instr{Op::LoopBack, 0, kNoOperand, top});
    pixel_.code[exit_jump].a = here();
    pixel_.code.push_back(Instr{Op::LoopEnd});
    --nesting_;
  }

  void emitPixel(const IrBlock& b, int varying_depth, bool in_loop) {
    for (const IrNode& n : b) {
      if (n.kind == IrNode::Kind::Loop) {
        emitPixelLoop(n, varying_depth);
        continue;
      }
      if (n.kind == IrNode::Kind::Inst && (n.inst.op == Op::Break || n.inst.op == Op::Continue)) {
        if (in_loop) pixel_.code.push_back(Instr{n.inst.op, static_cast<uint16_t>(std::max(n.inst.imm, 1))});
        continue;
      }
      if (n.kind == IrNode::Kind::If) {
        int d = varying_depth + (varying(n.cond) ? 1 : 0);
        bool t = pixelWork(*n.then_block, d, in_loop), e = pixelWork(*n.else_block, d, in_loop);
        if (!t && !e) continue;
        auto here = [&] { return static_cast<uint32_t>(pixel_.code.size()); };
        if (!varying(n.cond)) {
          size_t jf = pixel_.code.size();
          pixel_.code.push_back(Instr{Op::JmpIfNot, 0, kNoOperand, 0, pixelOperand(n.cond)});
          emitPixel(*n.then_block, d, in_loop);
          if (e) {
            size_t je = pixel_.code.size();
            pixel_.code.push_back(Instr{Op::Jmp, 0, kNoOperand, 0});
            pixel_.code[jf].a = here();
            emitPixel(*n.else_block, d, in_loop);
            pixel_.code[je].a = here();
          } else {
            pixel_.code[jf].a = here();
          }
          continue;
        }
        uint32_t cond = pixelOperand(n.cond);
        enter(n);
        pixel_.code.push_back(Instr{Op::MaskIf, 0, kNoOperand, kNoOperand, cond});
        size_t j1 = pixel_.code.size();
        pixel_.code.push_back(Instr{Op::JmpIfNone, 0, kNoOperand, 0});
        emitPixel(*n.then_block, d, in_loop);
        if (e) {
          pixel_.code[j1].a = here();
          pixel_.code.push_back(Instr{Op::MaskElse, 0, kNoOperand, kNoOperand, cond});
          size_t j2 = pixel_.code.size();
          pixel_.code.push_back(Instr{Op::JmpIfNone, 0, kNoOperand, 0});
          emitPixel(*n.else_block, d, in_loop);
          pixel_.code[j2].a = here();
        } else {
          pixel_.code[j1].a = here();
        }
        pixel_.code.push_back(Instr{Op::MaskEnd});
        --nesting_;
        continue;
      }
      const IrInst& in = n.inst;
      if (!pixelInst(in, varying_depth, in_loop)) continue;
      if (isSetupOnlyLoad(in.op)) {
        result_.errors.push_back({in.loc, "this reads a parameter-sized array inside a loop that runs per pixel, "
                                          "where the instance's parameters are not at hand: read it into a local "
                                          "array before the loop"});
        continue;
      }
      Instr out{in.op, static_cast<uint16_t>(in.imm), pixelOperand(in.dst), pixelOperand(in.a),
                pixelOperand(in.b), pixelOperand(in.c), pixelOperand(in.d)};
      out.masked_write = in.dst >= 0 && defs_[in.dst].size() > 1;  // a merge value
      pixel_.code.push_back(out);
    }
  }
};

}  // namespace

CodegenResult generateCode(const IrFunction& f) {
  Generator g(f);
  return g.run();
}

}  // namespace pf

