// The scalar reference interpreter (see reference_interpreter.h).
#include "reference_interpreter.h"

#include <bit>
#include <cmath>
#include <limits>

#include "compiler/scalar_ops.h"
#include "raster/pixel_executor.h"

namespace pf::test {
namespace {

enum class Flow { Normal, Break, Continue, Retire };

struct Outcome {
  Flow flow = Flow::Normal;
  int levels = 0;  // Break: loops still to leave
};

class Interpreter {
 public:
  Interpreter(const IrFunction& f, const std::vector<uint32_t>& params, const std::vector<float>& vc,
              const ChannelLayout& layout, const RasterState& st, float x, float y, float z)
      : f_(f), params_(params), vc_(vc), layout_(layout), st_(st), x_(x), y_(y), z_(z),
        scalar_(f.values.size(), 0u), interp_(f.values.size()) {
    out_.channels.assign(static_cast<size_t>(layout.count), 0.0f);
  }

  ReferencePixel run() {
    Outcome o = block(f_.body);
    out_.drawn = o.flow != Flow::Retire;
    if (!out_.drawn) {
      out_.depth_written = false;
      std::fill(out_.channels.begin(), out_.channels.end(), 0.0f);
    }
    return out_;
  }

 private:
  const IrFunction& f_;
  const std::vector<uint32_t>& params_;
  const std::vector<float>& vc_;
  const ChannelLayout& layout_;
  const RasterState& st_;
  float x_, y_, z_;
  std::vector<uint32_t> scalar_;
  std::vector<std::vector<float>> interp_;
  ReferencePixel out_;
  float field_box_[6] = {0, 0, 0, 0, 0, 0};  // FieldBox's staging, as the executor's

  // The caster for this one pixel, as a lane of its own block: the search of a lane does not
  // depend on the other lanes, so the result must equal the SIMD executor's bit for bit.
  float fieldHit(float id, float method, float param) {
    const field::ImplicitField* f = fieldById(st_, id);
    if (!f) return std::numeric_limits<float>::infinity();
    const field::CastRequest req = fieldCastRequest(st_, f, field_box_, method, param);
    const int px = static_cast<int>(std::floor(x_)), py = static_cast<int>(std::floor(y_));
    const int bx = px - ((px % kBlockSize) + kBlockSize) % kBlockSize, by = py - ((py % kBlockSize) + kBlockSize) % kBlockSize;
    const int lane = (py - by) * kBlockSize + (px - bx);
    float t[kLanes];
    field::FieldRayCaster caster;
    field::FieldCounters counters;
    caster.castBlock(req, bx, by, uint64_t(1) << lane, t, counters);
    return t[lane];
  }

  uint32_t get(int v) const {
    if (v < 0) return 0;
    const Value& val = f_.values[v];
    switch (val.origin) {
      case Value::Origin::Const: return val.bits;
      case Value::Origin::Param: return params_[val.index];
      case Value::Origin::Builtin:
        if (val.index == static_cast<int>(kRegX)) return fromF(x_);
        if (val.index == static_cast<int>(kRegY)) return fromF(y_);
        if (val.index == static_cast<int>(kRegZ)) return fromF(z_);
        return fromF(val.index == static_cast<int>(kRegP) + 3 ? 1.0f : 0.0f);  // P (0, 0, 0, 1), N 0
      case Value::Origin::FieldPoint: return 0;  // only in fields, which this does not run
      case Value::Origin::Temp: break;
    }
    return scalar_[v];
  }
  std::vector<float>& channels(int v) {
    auto& c = interp_[v];
    if (c.size() != static_cast<size_t>(layout_.count)) c.assign(static_cast<size_t>(layout_.count), 0.0f);
    return c;
  }
  template <class Fn>
  void forKinds(int set, Fn fn) {
    for (int k = 0; k < kInterpKindCount; ++k)
      if (set & (1 << k))
        for (int c = layout_.kind_begin[k]; c < layout_.kind_end[k]; ++c) fn(c);
  }
  float state(int which) const { return stateValue(st_, static_cast<uint16_t>(which)); }
  bool depthPasses(float z) const {
    if (!st_.depth_test) return true;
    switch (st_.depth_func) {
      case DepthFunc::Never: return false;
      case DepthFunc::Less: return z < z_;
      case DepthFunc::Equal: return z == z_;
      case DepthFunc::LessEqual: return z <= z_;
      case DepthFunc::Greater: return z > z_;
      case DepthFunc::NotEqual: return z != z_;
      case DepthFunc::GreaterEqual: return z >= z_;
      case DepthFunc::Always: return true;
    }
    return false;
  }

