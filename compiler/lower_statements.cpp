// Lowering of statements (the Lowerer, lowerer.h): blocks and declarations, `if` and the
// interpolation construct as branches with merge copies, loops (lowered again when a guess of
// uniformity proves wrong), calls of user functions inlined as one-iteration loops whose
// `return` is a break, and assignments to variables, elements and components.
#include "compiler/lowerer.h"

#include <algorithm>

namespace pf::lowering {
namespace {

// Whether a statement holds a `return` anywhere.
bool holdsReturn(const Stmt& s) {
  if (s.kind == StmtKind::Return) return true;
  for (const StmtPtr& c : s.body)
    if (holdsReturn(*c)) return true;
  for (const StmtPtr& c : s.else_body)
    if (holdsReturn(*c)) return true;
  for (const InterpolationCase& k : s.cases)
    for (const StmtPtr& c : k.body)
      if (holdsReturn(*c)) return true;
  return (s.init && holdsReturn(*s.init)) || (s.step && holdsReturn(*s.step));
}

// Whether a function body returns a value at its last statement and nowhere else.
bool returnsOnlyAtEnd(const std::vector<StmtPtr>& body) {
  if (body.empty() || body.back()->kind != StmtKind::Return || !body.back()->value) return false;
  for (size_t i = 0; i + 1 < body.size(); ++i)
    if (holdsReturn(*body[i])) return false;
  return true;
}

// Names assigned anywhere in a statement (targets' root variables).
void assignedNames(const Stmt& s, std::vector<std::string>& out) {
  if (s.kind == StmtKind::Assign) {
    const Expr* root = s.target.get();
    while (root->kind == ExprKind::Index || root->kind == ExprKind::Member) root = root->args[0].get();
    if (root->kind == ExprKind::Name) out.push_back(root->name);
  }
  for (const StmtPtr& c : s.body) assignedNames(*c, out);
  for (const StmtPtr& c : s.else_body) assignedNames(*c, out);
  for (const InterpolationCase& c : s.cases)
    for (const StmtPtr& b : c.body) assignedNames(*b, out);
  if (s.init) assignedNames(*s.init, out);
  if (s.step) assignedNames(*s.step, out);
}

}  // namespace

bool Lowerer::statements(const std::vector<StmtPtr>& body) {
  for (const StmtPtr& s : body)
    if (statement(*s)) return true;  // the rest is unreachable
  return false;
}

bool Lowerer::scoped(const std::vector<StmtPtr>& body) {
  scopes_.emplace_back();
  bool t = statements(body);
  scopes_.pop_back();
  return t;
}

bool Lowerer::statement(const Stmt& s) {
  NestingGuard guard(*this, s.loc);
  // Instructions no expression accounts for (the conversion of a value into a variable's type,
  // say) carry the statement's location.
  const SourceLoc saved = cur_loc_;
  cur_loc_ = s.loc;
  const bool returns = statementAt(s);
  cur_loc_ = saved;
  return returns;
}

bool Lowerer::statementAt(const Stmt& s) {
  switch (s.kind) {
    case StmtKind::Block:
      return s.op == "decls" ? statements(s.body) : scoped(s.body);
    case StmtKind::Decl: {
      Binding b;
      b.type = s.decl_type;
      b.may_vary = s.inferred_varying;
      if (s.value) {
        Binding v = expr(*s.value);
        cur_loc_ = s.value->loc;  // its conversion: where the value is
        b.comps = convert(v, s.decl_type);
      } else if (s.decl_type.base == BaseType::InterpData) {
        b.comps.assign(static_cast<size_t>(s.decl_type.elementCount()), zeroInterp());
      } else {
        // Locals start at zero, so no path can read an undefined value.
        ValueClass c = classOf(s.decl_type.base);
        int zero = constant(c, 0);
        b.comps.assign(s.decl_type.slotCount(), zero);
      }
      scopes_.back()[s.name] = static_cast<int>(bindings_.size());
      bindings_.push_back(std::move(b));
      return false;
    }
    case StmtKind::Assign: assign(s); return false;
    case StmtKind::ExprStmt: expr(*s.value); return false;
    case StmtKind::If: return ifStatement(s);
    case StmtKind::Return:
      if (s.value) return functionReturn(s);
      emitEffect(Op::Retire, -1, -1, -1, -1, 0, s.loc);
      return true;
    case StmtKind::Loop: loop(s); return false;
    case StmtKind::Break:
    case StmtKind::Continue:
      noteExit(1);
      carryCopies(s.loc);
      emitEffect(s.kind == StmtKind::Break ? Op::Break : Op::Continue, -1, -1, -1, -1, 1, s.loc);
      return true;
    case StmtKind::Bound: {
      int v[4];
      for (int i = 0; i < 4; ++i) v[i] = toFloat(expr(*s.bound_args[i]).comps[0]);
      emitEffect(Op::Bound, v[0], v[1], v[2], v[3], 0, s.loc);
      return false;
    }
    case StmtKind::Interpolation: {
      for (const InterpolationCase& c : s.cases) {
        if (!c.interpolators.empty()) {
          if (namedBranches(c)) return false;
          continue;
        }
        InterpKindSet set = 0;
        for (InterpKind k : c.kinds) set |= 1u << static_cast<int>(k);
        f_.kinds_handled |= set;
        InterpKindSet save = interp_kinds_;
        interp_kinds_ = set;
        // The branch runs only for instances with channels of its kinds: a uniform if, so
        // neither setup nor the pixel program pays for interpolations nobody asked for.
        int has = emit(Op::HasKinds, ValueClass::Bool, false, -1, -1, -1, static_cast<int>(set), c.label_locs.front());
        bool t = false;
        branch(has, c.label_locs.front(), [&] { return t = scoped(c.body); }, [] { return false; });
        interp_kinds_ = save;
        if (t) {
          log_.error(c.label_locs.front(), "an interpolation branch cannot end in 'return': the other branches must still run");
          return false;
        }
      }
      return false;
    }
    case StmtKind::InterpReturn:
      if (interpolator_) {
        // A shared interpolator's value: 4 floats, missing components (0, 0, 0, 1).
        Binding b = expr(*s.value);
        int c[4] = {constF(0.0f), constF(0.0f), constF(0.0f), constF(1.0f)};
        for (size_t k = 0; k < b.comps.size() && k < 4; ++k) c[k] = toFloat(b.comps[k]);
        emitEffect(Op::ShadeOut, c[0], c[1], c[2], c[3], 0, s.loc);
        return false;
      }
      if (named_index_ >= 0) {  // the primitive's own value of a shared interpolator, as one returns it
        Binding b = expr(*s.value);
        int c[4] = {constF(0.0f), constF(0.0f), constF(0.0f), constF(1.0f)};
        for (size_t k = 0; k < b.comps.size() && k < 4; ++k) c[k] = toFloat(b.comps[k]);
        emitEffect(Op::InterpNamedReturn, c[0], c[1], c[2], c[3], named_index_, s.loc);
        return false;
      }
      if (s.value) {
        int v = expr(*s.value).comps[0];
        emitEffect(Op::InterpReturn, v, -1, -1, -1, static_cast<int>(interp_kinds_), s.loc);
      } else {
        // The shared interpolators read the surface point P as it is here.
        const std::vector<int>& p = bindings_[lookup("P")].comps;
        emitEffect(Op::InterpShared, p[0], p[1], p[2], p[3], static_cast<int>(interp_kinds_), s.loc);
      }
      return false;
  }
  return false;
}

// The branch of `name:` labels: for each name, the body runs (a uniform if) only for instances
// with channels bound to that shared interpolator, and its interpolator_return(value) fills
// them (Op::InterpNamedReturn; the pixel executor then skips that interpolator's program).
// Returns true where lowering must stop (an error).
bool Lowerer::namedBranches(const InterpolationCase& c) {
  for (const std::string& name : c.interpolators) {
    auto known = std::find(f_.named_interpolators.begin(), f_.named_interpolators.end(), name);
    const int index = static_cast<int>(known - f_.named_interpolators.begin());
    if (known == f_.named_interpolators.end()) f_.named_interpolators.push_back(name);
    InterpKindSet save_kinds = interp_kinds_;
    const int save_index = named_index_;
    interp_kinds_ = 0;  // no interpolator_data channels belong to this branch
    named_index_ = index;
    int has = emit(Op::HasNamed, ValueClass::Bool, false, -1, -1, -1, index, c.label_locs.front());
    bool t = false;
    branch(has, c.label_locs.front(), [&] { return t = scoped(c.body); }, [] { return false; });
    interp_kinds_ = save_kinds;
    named_index_ = save_index;
    if (t) {
      log_.error(c.label_locs.front(), "an interpolation branch cannot end in 'return': the other branches must still run");
      return true;
    }
  }
  return false;
}

void Lowerer::carryCopies(SourceLoc loc, int index) {
  if (loops_.empty()) return;
  LoopContext& l = loops_[index < 0 ? loops_.size() - 1 : static_cast<size_t>(index)];
  for (size_t i = 0; i < l.slots.size(); ++i) {
    int cur = bindings_[l.slots[i].first].comps[l.slots[i].second];
    int m = l.merge[i];
    if (cur == m) continue;
    if (isVarying(cur) && !isVarying(m)) l.violated.push_back(i);  // lowered again, varying
    IrNode n;
    n.inst = IrInst{cls(m) == ValueClass::Interp ? Op::XMov : Op::Mov, m, cur, -1, -1, -1,
                    static_cast<int>(kAllInterpKinds), loc};
    blocks_.back()->push_back(std::move(n));
  }
}

void Lowerer::noteExit(int levels) {
  for (int k = 0; k < levels && k < static_cast<int>(loops_.size()); ++k) {
    LoopContext& l = loops_[loops_.size() - 1 - k];
    if (varying_depth_ > l.entry_varying_depth) l.varying_exit = true;
  }
}

bool Lowerer::functionReturn(const Stmt& s) {
  int levels = 0, target = -1;
  for (int k = static_cast<int>(loops_.size()) - 1; k >= 0; --k) {
    ++levels;
    if (loops_[k].function) {
      target = k;
      break;
    }
  }
  if (target < 0) return false;  // sema reports a value returned from a primitive
  int result = lookup("$result");
  Binding v = expr(*s.value);
  bindings_[result].comps = convert(v, bindings_[result].type);
  noteExit(levels);
  carryCopies(s.loc, target);
  emitEffect(Op::Break, -1, -1, -1, -1, levels, s.loc);
  return true;
}

void Lowerer::lowerLoop(const LoopSpec& spec) {
  bool loop_varying = spec.varying;
  std::vector<bool> forced;
  // Lowered before (an enclosing loop is being lowered again): what it found then still holds,
  // since a second attempt only ever finds more values varying.
  std::vector<const void*> key = call_sites_;
  key.push_back(spec.site);
  if (auto m = loop_memo_.find(key); spec.site && m != loop_memo_.end()) {
    loop_varying = loop_varying || m->second.varying;
    forced = m->second.forced;
  }
  for (int attempt = 0;; ++attempt) {
    std::vector<Binding> saved = bindings_;
    size_t saved_size = blocks_.back()->size();
    LoopContext ctx;
    ctx.function = spec.function;
    ctx.entry_varying_depth = varying_depth_;
    size_t slot = 0;
    for (int b : spec.carried_bindings) {
      for (size_t k = 0; k < bindings_[b].comps.size(); ++k, ++slot) {
        if (forced.size() <= slot) forced.push_back(false);
        int cur = bindings_[b].comps[k];
        Value m;
        m.cls = cls(cur);
        m.varying = loop_varying || bindings_[b].may_vary || isVarying(cur) || forced[slot];
        int mid = newValue(m);
        IrNode init;
        init.inst = IrInst{m.cls == ValueClass::Interp ? Op::XMov : Op::Mov, mid, cur, -1, -1, -1,
                           static_cast<int>(kAllInterpKinds), spec.loc};
        blocks_.back()->push_back(std::move(init));
        bindings_[b].comps[k] = mid;
        ctx.slots.push_back({b, static_cast<int>(k)});
        ctx.merge.push_back(mid);
      }
    }
    IrNode node;
    node.kind = IrNode::Kind::Loop;
    node.inst.loc = spec.loc;
    node.varying_loop = loop_varying;
    node.cond_block = std::make_unique<IrBlock>();
    node.body_block = std::make_unique<IrBlock>();
    node.step_block = std::make_unique<IrBlock>();
    loops_.push_back(ctx);
    if (loop_varying) ++varying_depth_;
    blocks_.push_back(node.cond_block.get());
    int cond = spec.cond ? spec.cond() : -1;
    node.cond = cond >= 0 ? cond : constB(true);
    blocks_.pop_back();
    blocks_.push_back(node.body_block.get());
    spec.body();
    blocks_.pop_back();
    for (size_t i = 0; i < ctx.slots.size(); ++i)  // the continue point
      bindings_[ctx.slots[i].first].comps[ctx.slots[i].second] = ctx.merge[i];
    blocks_.push_back(node.step_block.get());
    if (spec.step) spec.step();
    carryCopies(spec.loc);
    blocks_.pop_back();
    if (loop_varying) --varying_depth_;
    LoopContext done = std::move(loops_.back());
    loops_.pop_back();

    bool again = false;
    if (!loop_varying && (isVarying(node.cond) || done.varying_exit)) {
      loop_varying = true;
      again = true;
    }
    for (size_t i : done.violated)
      if (!forced[i]) {
        forced[i] = true;
        again = true;
      }
    if (again && attempt < 64) {
      bindings_ = std::move(saved);
      blocks_.back()->resize(saved_size);
      continue;
    }
    for (size_t i = 0; i < done.slots.size(); ++i)  // after the loop
      bindings_[done.slots[i].first].comps[done.slots[i].second] = done.merge[i];
    blocks_.back()->push_back(std::move(node));
    if (spec.site) loop_memo_[std::move(key)] = LoopMemo{loop_varying, std::move(forced)};
    return;
  }
}

std::vector<int> Lowerer::visibleBindings(const std::vector<std::string>& names) const {
  std::vector<int> out;
  for (const std::string& n : names) {
    int b = lookup(n);
    if (b >= 0 && std::find(out.begin(), out.end(), b) == out.end()) out.push_back(b);
  }
  return out;
}

void Lowerer::loop(const Stmt& s) {
  scopes_.emplace_back();
  if (s.init) statement(*s.init);
  std::vector<std::string> names;
  assignedNames(s, names);
  LoopSpec spec;
  spec.loc = s.loc;
  spec.site = &s;
  spec.varying = s.varying_loop;
  spec.carried_bindings = visibleBindings(names);
  if (s.value) spec.cond = [&] { return expr(*s.value).comps[0]; };
  spec.body = [&] {
    if (!scoped(s.body)) carryCopies(s.loc);
  };
  if (s.step) spec.step = [&] { statement(*s.step); };
  lowerLoop(spec);
  scopes_.pop_back();
}

Binding Lowerer::callFunction(const Expr& e, const Unit& fn) {
  std::vector<Binding> args;
  for (const ExprPtr& a : e.args) args.push_back(expr(*a));
  call_sites_.push_back(&e);
  Binding out = inlineFunction(fn, args, e.loc);
  call_sites_.pop_back();
  return out;
}

Binding Lowerer::inlineFunction(const Unit& fn, const std::vector<Binding>& args, SourceLoc call_loc) {
  Binding result;
  result.type = fn.return_type;
  if (fn.return_type.base == BaseType::InterpData) {
    log_.error(call_loc, "functions cannot return interpolator_data in this version of the language");
    return result;
  }
  inlining_.push_back(&fn);
  if (inlining_.size() > kMaxInlineDepth)
    refuse(call_loc, "calls nest more than " + std::to_string(kMaxInlineDepth) + " deep once functions are inlined");
  struct Leave {
    std::vector<const Unit*>& v;
    ~Leave() { v.pop_back(); }
  } leave{inlining_};
  // The parameters and the result are bound past the caller's variables and dropped on return:
  // branches copy every binding, so left behind they would make each later one slower.
  const size_t caller_bindings = bindings_.size();
  // The function sees the built-ins (scope 0) and its own parameters, nothing of the caller.
  std::vector<std::map<std::string, int>> saved_scopes = std::move(scopes_);
  scopes_.clear();
  scopes_.push_back(saved_scopes.front());
  scopes_.emplace_back();
  for (size_t i = 0; i < fn.params.size(); ++i) {
    Binding b;
    b.type = fn.params[i].type;
    b.comps = convert(args[i], b.type);
    b.writable = true;
    scopes_.back()[fn.params[i].name] = static_cast<int>(bindings_.size());
    bindings_.push_back(std::move(b));
  }
  ValueClass rc = classOf(fn.return_type.base);
  result.comps.assign(fn.return_type.slotCount(), constant(rc, 0));
  scopes_.back()["$result"] = static_cast<int>(bindings_.size());
  bindings_.push_back(std::move(result));

  // A body whose only `return` is its last statement needs no loop: lowered straight, its
  // uniform work stays uniform (hoisted into setup), as if written at the call.
  if (returnsOnlyAtEnd(fn.body)) {
    scopes_.emplace_back();
    for (size_t i = 0; i + 1 < fn.body.size(); ++i) statement(*fn.body[i]);
    Binding value = expr(*fn.body.back()->value);
    scopes_.pop_back();
    Binding out = bindings_[lookup("$result")];
    out.comps = convert(value, out.type);
    out.writable = true;
    scopes_ = std::move(saved_scopes);
    bindings_.erase(bindings_.begin() + static_cast<std::ptrdiff_t>(caller_bindings), bindings_.end());
    return out;
  }
  std::vector<std::string> names = {"$result"};
  for (const StmtPtr& st : fn.body) assignedNames(*st, names);
  LoopSpec spec;
  spec.loc = call_loc;
  spec.function = true;
  spec.site = &fn;
  spec.carried_bindings = visibleBindings(names);
  spec.body = [&] {
    if (!scoped(fn.body)) {  // sema makes every path return; stay safe regardless
      carryCopies(call_loc);
      emitEffect(Op::Break, -1, -1, -1, -1, 1, call_loc);
    }
  };
  lowerLoop(spec);
  Binding out = bindings_[lookup("$result")];
  out.writable = true;
  scopes_ = std::move(saved_scopes);
  bindings_.erase(bindings_.begin() + static_cast<std::ptrdiff_t>(caller_bindings), bindings_.end());
  return out;
}

// The `else if` links that follow `s`: each statement whose else part is one if statement.
static std::vector<const Stmt*> elseIfLinks(const Stmt& s) {
  std::vector<const Stmt*> links{&s};
  for (const Stmt* at = &s; at->else_body.size() == 1 && at->else_body[0]->kind == StmtKind::If;)
    links.push_back(at = at->else_body[0].get());
  return links;
}

bool Lowerer::ifStatement(const Stmt& s) {
  int cond = expr(*s.value).comps[0];
  if (isVarying(cond)) {
    std::vector<const Stmt*> links = elseIfLinks(s);
    if (links.size() >= kFlatElseIfLinks) return ifChain(links, cond);
  }
  return branch(cond, s.loc, [&] { return scoped(s.body); }, [&] { return scoped(s.else_body); });
}

// A varying chain `if (a) A else if (b) B … else E` nested as written opens one mask per link
// (a program nests at most 64). Lowered instead as a row of ifs one deep each, with a flag of
// the lanes some branch took:
//   taken = a;  if (a) A;
//   c = false;  if (!taken) c = b;  if (c) B;  taken = taken || c;  …
//   if (!taken) E
// so each condition still runs only in the lanes no earlier branch took, as nested ifs would.
bool Lowerer::ifChain(const std::vector<const Stmt*>& links, int first_cond) {
  const size_t flag = bindings_.size();  // the condition of the link being lowered
  Binding b;
  b.type.base = BaseType::Bool;
  b.comps = {first_cond};
  bindings_.push_back(b);
  int taken = first_cond;
  bool all_return = true;
  auto body = [&](int cond, SourceLoc loc, const std::vector<StmtPtr>& stmts) {
    bool returns = false;
    branch(cond, loc, [&] { return returns = scoped(stmts); }, [] { return false; });
    all_return = all_return && returns;
  };
  body(first_cond, links[0]->loc, links[0]->body);
  for (size_t i = 1; i < links.size(); ++i) {
    const Stmt& link = *links[i];
    const int not_taken = emit(Op::BNot, ValueClass::Bool, false, taken);
    bindings_[flag].comps[0] = constB(false);
    branch(not_taken, link.loc, [&] {
      bindings_[flag].comps[0] = expr(*link.value).comps[0];
      return false;
    }, [] { return false; });
    const int cond = bindings_[flag].comps[0];
    body(cond, link.loc, link.body);
    taken = emit(Op::BOr, ValueClass::Bool, false, taken, cond);
  }
  const Stmt& last = *links.back();
  if (last.else_body.empty()) {
    all_return = false;
  } else {
    body(emit(Op::BNot, ValueClass::Bool, false, taken), last.loc, last.else_body);
  }
  bindings_.erase(bindings_.begin() + static_cast<std::ptrdiff_t>(flag), bindings_.end());
  return all_return;
}

bool Lowerer::branch(int cond, SourceLoc loc, const std::function<bool()>& then_part, const std::function<bool()>& else_part) {
  bool vary = isVarying(cond);
  IrNode node;
  node.kind = IrNode::Kind::If;
  node.cond = cond;
  node.inst.loc = loc;
  node.then_block = std::make_unique<IrBlock>();
  node.else_block = std::make_unique<IrBlock>();
  std::vector<Binding> before = bindings_;
  if (vary) ++varying_depth_;
  blocks_.push_back(node.then_block.get());
  bool then_done = then_part();
  blocks_.pop_back();
  std::vector<Binding> after_then = bindings_;
  bindings_ = before;
  blocks_.push_back(node.else_block.get());
  bool else_done = else_part();
  blocks_.pop_back();
  std::vector<Binding> after_else = std::move(bindings_);
  if (vary) --varying_depth_;

  bindings_ = before;
  for (size_t i = 0; i < before.size(); ++i) {
    for (size_t k = 0; k < before[i].comps.size(); ++k) {
      int t = after_then[i].comps[k], e = after_else[i].comps[k];
      if (then_done && else_done) break;
      if (then_done) { bindings_[i].comps[k] = e; continue; }
      if (else_done) { bindings_[i].comps[k] = t; continue; }
      if (t == e) { bindings_[i].comps[k] = t; continue; }
      // Merge: a new value assigned at the end of each branch.
      Value m;
      m.cls = cls(t);
      m.varying = vary || isVarying(t) || isVarying(e);
      int mid = newValue(m);
      Op mov = m.cls == ValueClass::Interp ? Op::XMov : Op::Mov;
      IrNode ct, ce;
      ct.inst = IrInst{mov, mid, t, -1, -1, -1, static_cast<int>(kAllInterpKinds), loc};
      ce.inst = IrInst{mov, mid, e, -1, -1, -1, static_cast<int>(kAllInterpKinds), loc};
      node.then_block->push_back(std::move(ct));
      node.else_block->push_back(std::move(ce));
      bindings_[i].comps[k] = mid;
    }
  }
  blocks_.back()->push_back(std::move(node));
  return then_done && else_done;
}

bool Lowerer::target(const Expr& e, int& bind, std::vector<TargetSlots>& slots, int& count) {
  if (e.kind == ExprKind::Name) {
    bind = lookup(e.name);
    if (bind < 0) return false;
    slots = {{0, -1}};
    count = static_cast<int>(bindings_[bind].comps.size());
    return true;
  }
  if (!target(*e.args[0], bind, slots, count)) return false;
  const Type& bt = e.args[0]->type;
  if (e.kind == ExprKind::Member) {
    for (TargetSlots& t : slots) t.first += static_cast<int>(e.number);
    count = 1;
    return true;
  }
  int esz = bt.indexedSlots();
  int elements = bt.indexedCount();
  count = esz;
  if (e.number >= 0) {
    for (TargetSlots& t : slots) t.first += static_cast<int>(e.number) * esz;
    return true;
  }
  int index = expr(*e.args[1]).comps[0];
  std::vector<TargetSlots> out;
  for (const TargetSlots& t : slots)
    for (int k = 0; k < elements; ++k) {
      int hit = emit(Op::IEq, ValueClass::Bool, false, index, constI(k));
      int cond = t.cond < 0 ? hit : emit(Op::BAnd, ValueClass::Bool, false, t.cond, hit);
      out.push_back({t.first + k * esz, cond});
    }
  slots = std::move(out);
  return true;
}

int Lowerer::select(int cond, int a, int b) {
  if (cls(a) == ValueClass::Interp)
    return emit(Op::XSel, ValueClass::Interp, false, cond, a, b, static_cast<int>(interp_kinds_));
  return emit(Op::Sel, cls(a), false, cond, a, b);
}

void Lowerer::assign(const Stmt& s) {
  int bind, count;
  std::vector<TargetSlots> slots;
  if (!target(*s.target, bind, slots, count)) return;
  Binding value;
  if (s.op == "=") {
    value = expr(*s.value);
  } else {
    Binding cur = expr(*s.target);
    Binding rhs = expr(*s.value);
    value = arith(s.op.substr(0, 1), cur, rhs, s.target->type, s.loc);
  }
  std::vector<int> comps = convert(value, s.target->type);
  if (static_cast<int>(comps.size()) != count) return;  // type error already reported
  std::vector<int>& dst = bindings_[bind].comps;
  for (const TargetSlots& t : slots)
    for (int k = 0; k < count; ++k)
      dst[t.first + k] = t.cond < 0 ? comps[k] : select(t.cond, comps[k], dst[t.first + k]);
}

}  // namespace pf::lowering
