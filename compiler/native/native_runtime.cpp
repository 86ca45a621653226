// The helpers native code calls (see native_runtime.h).
#include "compiler/native/native_runtime.h"

#include "compiler/scalar_ops.h"

namespace pf {
namespace {

template <Op OP>
uint32_t unaryLane(uint32_t a) {
  return evalScalar(OP, a, 0u, 0u);
}
template <Op OP>
uint32_t binaryLane(uint32_t a, uint32_t b) {
  return evalScalar(OP, a, b, 0u);
}
uint32_t noiseLane(uint32_t a, uint32_t b, uint32_t c) { return evalScalar(Op::FNoise, a, b, c); }
uint32_t fixedLane(uint32_t op, uint32_t a, uint32_t b, uint32_t c, uint32_t d, uint32_t imm) {
  return evalFixed(static_cast<Op>(op), a, b, c, d, imm);
}

#define PF_UNARY(OP, NAME) {NAME, Op::OP, 1, reinterpret_cast<void*>(&unaryLane<Op::OP>)}
#define PF_BINARY(OP, NAME) {NAME, Op::OP, 2, reinterpret_cast<void*>(&binaryLane<Op::OP>)}
const NativeHelper kHelpers[] = {
    PF_UNARY(FSin, "pf_native_sin"),   PF_UNARY(FCos, "pf_native_cos"),   PF_UNARY(FTan, "pf_native_tan"),
    PF_UNARY(FAsin, "pf_native_asin"), PF_UNARY(FAcos, "pf_native_acos"), PF_UNARY(FAtan, "pf_native_atan"),
    PF_UNARY(FExp, "pf_native_exp"),   PF_UNARY(FLog, "pf_native_log"),   PF_BINARY(FAtan2, "pf_native_atan2"),
    PF_BINARY(FPow, "pf_native_pow"),  {"pf_native_noise", Op::FNoise, 3, reinterpret_cast<void*>(&noiseLane)},
    // Every fixed-point op (imm: its format and half), op passed as the first operand.
    {"pf_native_fixed", Op::QAdd, 6, reinterpret_cast<void*>(&fixedLane)},
};
#undef PF_UNARY
#undef PF_BINARY

}  // namespace

const NativeHelper* nativeHelperFor(Op op) {
  if (op >= Op::QAdd && op <= Op::QConv) return &kHelpers[sizeof kHelpers / sizeof kHelpers[0] - 1];
  for (const NativeHelper& h : kHelpers)
    if (h.op == op && h.arity < 6) return &h;
  return nullptr;
}

const NativeHelper* nativeHelpers(int& count) {
  count = static_cast<int>(sizeof kHelpers / sizeof kHelpers[0]);
  return kHelpers;
}

}  // namespace pf
