// The batched setup executor (see setup_batch.h).
//
// Every value-producing instruction is one kernel: evalScalar (compiler/scalar_ops.h, the same
// definition the scalar executor runs) over the kSetupBatchLanes lanes, instantiated per op so
// that GCC vectorizes the loop, for each instruction set (raster/lane_kernels.h). Registers, constants and parameters share one lane-major file
// (constants broadcast), so every operand is kSetupBatchLanes consecutive words.
#include "raster/setup_batch.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cstring>
#include <string>
#include <utility>

#include "compiler/native/native_cache.h"
#include "compiler/scalar_ops.h"
#include "raster/lane_count.h"
#include "raster/lane_kernels.h"
#include "raster/limits.h"
#include "raster/native_blocks.h"

namespace pf {
namespace {

constexpr int K = kSetupBatchLanes;
static_assert(K <= 32, "lane sets are 32-bit");
static_assert(K == kNativeSetupLanes && kMaxMaskDepth == kNativeSetupMaxLoops,
              "compiler/native/native_abi.h repeats the batch's sizes");
constexpr uint32_t kAllLanes = K == 32 ? ~0u : (1u << K) - 1u;

// The value-producing scalar instructions: every op up to Mov (their kernels: lane_kernels.h).
constexpr size_t kKernelOps = kLaneKernelOps;

alignas(64) const uint32_t kZeroLanes[K] = {};

bool sameSetupVariant(const NativeSetupVariant& a, const NativeSetupVariant& b) {
  return a.isa == b.isa && a.channels == b.channels && std::equal(a.kind_begin, a.kind_begin + 3, b.kind_begin) &&
         std::equal(a.kind_end, a.kind_end + 3, b.kind_end) && a.named_bound == b.named_bound;
}

// dst = f(a, b) in every lane, through a temporary (dst may be a or b).
template <class F>
[[gnu::always_inline]] inline void floatLanes(uint32_t* dst, const uint32_t* a, const uint32_t* b, F f) {
  alignas(64) float r[K];
  for (int l = 0; l < K; ++l) r[l] = f(std::bit_cast<float>(a[l]), std::bit_cast<float>(b[l]));
  std::memcpy(dst, r, sizeof r);
}

}  // namespace

void BatchSetupExecutor::run(const CompiledPrimitive& prim, const SetupInput* in, int count,
                             uint32_t* const* records, SetupOutput* out) {
  // The native function of each run of batches drawn with one layout.
  for (int first = 0; first < count;) {
    int end = first + 1;
    while (end < count && in[end].layout == in[first].layout) ++end;
    const NativeSetupFunction native = nativeFunction(prim, *in[first].layout, end - first);
    run(prim, in + first, end - first, records + first, out + first, native);
    first = end;
  }
}

void BatchSetupExecutor::run(const CompiledPrimitive& prim, const SetupInput* in, int count,
                             uint32_t* const* records, SetupOutput* out, NativeSetupFunction native) {
  for (int first = 0; first < count; first += K) {
    const int lanes = std::min(K, count - first);
    bool together = (batchable(prim) || batch_callers) && lanes >= kMinBatchLanes;
    for (int l = 1; together && l < lanes; ++l) {
      const SetupInput& a = in[first], & b = in[first + l];
      together = a.state == b.state && a.layout == b.layout && a.sequence_points == b.sequence_points &&
                 a.depth == b.depth;
    }
    if (together) {
      runBatch(prim, in + first, lanes, records + first, out + first, native);
      continue;
    }
    for (int l = 0; l < lanes; ++l) out[first + l] = scalar_.run(prim, in[first + l], records[first + l]);
    counters.lanes_scalar += static_cast<uint64_t>(lanes);
  }
}

void BatchSetupExecutor::finishScalar(const CompiledPrimitive& prim, const SetupInput& in, int l, uint32_t pc,
                                      uint32_t* record, SetupOutput& out, uint32_t instructions,
                                      const uint32_t* loop_counters, int loop_depth) {
  SetupResume r;
  r.pc = pc;
  // (A program with no registers or interpolants has empty arrays: null, not null + l.)
  r.regs = regs_.empty() ? nullptr : regs_.data() + l;
  r.reg_stride = K;
  r.interp = interp_.empty() ? nullptr : interp_.data() + l;
  r.interp_stride = K;
  r.loop_counters = loop_counters;
  r.loop_depth = loop_depth;
  r.out = out;
  r.out.instructions = instructions;
  out = scalar_.resume(prim, in, record, r);
  ++counters.lanes_resumed;
}

NativeSetupFunction BatchSetupExecutor::nativeFunction(const CompiledPrimitive& prim, const ChannelLayout& layout,
                                                      int instances) {
  // (Not a primitive that calls others: the renderer sets those up scalar -- their batches
  // would leave at the first call -- and their programs are the longest to compile.)
  if (!use_native || !batchable(prim) || !nativeCodeAvailable()) return nullptr;
  NativeSetupVariant& v = variant_;
  v.isa = nativeIsaOf(laneIsa());
  v.channels = layout.count;
  for (int k = 0; k < kInterpKindCount; ++k) {
    v.kind_begin[k] = layout.kind_begin[k];
    v.kind_end[k] = layout.kind_end[k];
  }
  v.named_bound.clear();
  for (const std::string& name : prim.named_interpolators) v.named_bound.push_back(layout.bindsInterpolator(name));
  NativeProgramCache& cache = NativeProgramCache::instance();
  Remembered& r = remembered_;
  const SetupProgram& p = prim.setup;
  auto sameInstr = [](const Instr& x, const Instr& y) {
    return x.op == y.op && x.imm == y.imm && x.dst == y.dst && x.a == y.a && x.b == y.b && x.c == y.c && x.d == y.d &&
           x.masked_write == y.masked_write;
  };
  const bool same = r.entry && std::equal(p.code.begin(), p.code.end(), r.code.begin(), r.code.end(), sameInstr) &&
                    p.constants == r.constants && p.scalar_exports == r.scalar_exports &&
                    p.interp_exports == r.interp_exports && p.num_regs == r.num_regs &&
                    p.num_interp_regs == r.num_interp_regs &&
                    sameSetupVariant(v, r.variant);
  if (!same) {
    r.entry = cache.setupEntry(p, v);
    r.code = p.code;
    r.constants = p.constants;
    r.scalar_exports = p.scalar_exports;
    r.interp_exports = p.interp_exports;
    r.num_regs = p.num_regs;
    r.num_interp_regs = p.num_interp_regs;
    r.variant = v;
  }
  NativeProgramCache::Entry* entry = r.entry;
  if (void* f = entry->function()) return reinterpret_cast<NativeSetupFunction>(f);
  if (entry->settled() || !cache.drawn(entry, static_cast<uint64_t>(instances))) return nullptr;
  return reinterpret_cast<NativeSetupFunction>(cache.compileSetup(entry, prim.setup, v));
}

void BatchSetupExecutor::reserveFor(const CompiledPrimitive& prim, const ChannelLayout& layout) {
  const SetupProgram& p = prim.setup;
  const size_t words = (p.num_regs + p.constants.size() + static_cast<size_t>(prim.param_floats)) * K;
  if (regs_.size() < words) regs_.resize(words);
  const size_t interp = static_cast<size_t>(p.num_interp_regs) * static_cast<size_t>(layout.count) * K;
  if (interp_.size() < interp) interp_.resize(interp);
}

void BatchSetupExecutor::runBatch(const CompiledPrimitive& prim, const SetupInput* in, int lanes,
                                  uint32_t* const* records, SetupOutput* out, NativeSetupFunction fn) {
  ++counters.batches;
  const SetupProgram& p = prim.setup;
  const ChannelLayout& layout = *in[0].layout;
  const RasterState& st = *in[0].state;
  const int sequence_points = in[0].sequence_points;
  const int nch = layout.count;
  const size_t nregs = p.num_regs, nconst = p.constants.size(), nparams = static_cast<size_t>(prim.param_floats);
  regs_.resize((nregs + nconst + nparams) * K);
  interp_.resize(static_cast<size_t>(p.num_interp_regs) * nch * K);
  // The file: the registers and interp registers zero (unless native code wrote them), the
  // constants broadcast, the parameters transposed.
  auto loadFile = [&](bool registers) {
    if (registers) {
      std::fill_n(regs_.begin(), nregs * K, 0u);
      std::fill(interp_.begin(), interp_.end(), 0.0f);
    }
    for (size_t k = 0; k < nconst; ++k) std::fill_n(regs_.begin() + static_cast<long>((nregs + k) * K), K, p.constants[k]);
    for (size_t k = 0; k < nparams; ++k) {
      uint32_t* d = regs_.data() + (nregs + nconst + k) * K;
      for (int l = 0; l < K; ++l) d[l] = in[l < lanes ? l : 0].params[k];  // lanes past the batch: copies of lane 0
    }
  };
  for (int l = 0; l < lanes; ++l) out[l] = SetupOutput{};
  if (!state_cached_ || !(cached_state_ == st)) {  // instances of one glBegin share their state
    for (int k = 0; k < kStateValueCount; ++k) state_values_[k] = stateValue(st, static_cast<uint16_t>(k));
    cached_state_ = st;
    state_cached_ = true;
  }

  const size_t base[4] = {0, 0, nregs, nregs + nconst};  // by OperandKind (setup has no Uniform operands)
  const BatchKernelTable& batch_kernels = *laneIsaTables().batch;
  uint32_t* const U = regs_.data();
  auto lanesOf = [&](uint32_t o) -> uint32_t* { return U + (base[o >> 30] + operandIndex(o)) * K; };
  auto argOf = [&](uint32_t o) -> const uint32_t* { return o == kNoOperand ? kZeroLanes : lanesOf(o); };
  auto xreg = [&](uint32_t o) { return interp_.data() + static_cast<size_t>(operandIndex(o)) * nch * K; };
  auto forChannels = [&](uint16_t set, auto&& fn) {
    for (int k = 0; k < kInterpKindCount; ++k)
      if (set & (1u << k))
        for (int c = layout.kind_begin[k]; c < layout.kind_end[k]; ++c) fn(c);
  };
  const uint64_t cap = std::max<uint64_t>(st.iteration_cap, static_cast<uint64_t>(sequence_points) + 1);
  uint32_t loop_counters[kMaxMaskDepth];
  int loop_depth = 0;
  uint32_t active = lanes == 32 ? ~0u : (1u << lanes) - 1u;
  uint32_t count = 0;  // instructions executed, the same for every lane in the batch
  auto forActive = [&](auto&& fn) {
    for (uint32_t m = active; m; m &= m - 1) fn(std::countr_zero(m));
  };
  // Every lane still in the batch leaves it at `pc`.
  auto leaveAll = [&](uint32_t pc, uint32_t executed) {
    forActive([&](int l) { finishScalar(prim, in[l], l, pc, records[l], out[l], executed, loop_counters, loop_depth); });
  };
  auto killAll = [&](bool cap_hit) {
    forActive([&](int l) {
      out[l].killed = true;
      out[l].iteration_cap_hit = cap_hit;
      out[l].instructions = count;
    });
    counters.lanes_batched += static_cast<uint64_t>(laneCount(active));
  };

  const size_t n = p.code.size();
  size_t pc = 0;
  // Native code first, while the lanes agree: where it stops, this loop goes on.
  if (fn) {
    NativeSetupArgs& a = native_args_;
    a.regs = regs_.data();
    a.interp = interp_.data();
    a.state_values = state_values_;
    for (int l = 0; l < K; ++l) {
      a.params[l] = in[l < lanes ? l : 0].params;
      a.vertex_channels[l] = in[l < lanes ? l : 0].vertex_channels;
      a.records[l] = l < lanes ? records[l] : nullptr;
    }
    a.iteration_cap = cap;
    a.param_words = prim.paramFloats(sequence_points);
    a.active = active;
    a.sequence_points = sequence_points;
    const NativeSetupStatus status = fn(&a);
    ++counters.batches_native;
    forActive([&](int l) {
      if (a.has_bound) {
        out[l].has_bound = true;
        for (int k = 0; k < 4; ++k) out[l].bound[k] = a.bound[k][l];
      }
      if (a.has_facing) out[l].back_facing = a.back_facing[l] != 0;
      if (a.has_depth_bound) {
        out[l].has_depth_bound = true;
        for (int k = 0; k < 2; ++k) out[l].depth_bound[k] = a.depth_bound[k][l];
      }
    });
    count = a.instructions;
    if (status == NativeSetupStatus::Killed || status == NativeSetupStatus::CapHit) {
      counters.lanes_native += static_cast<uint64_t>(laneCount(active));
      killAll(status == NativeSetupStatus::CapHit);
      return;
    }
    if (status == NativeSetupStatus::Done) {  // (the records written)
      forActive([&](int l) { out[l].instructions = count; });
      counters.lanes_native += static_cast<uint64_t>(laneCount(active));
      counters.lanes_batched += static_cast<uint64_t>(laneCount(active));
      return;
    }
    loadFile(false);  // (the registers written)
    pc = a.pc;
    loop_depth = a.loop_depth;
    std::copy_n(a.loop_counters, loop_depth, loop_counters);
  } else {
    loadFile(true);
  }
  while (pc < n) {
    const Instr& ins = p.code[pc];
    ++pc;
    ++count;
    switch (ins.op) {  // the commonest arithmetic inline, without the kernel call
      case Op::FAdd: floatLanes(lanesOf(ins.dst), lanesOf(ins.a), lanesOf(ins.b), [](float x, float y) { return x + y; }); continue;
      case Op::FSub: floatLanes(lanesOf(ins.dst), lanesOf(ins.a), lanesOf(ins.b), [](float x, float y) { return x - y; }); continue;
      case Op::FMul: floatLanes(lanesOf(ins.dst), lanesOf(ins.a), lanesOf(ins.b), [](float x, float y) { return x * y; }); continue;
      case Op::Mov: std::memmove(lanesOf(ins.dst), lanesOf(ins.a), sizeof(uint32_t) * K); continue;
      default: break;
    }
    if (static_cast<size_t>(ins.op) < kKernelOps) {
      batch_kernels[static_cast<size_t>(ins.op)](lanesOf(ins.dst), argOf(ins.a), argOf(ins.b), argOf(ins.c),
                                                argOf(ins.d), ins.imm);
      continue;
    }
    switch (ins.op) {
      case Op::Jmp: pc = ins.a; continue;
      case Op::JmpIfNot: {
        const uint32_t* v = lanesOf(ins.b);
        uint32_t on;  // lanes whose condition holds: they go on at pc
        if (active == kAllLanes) {  // the usual case, vectorized: all lanes agree?
          uint32_t holds = 0;
          for (int l = 0; l < K; ++l) holds += v[l] != 0 ? 1u : 0u;
          on = holds == static_cast<uint32_t>(K) ? kAllLanes : 0u;
          if (holds != 0 && holds != static_cast<uint32_t>(K))
            for (int l = 0; l < K; ++l) on |= static_cast<uint32_t>(v[l] != 0) << l;
        } else {
          on = 0;
          for (int l = 0; l < K; ++l) on |= static_cast<uint32_t>(v[l] != 0) << l;
          on &= active;
        }
        const uint32_t jump = active & ~on;
        if (!jump) continue;
        if (!on) {
          pc = ins.a;
          continue;
        }
        // The lanes disagree: the smaller group finishes scalar, the larger stays.
        const bool stay_on = std::popcount(on) >= std::popcount(jump);
        const uint32_t stay = stay_on ? on : jump, leave = active & ~stay;
        const uint32_t leave_pc = stay_on ? ins.a : static_cast<uint32_t>(pc);
        active = leave;
        leaveAll(leave_pc, count);
        active = stay;
        if (!stay_on) pc = ins.a;
        if (laneCount(active) < kMinBatchLanes) {
          leaveAll(static_cast<uint32_t>(pc), count);
          return;
        }
        continue;
      }
      case Op::Kill: killAll(false); return;
      case Op::LoopBegin:
        if (loop_depth >= kMaxMaskDepth) {  // as the scalar executor (codegen rejects deeper nesting)
          killAll(false);
          return;
        }
        loop_counters[loop_depth++] = 0;
        continue;
      case Op::LoopBack:
        if (loop_depth > 0 && ++loop_counters[loop_depth - 1] >= cap) {
          killAll(true);
          return;
        }
        pc = ins.a;
        continue;
      case Op::LoopEnd:
        if (loop_depth > 0) --loop_depth;
        continue;
      case Op::Bound: {
        const uint32_t *a = lanesOf(ins.a), *b = lanesOf(ins.b), *c = lanesOf(ins.c), *d = lanesOf(ins.dst);
        forActive([&](int l) {
          out[l].has_bound = true;
          out[l].bound[0] = std::bit_cast<float>(a[l]);
          out[l].bound[1] = std::bit_cast<float>(b[l]);
          out[l].bound[2] = std::bit_cast<float>(c[l]);
          out[l].bound[3] = std::bit_cast<float>(d[l]);
        });
        continue;
      }
      case Op::BackFacing: {
        const uint32_t* a = lanesOf(ins.a);
        forActive([&](int l) { out[l].back_facing = a[l] != 0; });
        continue;
      }
      case Op::DepthBound: {
        const uint32_t *a = lanesOf(ins.a), *b = lanesOf(ins.b);
        forActive([&](int l) {
          out[l].has_depth_bound = true;
          out[l].depth_bound[0] = std::bit_cast<float>(a[l]);
          out[l].depth_bound[1] = std::bit_cast<float>(b[l]);
        });
        continue;
      }
      case Op::LoadState: {
        const float v = ins.imm < kStateValueCount ? state_values_[ins.imm] : 0.0f;
        std::fill_n(lanesOf(ins.dst), K, std::bit_cast<uint32_t>(v));
        continue;
      }
      case Op::HasKinds: std::fill_n(lanesOf(ins.dst), K, layout.hasKinds(ins.imm) ? 1u : 0u); continue;
      case Op::HasNamed:
        std::fill_n(lanesOf(ins.dst), K,
                    layout.bindsInterpolator(prim.named_interpolators[static_cast<size_t>(ins.imm)]) ? 1u : 0u);
        continue;
      case Op::LoadParamAt: {
        const uint32_t* a = lanesOf(ins.a);
        uint32_t* d = lanesOf(ins.dst);
        const int64_t words = prim.paramFloats(sequence_points);
        for (int l = 0; l < K; ++l) {
          const int32_t slot = static_cast<int32_t>(a[l]);
          const int64_t at = static_cast<int64_t>(slot) + ins.imm;
          d[l] = l < lanes && slot >= 0 && at < words ? in[l].params[at] : 0u;
        }
        continue;
      }
      case Op::XLoadVertex: {
        float* d = xreg(ins.dst);
        for (int c = 0; c < nch; ++c)
          for (int l = 0; l < lanes; ++l) d[c * K + l] = in[l].vertex_channels[static_cast<size_t>(ins.imm) * nch + c];
        continue;
      }
      case Op::XLoadVertexAt: {
        float* d = xreg(ins.dst);
        const uint32_t* a = lanesOf(ins.a);
        for (int l = 0; l < lanes; ++l) {
          const int32_t i = static_cast<int32_t>(a[l]);
          const bool inside = i >= 0 && i < sequence_points;
          for (int c = 0; c < nch; ++c)
            d[c * K + l] = inside ? in[l].vertex_channels[static_cast<size_t>(i) * nch + c] : 0.0f;
        }
        continue;
      }
      case Op::XSel: {
        float* d = xreg(ins.dst);
        const float* a = xreg(ins.b);
        const float* b = xreg(ins.c);
        const uint32_t* s = lanesOf(ins.a);
        forChannels(ins.imm, [&](int c) {
          for (int l = 0; l < K; ++l) d[c * K + l] = s[l] != 0 ? a[c * K + l] : b[c * K + l];
        });
        continue;
      }
      case Op::XAdd: case Op::XSub: case Op::XMulF: case Op::XDivF: case Op::XNeg: case Op::XMov: {
        float* d = xreg(ins.dst);
        const float* a = xreg(ins.a);
        if (ins.op == Op::XAdd || ins.op == Op::XSub) {
          const float* b = xreg(ins.b);
          const bool add = ins.op == Op::XAdd;
          forChannels(ins.imm, [&](int c) {
            for (int l = 0; l < K; ++l) d[c * K + l] = add ? a[c * K + l] + b[c * K + l] : a[c * K + l] - b[c * K + l];
          });
        } else if (ins.op == Op::XMulF || ins.op == Op::XDivF) {
          const uint32_t* b = lanesOf(ins.b);
          const bool mul = ins.op == Op::XMulF;
          forChannels(ins.imm, [&](int c) {
            for (int l = 0; l < K; ++l) {
              const float s = std::bit_cast<float>(b[l]);
              d[c * K + l] = mul ? a[c * K + l] * s : a[c * K + l] / s;
            }
          });
        } else {
          const bool neg = ins.op == Op::XNeg;
          forChannels(ins.imm, [&](int c) {
            for (int l = 0; l < K; ++l) d[c * K + l] = neg ? -a[c * K + l] : a[c * K + l];
          });
        }
        continue;
      }
      default:
        // Not batched (calls of other primitives; anything a setup program should not hold):
        // every lane finishes scalar from this instruction, which it has not run yet.
        leaveAll(static_cast<uint32_t>(pc - 1), count - 1);
        return;
    }
  }
  // Exports: each lane's record.
  forActive([&](int l) {
    out[l].instructions = count;
    uint32_t* record = records[l];
    for (size_t s = 0; s < p.scalar_exports.size(); ++s) record[s] = argOf(p.scalar_exports[s])[l];
    float* xrec = reinterpret_cast<float*>(record + p.scalar_exports.size());
    for (size_t s = 0; s < p.interp_exports.size(); ++s) {
      const float* x = interp_.data() + static_cast<size_t>(p.interp_exports[s]) * nch * K;
      for (int c = 0; c < nch; ++c) xrec[s * nch + c] = x[c * K + l];
    }
  });
  counters.lanes_batched += static_cast<uint64_t>(laneCount(active));
}

}  // namespace pf
