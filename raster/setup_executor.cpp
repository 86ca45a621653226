// The scalar setup interpreter (see setup_executor.h).
#include "raster/setup_executor.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstring>

#include "raster/limits.h"
#include "compiler/scalar_ops.h"

namespace pf {

void SetupExecutor::cacheState(const RasterState& state) {
  if (state_cached_ && cached_state_ == state) return;
  for (int k = 0; k < kStateValueCount; ++k) state_values_[k] = stateValue(state, static_cast<uint16_t>(k));
  cached_state_ = state;
  state_cached_ = true;
}

void SetupExecutor::load(const CompiledPrimitive& prim, const SetupInput& in) {
  const SetupProgram& p = prim.setup;
  cacheState(*in.state);
  // One flat file for every operand kind -- registers, then constants, then the fixed part of
  // the parameters -- so that reading an operand is an add and a load, not a switch.
  const size_t nregs = p.num_regs, nconst = p.constants.size(), nparams = static_cast<size_t>(prim.param_floats);
  regs_.resize(nregs + nconst + nparams);
  std::fill_n(regs_.begin(), nregs, 0u);
  std::copy(p.constants.begin(), p.constants.end(), regs_.begin() + static_cast<long>(nregs));
  std::copy_n(in.params, nparams, regs_.begin() + static_cast<long>(nregs + nconst));
  interp_.assign(static_cast<size_t>(p.num_interp_regs) * in.layout->count, 0.0f);
}

SetupOutput SetupExecutor::run(const CompiledPrimitive& prim, const SetupInput& in, uint32_t* record) {
  load(prim, in);
  return execute(prim, in, record, 0, SetupOutput{}, nullptr, 0);
}

SetupOutput SetupExecutor::resume(const CompiledPrimitive& prim, const SetupInput& in, uint32_t* record,
                                  const SetupResume& from) {
  load(prim, in);
  const SetupProgram& p = prim.setup;
  for (size_t r = 0; r < p.num_regs; ++r) regs_[r] = from.regs[r * from.reg_stride];
  for (size_t i = 0; i < interp_.size(); ++i) interp_[i] = from.interp[i * from.interp_stride];
  return execute(prim, in, record, from.pc, from.out, from.loop_counters, from.loop_depth);
}

SetupOutput SetupExecutor::execute(const CompiledPrimitive& prim, const SetupInput& in, uint32_t* record,
                                   size_t start_pc, SetupOutput out, const uint32_t* open_loops, int open_depth) {
  const SetupProgram& p = prim.setup;
  const int nch = in.layout->count;
  const size_t nregs = p.num_regs, nconst = p.constants.size();
  const uint32_t base[4] = {0, 0, static_cast<uint32_t>(nregs), static_cast<uint32_t>(nregs + nconst)};  // by OperandKind
  uint32_t* const U = regs_.data();

  // (Setup programs have no Uniform operands.)
  auto read = [&](uint32_t o) -> uint32_t { return U[base[o >> 30] + operandIndex(o)]; };
  auto rf = [&](uint32_t o) { return std::bit_cast<float>(read(o)); };
  auto xreg = [&](uint32_t o) { return interp_.data() + static_cast<size_t>(operandIndex(o)) * nch; };
  auto state = [&](uint16_t which) { return which < kStateValueCount ? state_values_[which] : 0.0f; };
  // Channel ranges of the kinds in `set`, as [begin, end) pairs.
  auto forChannels = [&](uint16_t set, auto&& fn) {
    for (int k = 0; k < kInterpKindCount; ++k)
      if (set & (1u << k))
        for (int c = in.layout->kind_begin[k]; c < in.layout->kind_end[k]; ++c) fn(c);
  };

  // A loop may run as often as the cap -- or, over a parameter-sized array, once per sequence
  // point (a strip of 100k vertices is no runaway).
  const uint64_t cap = std::max<uint64_t>(in.state->iteration_cap, static_cast<uint64_t>(in.sequence_points) + 1);
  uint32_t loop_counters[kMaxMaskDepth];
  int loop_depth = std::min(open_depth, kMaxMaskDepth);
  std::copy_n(open_loops, loop_depth, loop_counters);

  const size_t n = p.code.size();
  for (size_t pc = start_pc; pc < n;) {
    const Instr& ins = p.code[pc];
    ++pc;
    ++out.instructions;
    switch (ins.op) {
      // The commonest arithmetic, without evalScalar's second dispatch.
      case Op::FAdd: U[operandIndex(ins.dst)] = std::bit_cast<uint32_t>(rf(ins.a) + rf(ins.b)); continue;
      case Op::FSub: U[operandIndex(ins.dst)] = std::bit_cast<uint32_t>(rf(ins.a) - rf(ins.b)); continue;
      case Op::FMul: U[operandIndex(ins.dst)] = std::bit_cast<uint32_t>(rf(ins.a) * rf(ins.b)); continue;
      case Op::Jmp: pc = ins.a; continue;
      case Op::JmpIfNot:
        if (!read(ins.b)) pc = ins.a;
        continue;
      case Op::Kill: out.killed = true; return out;
      case Op::LoopBegin:
        if (loop_depth >= kMaxMaskDepth) {  // codegen rejects deeper nesting; never reached
          out.killed = true;
          return out;
        }
        loop_counters[loop_depth++] = 0;
        continue;
      case Op::LoopBack:
        if (loop_depth > 0 && ++loop_counters[loop_depth - 1] >= cap) {
          out.killed = true;
          out.iteration_cap_hit = true;
          return out;
        }
        pc = ins.a;
        continue;
      case Op::LoopEnd:
        if (loop_depth > 0) --loop_depth;
        continue;
      case Op::Bound:
        out.has_bound = true;
        out.bound[0] = rf(ins.a);
        out.bound[1] = rf(ins.b);
        out.bound[2] = rf(ins.c);
        out.bound[3] = rf(ins.dst);
        continue;
      case Op::LoadState: U[operandIndex(ins.dst)] = std::bit_cast<uint32_t>(state(ins.imm)); continue;
      case Op::HasKinds: U[operandIndex(ins.dst)] = in.layout->hasKinds(ins.imm) ? 1u : 0u; continue;
      case Op::HasNamed:
        U[operandIndex(ins.dst)] =
            in.layout->bindsInterpolator(prim.named_interpolators[static_cast<size_t>(ins.imm)]) ? 1u : 0u;
        continue;
      case Op::XLoadVertex: {
        float* d = xreg(ins.dst);
        const float* s = in.vertex_channels + static_cast<size_t>(ins.imm) * nch;
        std::memcpy(d, s, sizeof(float) * nch);
        continue;
      }
      case Op::XLoadVertexAt: {
        float* d = xreg(ins.dst);
        const int32_t i = static_cast<int32_t>(read(ins.a));
        if (i >= 0 && i < in.sequence_points)
          std::memcpy(d, in.vertex_channels + static_cast<size_t>(i) * nch, sizeof(float) * nch);
        else
          std::fill(d, d + nch, 0.0f);
        continue;
      }
      case Op::LoadParamAt: {
        const int32_t slot = static_cast<int32_t>(read(ins.a));
        const int64_t at = static_cast<int64_t>(slot) + ins.imm;
        U[operandIndex(ins.dst)] = slot >= 0 && at < prim.paramFloats(in.sequence_points) ? in.params[at] : 0u;
        continue;
      }
      case Op::XSel: {
        float* d = xreg(ins.dst);
        const float* a = xreg(ins.b);
        const float* b = xreg(ins.c);
        const bool pick_a = read(ins.a) != 0;
        forChannels(ins.imm, [&](int c) { d[c] = pick_a ? a[c] : b[c]; });
        continue;
      }
      case Op::BackFacing: out.back_facing = read(ins.a) != 0; continue;
      case Op::DepthBound:
        out.has_depth_bound = true;
        out.depth_bound[0] = rf(ins.a);
        out.depth_bound[1] = rf(ins.b);
        continue;
      case Op::OutParam: {
        if (out_params_.size() <= ins.imm) out_params_.resize(ins.imm + 1u, 0u);
        out_params_[ins.imm] = read(ins.a);
        continue;
      }
      case Op::OutVertex: {
        const size_t need = (static_cast<size_t>(ins.imm) + 1) * nch;
        if (out_vertices_.size() < need) out_vertices_.resize(need, 0.0f);
        std::memcpy(out_vertices_.data() + static_cast<size_t>(ins.imm) * nch, xreg(ins.a), sizeof(float) * nch);
        continue;
      }
      case Op::Emit: {
        const CompiledPrimitive& callee = *prim.callees[ins.imm];
        // Every parameter of the callee was passed (sema checks the call), so the block is full.
        out_params_.resize(static_cast<size_t>(callee.paramFloats(callee.sequence_points)), 0u);
        out_vertices_.resize(static_cast<size_t>(callee.sequence_points) * nch, 0.0f);
        if (in.sink) in.sink->submitCall(callee, out_params_.data(), out_vertices_.data(), in.depth + 1);
        continue;
      }
      case Op::XAdd: case Op::XSub: case Op::XMulF: case Op::XDivF: case Op::XNeg: case Op::XMov: {
        float* d = xreg(ins.dst);
        const float* a = xreg(ins.a);
        if (ins.op == Op::XAdd || ins.op == Op::XSub) {
          const float* b = xreg(ins.b);
          forChannels(ins.imm, [&](int c) { d[c] = ins.op == Op::XAdd ? a[c] + b[c] : a[c] - b[c]; });
        } else if (ins.op == Op::XMulF || ins.op == Op::XDivF) {
          float b = rf(ins.b);
          forChannels(ins.imm, [&](int c) { d[c] = ins.op == Op::XMulF ? a[c] * b : a[c] / b; });
        } else {
          forChannels(ins.imm, [&](int c) { d[c] = ins.op == Op::XNeg ? -a[c] : a[c]; });
        }
        continue;
      }
      default: {
        uint32_t r = evalScalar(ins.op, read(ins.a), ins.b == kNoOperand ? 0 : read(ins.b),
                                ins.c == kNoOperand ? 0 : read(ins.c), ins.d == kNoOperand ? 0 : read(ins.d), ins.imm);
        U[operandIndex(ins.dst)] = r;
      }
    }
  }
  // Exports: the pixel program's view of this instance.
  for (size_t s = 0; s < p.scalar_exports.size(); ++s) record[s] = read(p.scalar_exports[s]);
  float* xrec = reinterpret_cast<float*>(record + p.scalar_exports.size());
  for (size_t s = 0; s < p.interp_exports.size(); ++s)
    std::memcpy(xrec + s * nch, interp_.data() + static_cast<size_t>(p.interp_exports[s]) * nch, sizeof(float) * nch);
  return out;
}

}  // namespace pf
