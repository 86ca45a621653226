// The SIMD pixel executor's interpreter (see pixel_executor.h): a block run by bytecode.
//
// Each value-producing instruction runs one kernel (raster/lane_kernels.h): a loop over the
// kLanes lanes of evalScalar instantiated for the instruction and for which operands are wide
// (one value per lane) or scalar (uniform / constant), vectorized for the machine's instruction
// set, picked once per program and frame (raster/decoded_program.h). A merge value written
// under a partial mask goes through a blend; every other value writes all lanes
// (Instr::masked_write). Control, effects and the per-channel interpolator ops run in a switch.
#include "raster/pixel_executor.h"

#include <algorithm>
#include <array>
#include <cstring>

#include "compiler/scalar_ops.h"
#include "raster/lane_count.h"
#include "raster/lane_kernels.h"

namespace pf {
namespace {

alignas(64) const uint32_t kZeroLanes[kLanes] = {};

// The lanes where v is not zero (v uniform: all or none).
inline uint64_t laneMaskOf(const LaneMaskOps& masks, const uint32_t* v, bool wide) {
  if (!wide) return v[0] ? ~0ull : 0ull;
  return masks.nonzero(v);
}

}  // namespace

void PixelExecutor::runSharedInterpolators(const CompiledPrimitive& prim, const ChannelLayout& layout,
                                           const RasterState& state, int bx, int by, const PackedLanes* packed,
                                           uint64_t exec, const uint32_t* const p[4], const bool p_wide[4],
                                           const uint32_t* shared_records) {
  if (layout.shared.empty() || exec == 0 || !shared_records) return;
  alignas(64) uint32_t p_lanes[4 * kLanes];
  for (int k = 0; k < 4; ++k)
    for (int i = 0; i < kLanes; ++i) p_lanes[k * kLanes + i] = p_wide[k] ? p[k][i] : p[k][0];
  if (!shared_) shared_ = std::make_unique<PixelExecutor>();
  static const ChannelLayout kNoChannels;
  for (const ChannelLayout::SharedInterpolator& s : layout.shared) {
    // An interpolator the primitive computes itself (a `name:` label) is the primitive's to fill.
    if (prim.computesInterpolator(s.program->name)) continue;
    PixelExecutor& sub = *shared_;
    sub.shade_out_.assign(4 * kLanes, 0u);
    sub.execute(*s.program, s.program->pixel, shared_records + s.record_offset, kNoChannels, state, bx, by, packed,
                exec, BlockTarget{}, nullptr, p_lanes);
    for (int k = 0; k < 4; ++k) {
      uint32_t* d = staging_.data() + static_cast<size_t>(s.first + k) * kLanes;
      const uint32_t* v = sub.shade_out_.data() + static_cast<size_t>(k) * kLanes;
      for (int i = 0; i < kLanes; ++i)
        if ((exec >> i) & 1u) d[i] = v[i];
    }
    counters.instructions += sub.counters.instructions;
    sub.counters.instructions = 0;
    if (sub.counters.iteration_cap_lanes) {  // a runaway interpolator: reported like a primitive
      counters.iteration_cap_lanes += sub.counters.iteration_cap_lanes;
      counters.cap_primitive = sub.counters.cap_primitive;
      sub.counters.iteration_cap_lanes = 0;
    }
  }
}

uint64_t PixelExecutor::execute(const CompiledPrimitive& prim, const PixelProgram& program, const uint32_t* record,
                                const ChannelLayout& layout, const RasterState& state, int bx, int by,
                                const PackedLanes* packed, uint64_t mask, const BlockTarget& target,
                                const uint32_t* shared_records, const uint32_t* p_in, bool wide_record) {
  ++run_serial_;  // field_hit()'s tapes belong to this run only
  const PixelProgram& p = program;
  const int nch = layout.count;
  const size_t reg_words = static_cast<size_t>(p.num_regs) * kLanes;
  if (regs_.size() < reg_words) regs_.resize(reg_words);
  const size_t xreg_words = static_cast<size_t>(p.num_interp_regs) * nch * kLanes;
  if (xregs_.size() < xreg_words) xregs_.resize(xreg_words);
  const size_t staging_words = static_cast<size_t>(nch) * kLanes;
  if (staging_.size() < staging_words) staging_.resize(staging_words);
  std::fill(staging_.begin(), staging_.begin() + staging_words, 0u);

  uint32_t* R = regs_.data();
  // Built-ins: X, Y at pixel centres; Z from the depth buffer; P given, or (0, 0, 0, 1), and N 0
  // (only for programs that read them: a block's set-up is part of every block's cost).
  if (p.reads_surface || p_in) {
    for (int k = 0; k < 4; ++k)
      for (int i = 0; i < kLanes; ++i)
        R[(kRegP + k) * kLanes + i] = p_in ? p_in[k * kLanes + i] : (k == 3 ? fromF(1.0f) : 0u);
    std::fill_n(R + static_cast<size_t>(kRegN) * kLanes, 3 * kLanes, 0u);
  }
  // X, Y and Z through the lane kernels and the depth loads of lane_kernels.h: whole-vector
  // stores, which the program's first vector loads of them can forward from. (A stall perf
  // showed at the program's first instruction, 8% of a frame of small spheres, was in fact the
  // first read of the instance's record missing the cache: runTile prefetches it now.)
  const LaneIsaTables& isa = laneIsaTables();
  auto kernel = [&](Op op, unsigned wide) { return (*isa.kernels)[static_cast<size_t>(op)][wide]; };
  uint32_t* const RX = R + static_cast<size_t>(kRegX) * kLanes;
  uint32_t* const RY = R + static_cast<size_t>(kRegY) * kLanes;
  uint32_t* const RZ = R + static_cast<size_t>(kRegZ) * kLanes;
  static const uint32_t kHalf = fromF(0.5f);
  alignas(64) uint32_t scratch[kLanes];
  if (packed) {
    // Each lane its own pixel: float(x) + 0.5, as the aligned block's float(bx + column) + 0.5.
    const uint32_t* px = reinterpret_cast<const uint32_t*>(packed->x);
    const uint32_t* py = reinterpret_cast<const uint32_t*>(packed->y);
    kernel(Op::I2F, 1)(scratch, px, kZeroLanes, kZeroLanes, kZeroLanes, 0);
    kernel(Op::FAdd, 1)(RX, scratch, &kHalf, kZeroLanes, kZeroLanes, 0);
    kernel(Op::I2F, 1)(scratch, py, kZeroLanes, kZeroLanes, kZeroLanes, 0);
    kernel(Op::FAdd, 1)(RY, scratch, &kHalf, kZeroLanes, kZeroLanes, 0);
    if (target.depth) {
      alignas(64) int32_t offset[kLanes];  // y * stride + x
      const uint32_t stride = static_cast<uint32_t>(target.depth_stride);
      kernel(Op::IMul, 1)(scratch, py, &stride, kZeroLanes, kZeroLanes, 0);
      kernel(Op::IAdd, 3)(reinterpret_cast<uint32_t*>(offset), scratch, px, kZeroLanes, kZeroLanes, 0);
      isa.masks.gather(RZ, target.depth, offset, mask);
    } else {
      std::fill_n(RZ, kLanes, 0u);
    }
  } else {
    // Column and row offsets of the lanes' pixel centres (exact: float(bx) + (c + 0.5) is
    // float(bx + c) + 0.5 for every pixel coordinate a framebuffer has).
    alignas(64) static const std::array<uint32_t, kLanes> kColumn = [] {
      std::array<uint32_t, kLanes> t{};
      for (int i = 0; i < kLanes; ++i) t[static_cast<size_t>(i)] = fromF(static_cast<float>(i % kBlockSize) + 0.5f);
      return t;
    }();
    alignas(64) static const std::array<uint32_t, kLanes> kRow = [] {
      std::array<uint32_t, kLanes> t{};
      for (int i = 0; i < kLanes; ++i) t[static_cast<size_t>(i)] = fromF(static_cast<float>(i / kBlockSize) + 0.5f);
      return t;
    }();
    const uint32_t fx = fromF(static_cast<float>(bx)), fy = fromF(static_cast<float>(by));
    kernel(Op::FAdd, 1)(RX, kColumn.data(), &fx, kZeroLanes, kZeroLanes, 0);
    kernel(Op::FAdd, 1)(RY, kRow.data(), &fy, kZeroLanes, kZeroLanes, 0);
    if (target.depth)
      isa.masks.load_block(RZ, target.depth + static_cast<size_t>(by) * target.depth_stride + bx, target.depth_stride,
                           mask);
    else
      std::fill_n(RZ, kLanes, 0u);
  }

  // A gang's record: kLanes words per record word.
  const size_t record_stride = wide_record ? static_cast<size_t>(kLanes) : 1u;
  const uint32_t* xrecord = record + p.num_uniform_slots * record_stride;
  // Pointer to an operand's lanes (wide) or its single value (scalar).
  auto src = [&](uint32_t o, bool& wide) -> const uint32_t* {
    uint32_t i = operandIndex(o);
    switch (operandKind(o)) {
      case OperandKind::Reg: wide = true; return R + static_cast<size_t>(i) * kLanes;
      case OperandKind::Uniform: wide = wide_record; return record + i * record_stride;
      case OperandKind::Const: wide = false; return &p.constants[i];
      case OperandKind::Param: break;
    }
    wide = false;
    return kZeroLanes;
  };
  // Interp operand, channel c.
  auto xsrc = [&](uint32_t o, int c, bool& wide) -> const uint32_t* {
    uint32_t i = operandIndex(o);
    if (operandKind(o) == OperandKind::Reg) {
      wide = true;
      return xregs_.data() + (static_cast<size_t>(i) * nch + c) * kLanes;
    }
    wide = wide_record;
    return xrecord + (static_cast<size_t>(i) * nch + c) * record_stride;
  };

  uint64_t alive = mask;
  uint64_t cur = ~0ull;  // the lanes the enclosing ifs and loops let run
  // One frame per open if (cond: its condition) or loop (cond: the lanes that took
  // `continue` this iteration; iterations: its count). `saved` is `cur` before it opened.
  struct MaskFrame {
    uint64_t saved;
    uint64_t cond;
    bool loop;
    uint32_t iterations;
  };
  MaskFrame stack[kMaxMaskDepth];
  int depth = 0;
  // Break / continue: the active lanes leave the `levels` innermost loops (and every if inside
  // them); a continue brings them back at the innermost loop's continue point.
  auto leaveLoop = [&](uint64_t lanes, int levels, bool to_continue) {
    for (int f = depth - 1; f >= 0; --f) {
      if (stack[f].loop && --levels == 0) {
        if (to_continue) stack[f].cond |= lanes;
        break;
      }
      stack[f].saved &= ~lanes;
      if (stack[f].loop) stack[f].cond &= ~lanes;
    }
    cur &= ~lanes;
  };
  alignas(64) uint32_t tmp[kLanes];

  auto run = [&](Op op, uint32_t* dst, const uint32_t* a, bool wa, const uint32_t* b, bool wb,
                 const uint32_t* c, bool wc, uint64_t exec, const uint32_t* d = kZeroLanes, bool wd = false,
                 uint32_t imm = 0) {
    LaneKernel k = (*isa.kernels)[static_cast<size_t>(op)][(wa ? 1 : 0) | (wb ? 2 : 0) | (wc ? 4 : 0) | (wd ? 8 : 0)];
    if (exec == ~0ull) {
      k(dst, a, b, c, d, imm);
    } else {
      k(tmp, a, b, c, d, imm);
      isa.masks.blend(dst, tmp, exec);
    }
  };
  auto forChannels = [&](uint16_t set, auto&& fn) {
    for (int kind = 0; kind < kInterpKindCount; ++kind)
      if (set & (1u << kind))
        for (int ch = layout.kind_begin[kind]; ch < layout.kind_end[kind]; ++ch) fn(ch);
  };

  const size_t n = p.code.size();
  const DecodedInstr* const dec = decoded(p, isa, wide_record).code.data();
  // The decoded operands' bases (OperandBase order).
  const uint32_t* const bases[4] = {R, record, p.constants.data(), kZeroLanes};
  uint64_t executed = 0;
  struct CountOnExit {  // counted however the block ends
    uint64_t& total;
    uint64_t& n;
    ~CountOnExit() { total += n; }
  } count_on_exit{counters.instructions, executed};
  for (size_t pc = 0; pc < n;) {
    const DecodedInstr& d = dec[pc];
    const Instr& ins = p.code[pc++];
    ++executed;
    const uint64_t exec = alive & cur;
    if (d.kernel) {
      // A value instruction, decoded: a value written once writes every lane (see
      // Instr::masked_write); a merge value under a partial mask goes through a blend.
      const uint32_t* a = bases[static_cast<int>(d.base[0])] + d.offset[0];
      const uint32_t* b = bases[static_cast<int>(d.base[1])] + d.offset[1];
      const uint32_t* c = bases[static_cast<int>(d.base[2])] + d.offset[2];
      const uint32_t* e = bases[static_cast<int>(d.base[3])] + d.offset[3];
      if (!d.masked_write || exec == ~0ull) {
        d.kernel(R + d.dst, a, b, c, e, d.imm);
      } else {
        d.kernel(tmp, a, b, c, e, d.imm);
        isa.masks.blend(R + d.dst, tmp, exec);
      }
      continue;
    }
    switch (ins.op) {
      case Op::Jmp: pc = ins.a; continue;
      case Op::JmpIfNot: {
        // A uniform condition: in a register (computed per iteration of a loop), every active
        // lane holds the same value; read the first one. (In a gang block's wide record too:
        // its instances agree on the program's branch_slots.)
        bool w;
        const uint32_t* c = src(ins.b, w);
        if (w ? (exec == 0 || !c[__builtin_ctzll(exec)]) : !c[0]) pc = ins.a;
        continue;
      }
      case Op::JmpIfNone:
        if (exec == 0) pc = ins.a;
        continue;
      case Op::MaskIf: {
        bool w;
        const uint32_t* c = src(ins.b, w);
        if (depth >= kMaxMaskDepth) return 0;  // codegen rejects deeper nesting; never reached
        stack[depth++] = {cur, laneMaskOf(isa.masks, c, w), false, 0};
        cur &= stack[depth - 1].cond;
        continue;
      }
      case Op::LoopBegin:
        if (depth >= kMaxMaskDepth) return 0;  // codegen rejects deeper nesting; never reached
        stack[depth++] = {cur, 0, true, 0};
        continue;
      case Op::LoopTest: {
        bool w;
        const uint32_t* c = src(ins.b, w);
        cur &= laneMaskOf(isa.masks, c, w);
        continue;
      }
      case Op::Break: leaveLoop(exec, ins.imm > 1 ? ins.imm : 1, false); continue;
      case Op::Continue: leaveLoop(exec, 1, true); continue;
      case Op::LoopContinue:
        if (depth > 0) {
          cur |= stack[depth - 1].cond & alive;
          stack[depth - 1].cond = 0;
        }
        continue;
      case Op::LoopBack:
        if (depth > 0 && ++stack[depth - 1].iterations >= state.iteration_cap) {
          // Runaway: the lanes still looping stop here and draw nothing.
          uint64_t stuck = alive & cur;
          counters.iteration_cap_lanes += static_cast<uint64_t>(laneCount(stuck));
          counters.cap_primitive = &prim;
          alive &= ~stuck;
          cur = 0;
          if (alive == 0) return 0;
        }
        pc = ins.a;
        continue;
      case Op::LoopEnd:
        if (depth > 0) cur = stack[--depth].saved;
        continue;
      case Op::MaskElse:
        if (depth > 0) cur = stack[depth - 1].saved & ~stack[depth - 1].cond;
        continue;
      case Op::MaskEnd:
        if (depth > 0) cur = stack[--depth].saved;
        continue;
      case Op::Retire:
        alive &= ~exec;
        if (alive == 0) return 0;
        continue;
      case Op::ZTest: {
        // The depth function as a comparison kernel of (Z, the depth buffer's value).
        bool w;
        const uint32_t* z = src(ins.a, w);
        uint32_t* d = R + static_cast<size_t>(operandIndex(ins.dst)) * kLanes;
        const uint32_t* zb = R + kRegZ * kLanes;
        static const uint32_t kFalse = 0u, kTrue = 1u;
        switch (state.depth_test ? state.depth_func : DepthFunc::Always) {
          case DepthFunc::Never: run(Op::Mov, d, &kFalse, false, kZeroLanes, false, kZeroLanes, false, exec); break;
          case DepthFunc::Always: run(Op::Mov, d, &kTrue, false, kZeroLanes, false, kZeroLanes, false, exec); break;
          case DepthFunc::Less: run(Op::FLt, d, z, w, zb, true, kZeroLanes, false, exec); break;
          case DepthFunc::LessEqual: run(Op::FLe, d, z, w, zb, true, kZeroLanes, false, exec); break;
          case DepthFunc::Greater: run(Op::FLt, d, zb, true, z, w, kZeroLanes, false, exec); break;
          case DepthFunc::GreaterEqual: run(Op::FLe, d, zb, true, z, w, kZeroLanes, false, exec); break;
          case DepthFunc::Equal: run(Op::FEq, d, z, w, zb, true, kZeroLanes, false, exec); break;
          case DepthFunc::NotEqual: run(Op::FNe, d, z, w, zb, true, kZeroLanes, false, exec); break;
        }
        // User clip planes: a fragment they clip fails (RasterState::clipKeeps, as native code).
        if (state.clip_plane_count > 0)
          for (uint64_t m = exec; m != 0; m &= m - 1) {
            const int i = __builtin_ctzll(m);
            if (!state.clipKeeps(asF(RX[i]), asF(RY[i]), asF(w ? z[i] : z[0]))) d[i] = 0u;
          }
        // polygon_ztest(): the polygon stipple fails the fragments its pattern drops (as native code).
        if (ins.imm != 0 && state.polygon_stipple)
          for (uint64_t m = exec; m != 0; m &= m - 1) {
            const int i = __builtin_ctzll(m);
            if (!state.stippleKeeps(asF(RX[i]), asF(RY[i]))) d[i] = 0u;
          }
        continue;
      }
      case Op::FieldBox:
        for (int k = 0; k < 3; ++k) {
          bool w;
          const uint32_t* v = src(k == 0 ? ins.a : k == 1 ? ins.b : ins.c, w);
          field_box_[ins.imm * 3 + k] = asF(w ? v[exec ? __builtin_ctzll(exec) : 0] : v[0]);
        }
        continue;
      case Op::FieldHit: {
        // Uniform operands (the compiler requires it): the first active lane's value.
        const int lane = exec ? __builtin_ctzll(exec) : 0;
        float u[3];
        for (int k = 0; k < 3; ++k) {
          bool w;
          const uint32_t* v = src(k == 0 ? ins.a : k == 1 ? ins.b : ins.c, w);
          u[k] = asF(w ? v[lane] : v[0]);
        }
        alignas(64) float t[kLanes];
        const uint64_t capped_before = counters.iteration_cap_lanes;
        fieldHit(state, bx, by, exec, u[0], u[1], u[2], t);
        // Rays the search stopped at the cap are this primitive's runaway lanes, named in its report.
        if (counters.iteration_cap_lanes != capped_before) counters.cap_primitive = &prim;
        std::memcpy(tmp, t, sizeof t);
        isa.masks.blend(R + static_cast<size_t>(operandIndex(ins.dst)) * kLanes, tmp, exec);
        continue;
      }
      case Op::FieldGradient:
      case Op::FieldColor: {
        // A point (a, b, c) per lane and the field d (uniform: the first active lane's).
        const float* p[3];
        bool wide[3];
        for (int k = 0; k < 3; ++k)
          p[k] = reinterpret_cast<const float*>(src(k == 0 ? ins.a : k == 1 ? ins.b : ins.c, wide[k]));
        bool wf;
        const uint32_t* fv = src(ins.d, wf);
        const float field = asF(wf ? fv[exec ? __builtin_ctzll(exec) : 0] : fv[0]);
        alignas(64) float v[kLanes];
        if (ins.op == Op::FieldGradient)
          fieldGradient(state, exec, field, ins.imm & 3, (ins.imm & 4) != 0, p, wide, v);
        else
          fieldColor(state, exec, field, ins.imm, p, wide, v);
        std::memcpy(tmp, v, sizeof v);
        isa.masks.blend(R + static_cast<size_t>(operandIndex(ins.dst)) * kLanes, tmp, exec);
        continue;
      }
      case Op::ZCommit: {
        if (!target.depth || !state.depth_test || !state.depth_write) continue;
        bool w;
        const uint32_t* z = src(ins.a, w);
        if (packed) {
          for (uint64_t m = exec; m; m &= m - 1) {
            const int i = __builtin_ctzll(m);
            target.depth[static_cast<size_t>(packed->y[i]) * target.depth_stride + packed->x[i]] = asF(w ? z[i] : z[0]);
          }
          continue;
        }
        // Row by row; whole rows of a wide Z by memcpy (the lanes outside exec may lie past the
        // framebuffer's edge: never touched).
        for (int row = 0; row < kBlockSize; ++row) {
          const unsigned row_mask = static_cast<unsigned>(exec >> (row * kBlockSize)) & ((1u << kBlockSize) - 1u);
          if (row_mask == 0) continue;
          float* depth = target.depth + static_cast<size_t>(by + row) * target.depth_stride + bx;
          const uint32_t* zr = w ? z + row * kBlockSize : nullptr;
          if (zr && row_mask == (1u << kBlockSize) - 1u) {
            std::memcpy(depth, zr, sizeof(float) * kBlockSize);
            continue;
          }
          for (int lx = 0; lx < kBlockSize; ++lx)
            if ((row_mask >> lx) & 1u) depth[lx] = asF(zr ? zr[lx] : z[0]);
        }
        continue;
      }
      case Op::InterpReturn:
        forChannels(ins.imm, [&](int ch) {
          bool w;
          const uint32_t* v = xsrc(ins.a, ch, w);
          run(Op::Mov, staging_.data() + static_cast<size_t>(ch) * kLanes, v, w, kZeroLanes, false,
              kZeroLanes, false, exec);
        });
        continue;
      case Op::InterpShared: {
        // The shared interpolators bound to the Shared channels, at surface point P.
        const uint32_t* pv[4];
        bool pw[4];
        const uint32_t ops[4] = {ins.a, ins.b, ins.c, ins.d};
        for (int k = 0; k < 4; ++k) pv[k] = src(ops[k], pw[k]);
        runSharedInterpolators(prim, layout, state, bx, by, packed, exec, pv, pw, shared_records);
        continue;
      }
      case Op::SurfaceCommit: {  // P (imm 0) or N (imm 1) of the lanes alive at the end
        const uint32_t ops[4] = {ins.a, ins.b, ins.c, ins.d};
        for (int k = 0; k < (ins.imm == 0 ? 4 : 3); ++k) {
          bool w;
          const uint32_t* v = src(ops[k], w);
          run(Op::Mov, surface_.data() + static_cast<size_t>(ins.imm * 4 + k) * kLanes, v, w, kZeroLanes, false,
              kZeroLanes, false, exec);
        }
        continue;
      }
      case Op::ShadeOut: {  // a shared interpolator's value
        const uint32_t ops[4] = {ins.a, ins.b, ins.c, ins.d};
        if (shade_out_.size() < 4 * kLanes) shade_out_.assign(4 * kLanes, 0u);
        for (int k = 0; k < 4; ++k) {
          bool w;
          const uint32_t* v = src(ops[k], w);
          run(Op::Mov, shade_out_.data() + static_cast<size_t>(k) * kLanes, v, w, kZeroLanes, false, kZeroLanes, false, exec);
        }
        continue;
      }
      case Op::HasNamed: {  // uniform; here only inside a loop that runs per pixel
        uint32_t* d = regs_.data() + static_cast<size_t>(operandIndex(ins.dst)) * kLanes;
        std::fill(d, d + kLanes,
                  layout.bindsInterpolator(prim.named_interpolators[static_cast<size_t>(ins.imm)]) ? 1u : 0u);
        continue;
      }
      case Op::InterpNamedReturn: {  // the primitive's own value for channels of a shared interpolator
        const std::string& name = prim.named_interpolators[static_cast<size_t>(ins.imm)];
        const uint32_t ops[4] = {ins.a, ins.b, ins.c, ins.d};
        for (const ChannelLayout::SharedInterpolator& s : layout.shared) {
          if (s.program->name != name) continue;
          for (int k = 0; k < 4; ++k) {
            bool w;
            const uint32_t* v = src(ops[k], w);
            run(Op::Mov, staging_.data() + static_cast<size_t>(s.first + k) * kLanes, v, w, kZeroLanes, false,
                kZeroLanes, false, exec);
          }
        }
        continue;
      }
      case Op::HasKinds: {  // uniform; here only inside a loop that runs per pixel
        uint32_t* d = regs_.data() + static_cast<size_t>(operandIndex(ins.dst)) * kLanes;
        std::fill(d, d + kLanes, layout.hasKinds(ins.imm) ? 1u : 0u);
        continue;
      }
      case Op::LoadState: {  // uniform; here inside a loop that runs per pixel
        uint32_t* d = R + static_cast<size_t>(operandIndex(ins.dst)) * kLanes;
        std::fill(d, d + kLanes, fromF(stateValue(state, ins.imm)));
        continue;
      }
      case Op::XLoadVertex: case Op::Bound: case Op::Kill: case Op::OpCount:
      case Op::LoadParamAt: case Op::XLoadVertexAt: case Op::OutParam: case Op::OutVertex: case Op::Emit:
      case Op::BackFacing: case Op::DepthBound:
        continue;  // setup-only instructions never reach a pixel program
      case Op::XSel:
        forChannels(ins.imm, [&](int ch) {
          bool wc, wa, wb;
          const uint32_t* cond = src(ins.a, wc);
          const uint32_t* a = xsrc(ins.b, ch, wa);
          const uint32_t* b = xsrc(ins.c, ch, wb);
          uint32_t* d = xregs_.data() + (static_cast<size_t>(operandIndex(ins.dst)) * nch + ch) * kLanes;
          run(Op::Sel, d, cond, wc, a, wa, b, wb, ins.masked_write ? exec : ~0ull);
        });
        continue;
      case Op::XAdd: case Op::XSub: case Op::XMulF: case Op::XDivF: case Op::XNeg: case Op::XMov: {
        Op scalar_op = ins.op == Op::XAdd ? Op::FAdd : ins.op == Op::XSub ? Op::FSub
                       : ins.op == Op::XMulF ? Op::FMul : ins.op == Op::XDivF ? Op::FDiv
                       : ins.op == Op::XNeg ? Op::FNeg : Op::Mov;
        bool float_b = ins.op == Op::XMulF || ins.op == Op::XDivF;
        forChannels(ins.imm, [&](int ch) {
          bool wa, wb = false;
          const uint32_t* a = xsrc(ins.a, ch, wa);
          const uint32_t* b = kZeroLanes;
          if (ins.b != kNoOperand) b = float_b ? src(ins.b, wb) : xsrc(ins.b, ch, wb);
          uint32_t* d = xregs_.data() + (static_cast<size_t>(operandIndex(ins.dst)) * nch + ch) * kLanes;
          run(scalar_op, d, a, wa, b, wb, kZeroLanes, false, ins.masked_write ? exec : ~0ull);
        });
        continue;
      }
      default:
        continue;  // the value ops: decoded, run above
    }
  }

  return alive;
}

}  // namespace pf