  Outcome block(const IrBlock& b) {
    for (const IrNode& n : b) {
      Outcome o;
      if (n.kind == IrNode::Kind::If) {
        o = block(get(n.cond) ? *n.then_block : *n.else_block);
      } else if (n.kind == IrNode::Kind::Loop) {
        o = loop(n);
      } else {
        o = inst(n.inst);
      }
      if (o.flow != Flow::Normal) return o;
    }
    return {};
  }

  Outcome loop(const IrNode& n) {
    for (uint32_t iterations = 0;;) {
      Outcome c = block(*n.cond_block);
      if (c.flow != Flow::Normal) return c;
      if (!get(n.cond)) return {};
      Outcome b = block(*n.body_block);
      if (b.flow == Flow::Retire) return b;
      if (b.flow == Flow::Break) return b.levels > 1 ? Outcome{Flow::Break, b.levels - 1} : Outcome{};
      Outcome s = block(*n.step_block);
      if (s.flow == Flow::Retire) return s;
      if (++iterations >= st_.iteration_cap) {  // as the executors: the pixel stops
        out_.iteration_cap_hit = true;
        return {Flow::Retire, 0};
      }
    }
  }

  Outcome inst(const IrInst& in) {
    switch (in.op) {
      case Op::Retire: return {Flow::Retire, 0};
      case Op::Break: return {Flow::Break, in.imm > 1 ? in.imm : 1};
      case Op::Continue: return {Flow::Continue, 1};
      case Op::Bound: case Op::Kill: case Op::InterpShared: case Op::SurfaceCommit: return {};
      // Calls of other primitives submit instances the reference of this one does not draw.
      case Op::OutParam: case Op::OutVertex: case Op::Emit: case Op::BackFacing: case Op::DepthBound: return {};
      case Op::LoadParamAt: {
        const int32_t slot = static_cast<int32_t>(get(in.a));
        const int64_t at = static_cast<int64_t>(slot) + in.imm;
        scalar_[in.dst] = slot >= 0 && at < static_cast<int64_t>(params_.size()) ? params_[at] : 0u;
        return {};
      }
      case Op::XLoadVertexAt: {
        const int32_t i = static_cast<int32_t>(get(in.a));
        const int64_t count = layout_.count ? static_cast<int64_t>(vc_.size()) / layout_.count : 0;
        std::vector<float>& d = channels(in.dst);
        for (int c = 0; c < layout_.count; ++c)
          d[c] = i >= 0 && i < count ? vc_[static_cast<size_t>(i) * layout_.count + c] : 0.0f;
        return {};
      }
      case Op::XSel: {
        const bool pick_a = get(in.a) != 0;
        std::vector<float> a = channels(in.b), b = channels(in.c);
        std::vector<float>& d = channels(in.dst);
        forKinds(in.imm, [&](int c) { d[c] = pick_a ? a[c] : b[c]; });
        return {};
      }
      case Op::ZCommit:
        if (st_.depth_test && st_.depth_write) {
          out_.depth_written = true;
          out_.depth = asF(get(in.a));
        }
        return {};
      case Op::InterpReturn: {
        const std::vector<float>& v = channels(in.a);
        forKinds(in.imm, [&](int c) { out_.channels[c] = v[c]; });
        return {};
      }
      case Op::ZTest:  // (imm 1, polygon_ztest(): the polygon stipple too)
        scalar_[in.dst] = depthPasses(asF(get(in.a))) && (in.imm == 0 || !st_.polygon_stipple || st_.stippleKeeps(x_, y_)) ? 1u : 0u;
        return {};
      case Op::FieldBox:
        for (int k = 0; k < 3; ++k) field_box_[in.imm * 3 + k] = asF(get(k == 0 ? in.a : k == 1 ? in.b : in.c));
        return {};
      case Op::FieldHit: scalar_[in.dst] = fromF(fieldHit(asF(get(in.a)), asF(get(in.b)), asF(get(in.c)))); return {};
      case Op::FieldGradient: {
        const field::ImplicitField* f = fieldById(st_, asF(get(in.d)));
        const float q[3] = {asF(get(in.a)), asF(get(in.b)), asF(get(in.c))};
        if (!f) {
          scalar_[in.dst] = fromF(0.0f);
          return {};
        }
        field::GradientEvaluator ge(f->tape);
        scalar_[in.dst] = fromF(fieldGradientAt(ge, q, in.imm & 3, (in.imm & 4) != 0));
        return {};
      }
      case Op::FieldColor: {
        const field::ImplicitField* f = fieldById(st_, asF(get(in.d)));
        const size_t k = static_cast<size_t>(in.imm);
        if (!f || k >= f->attributes.size()) {
          scalar_[in.dst] = fromF(1.0f);
          return {};
        }
        field::FloatEvaluator fe(f->attributes[k]);
        scalar_[in.dst] = fromF(fe.evaluate(asF(get(in.a)), asF(get(in.b)), asF(get(in.c))));
        return {};
      }
      case Op::LoadState: scalar_[in.dst] = fromF(state(in.imm)); return {};
      case Op::HasKinds: scalar_[in.dst] = layout_.hasKinds(static_cast<unsigned>(in.imm)) ? 1u : 0u; return {};
      case Op::HasNamed:
        scalar_[in.dst] = layout_.bindsInterpolator(f_.named_interpolators[static_cast<size_t>(in.imm)]) ? 1u : 0u;
        return {};
      case Op::InterpNamedReturn: {  // the channels of the shared interpolators of that name
        const int ops[4] = {in.a, in.b, in.c, in.d};
        for (const ChannelLayout::SharedInterpolator& s : layout_.shared)
          if (s.program->name == f_.named_interpolators[static_cast<size_t>(in.imm)])
            for (int k = 0; k < 4; ++k) out_.channels[static_cast<size_t>(s.first + k)] = asF(get(ops[k]));
        return {};
      }
      case Op::XLoadVertex: {
        std::vector<float>& d = channels(in.dst);
        for (int c = 0; c < layout_.count; ++c) d[c] = vc_[static_cast<size_t>(in.imm) * layout_.count + c];
        return {};
      }
      case Op::XAdd: case Op::XSub: case Op::XMulF: case Op::XDivF: case Op::XNeg: case Op::XMov: {
        std::vector<float> a = channels(in.a);
        std::vector<float> b = in.b >= 0 && (in.op == Op::XAdd || in.op == Op::XSub) ? channels(in.b) : std::vector<float>();
        float k = in.op == Op::XMulF || in.op == Op::XDivF ? asF(get(in.b)) : 0.0f;
        std::vector<float>& d = channels(in.dst);
        forKinds(in.imm, [&](int c) {
          switch (in.op) {
            case Op::XAdd: d[c] = a[c] + b[c]; break;
            case Op::XSub: d[c] = a[c] - b[c]; break;
            case Op::XMulF: d[c] = a[c] * k; break;
            case Op::XDivF: d[c] = a[c] / k; break;
            case Op::XNeg: d[c] = -a[c]; break;
            default: d[c] = a[c];
          }
        });
        return {};
      }
      default:
        scalar_[in.dst] = evalScalar(in.op, get(in.a), get(in.b), get(in.c), get(in.d), static_cast<uint32_t>(in.imm));
        return {};
    }
  }
};

}  // namespace

ReferencePixel runReference(const IrFunction& f, const std::vector<uint32_t>& params,
                            const std::vector<float>& vertex_channels, const ChannelLayout& layout,
                            const RasterState& state, float x, float y, float depth_in) {
  Interpreter in(f, params, vertex_channels, layout, state, x, y, depth_in);
  return in.run();
}

}  // namespace pf::test
