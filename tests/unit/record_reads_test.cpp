// compiler/record_reads.h: the record words a pixel program reads on the paths its uniform
// branches take -- a gang block spreads only those. Checked on the triangle: with every vertex in
// front of the eye it never reads the other coverage branch's planes, with a vertex behind it
// reads them; every uniform a taken branch's instructions name is in the set.
#include <gtest/gtest.h>

#include <set>
#include <vector>

#include "compiler/builtin_primitives.h"
#include "compiler/record_reads.h"

using namespace pf;

namespace {

std::set<uint32_t> wordsOf(const std::vector<RecordWordRun>& runs) {
  std::set<uint32_t> w;
  for (const RecordWordRun& r : runs)
    for (uint32_t k = 0; k < r.count; ++k) w.insert(r.first + k);
  return w;
}

// The uniform (scalar) slots instructions [from, to) read.
std::set<uint32_t> uniformsIn(const PixelProgram& p, size_t from, size_t to) {
  std::set<uint32_t> u;
  for (size_t pc = from; pc < to; ++pc) {
    const Instr& in = p.code[pc];
    for (uint32_t o : {in.a, in.b, in.c, in.d})
      if (o != kNoOperand && operandKind(o) == OperandKind::Uniform && in.op != Op::Jmp) u.insert(operandIndex(o));
  }
  return u;
}

}  // namespace

TEST(RecordReads, TheTrianglesUntakenCoverageBranchIsNotRead) {
  const PixelProgram& p = builtinPrimitives().by_name.at("triangles")->pixel;
  ASSERT_FALSE(p.branch_slots.empty());
  // The program's first uniform jump chooses the coverage branch: its slot is the first branch slot.
  size_t jump = 0;
  while (jump < p.code.size() && p.code[jump].op != Op::JmpIfNot) ++jump;
  ASSERT_LT(jump, p.code.size());
  const uint32_t slot = operandIndex(p.code[jump].b);
  const size_t else_at = p.code[jump].a;  // the branch for a vertex behind the eye
  ASSERT_EQ(p.code[else_at - 1].op, Op::Jmp);  // the then-part ends jumping past the else part
  std::vector<uint32_t> record(p.num_uniform_slots + p.num_interp_uniform_slots * 4 + 1, 0u);
  std::vector<RecordWordRun> runs;
  RecordReadsScratch scratch;
  record[slot] = 1;  // every vertex in front: the then-part
  recordWordsRead(p, 4, record.data(), runs, scratch);
  const std::set<uint32_t> in_front = wordsOf(runs);
  for (uint32_t u : uniformsIn(p, jump + 1, else_at)) EXPECT_TRUE(in_front.count(u)) << "slot " << u << " not read";
  size_t missing_from_else = 0;
  for (uint32_t u : uniformsIn(p, else_at, p.code[else_at - 1].a))
    missing_from_else += in_front.count(u) == 0 && uniformsIn(p, jump + 1, else_at).count(u) == 0;
  EXPECT_GT(missing_from_else, 5u) << "the other branch's planes are read";
  record[slot] = 0;  // a vertex behind: the else part
  recordWordsRead(p, 4, record.data(), runs, scratch);
  const std::set<uint32_t> behind = wordsOf(runs);
  for (uint32_t u : uniformsIn(p, else_at, p.code[else_at - 1].a)) EXPECT_TRUE(behind.count(u)) << "slot " << u;
  EXPECT_LT(in_front.size(), p.num_uniform_slots + p.num_interp_uniform_slots * 4);
}
