// The block's memory in native pixel programs (see pixel_codegen_impl.h): the lanes' X and Y,
// the depth under them, depth writes, and the commit of the surviving lanes to the tile's
// G-buffer -- what PixelExecutor::execute's set-up, its ZCommit and runAndCommit do. An
// aligned block's chunk is whole rows (16 lanes: two; 8: one) or half a row (4), each row's
// lanes consecutive in memory; packed lanes are gathered and scattered.
#include <llvm/IR/Intrinsics.h>

#include "compiler/native/pixel_codegen_impl.h"

namespace pf {

std::vector<PixelCodegen::RowPiece> PixelCodegen::rowPieces() {
  std::vector<RowPiece> pieces;
  const unsigned count = std::min<unsigned>(width_, kNativeBlockSize);
  for (unsigned first = 0; first < width_; first += count) {
    llvm::Value* lane = b_.CreateAdd(first_lane_, b_.getInt32(first));
    llvm::Value* x = b_.CreateAdd(bx_, b_.CreateAnd(lane, b_.getInt32(kNativeBlockSize - 1)));
    llvm::Value* y = b_.CreateAdd(by_, b_.CreateLShr(lane, b_.getInt32(3)));
    pieces.push_back(RowPiece{first, count, x, y});
  }
  return pieces;
}

llvm::Value* PixelCodegen::slice(llvm::Value* v, unsigned first, unsigned count) {
  if (first == 0 && count == width_) return v;
  std::vector<int> lanes;
  for (unsigned i = 0; i < count; ++i) lanes.push_back(static_cast<int>(first + i));
  return b_.CreateShuffleVector(v, lanes);
}

llvm::Value* PixelCodegen::concat(const std::vector<llvm::Value*>& pieces) {
  if (pieces.size() == 1) return pieces[0];
  // Two at a time (every piece the same width).
  std::vector<llvm::Value*> level = pieces;
  while (level.size() > 1) {
    std::vector<llvm::Value*> up;
    for (size_t i = 0; i + 1 < level.size(); i += 2) {
      const unsigned n = llvm::cast<llvm::FixedVectorType>(level[i]->getType())->getNumElements();
      std::vector<int> lanes;
      for (unsigned k = 0; k < 2 * n; ++k) lanes.push_back(static_cast<int>(k));
      up.push_back(b_.CreateShuffleVector(level[i], level[i + 1], lanes));
    }
    level = up;
  }
  return level[0];
}

PixelCodegen::Values PixelCodegen::byShape(const std::function<Values()>& aligned, const std::function<Values()>& packed,
                                           llvm::Value* when, const Values& otherwise) {
  llvm::BasicBlock* from = b_.GetInsertBlock();
  llvm::BasicBlock* join = llvm::BasicBlock::Create(ctx_, "shape.join", fn_);
  std::vector<std::pair<llvm::BasicBlock*, Values>> arms;
  if (when) {
    llvm::BasicBlock* run = llvm::BasicBlock::Create(ctx_, "shape.when", fn_);
    b_.CreateCondBr(when, run, join);
    arms.emplace_back(from, otherwise);
    b_.SetInsertPoint(run);
  }
  if (variant_.gang) {
    Values v = packed();
    b_.CreateBr(join);
    arms.emplace_back(b_.GetInsertBlock(), v);
  } else {
    llvm::BasicBlock* a = llvm::BasicBlock::Create(ctx_, "shape.aligned", fn_);
    llvm::BasicBlock* p = llvm::BasicBlock::Create(ctx_, "shape.packed", fn_);
    b_.CreateCondBr(packed_, p, a);
    b_.SetInsertPoint(a);
    Values va = aligned();
    b_.CreateBr(join);
    arms.emplace_back(b_.GetInsertBlock(), va);
    b_.SetInsertPoint(p);
    Values vp = packed();
    b_.CreateBr(join);
    arms.emplace_back(b_.GetInsertBlock(), vp);
  }
  b_.SetInsertPoint(join);
  Values out;
  const size_t n = arms.back().second.size();
  for (size_t k = 0; k < n; ++k) {
    llvm::PHINode* phi = b_.CreatePHI(arms.back().second[k]->getType(), static_cast<unsigned>(arms.size()));
    for (auto& [block, values] : arms) phi->addIncoming(values[k], block);
    out.push_back(phi);
  }
  return out;
}

// Lane i's pixel: (bx + (first_lane + i) % 8, by + (first_lane + i) / 8) in an aligned block,
// (lane_x[i], lane_y[i]) in packed ones; X and Y are its centre, computed as the interpreter
// does (the column's offset plus float(bx); float(x) + 0.5).
void PixelCodegen::pixelCoordinates(llvm::Value*& x, llvm::Value*& y) {
  llvm::Value* half = splatF(0.5f);
  Values v = byShape(
      [&]() -> Values {
        std::vector<llvm::Constant*> index;
        for (unsigned i = 0; i < width_; ++i) index.push_back(b_.getInt32(i));
        llvm::Value* lane = b_.CreateAdd(b_.CreateVectorSplat(width_, first_lane_), llvm::ConstantVector::get(index));
        llvm::Value* column = b_.CreateAnd(lane, splatI(kNativeBlockSize - 1));
        llvm::Value* row = b_.CreateLShr(lane, splatI(3));
        llvm::Value* fx = b_.CreateVectorSplat(width_, b_.CreateSIToFP(bx_, b_.getFloatTy()));
        llvm::Value* fy = b_.CreateVectorSplat(width_, b_.CreateSIToFP(by_, b_.getFloatTy()));
        return {b_.CreateBitCast(b_.CreateFAdd(b_.CreateFAdd(b_.CreateSIToFP(column, fv_), half), fx), iv_),
                b_.CreateBitCast(b_.CreateFAdd(b_.CreateFAdd(b_.CreateSIToFP(row, fv_), half), fy), iv_), splatI(0),
                splatI(0)};
      },
      [&]() -> Values {
        llvm::Value* px = b_.CreateAlignedLoad(iv_, b_.CreateInBoundsGEP(b_.getInt32Ty(), lane_x_, first_lane_), llvm::Align(4));
        llvm::Value* py = b_.CreateAlignedLoad(iv_, b_.CreateInBoundsGEP(b_.getInt32Ty(), lane_y_, first_lane_), llvm::Align(4));
        return {b_.CreateBitCast(b_.CreateFAdd(b_.CreateSIToFP(px, fv_), half), iv_),
                b_.CreateBitCast(b_.CreateFAdd(b_.CreateSIToFP(py, fv_), half), iv_), px, py};
      });
  x = v[0];
  y = v[1];
  lane_px_ = v[2];
  lane_py_ = v[3];
}

// Packed lanes' depth entries: depth + (y * stride + x), the offset in 32-bit arithmetic as
// the interpreter computes it.
llvm::Value* PixelCodegen::depthAddress(llvm::Value* x, llvm::Value* y) {
  llvm::Value* offset = b_.CreateAdd(b_.CreateMul(y, b_.CreateVectorSplat(width_, depth_stride_)), x);
  return b_.CreateInBoundsGEP(b_.getFloatTy(), depth_, b_.CreateSExt(offset, llvm::FixedVectorType::get(b_.getInt64Ty(), width_)));
}

// An aligned row piece's first depth entry.
static llvm::Value* rowAddress(llvm::IRBuilder<>& b, llvm::Value* depth, llvm::Value* stride, llvm::Value* x, llvm::Value* y) {
  llvm::Value* at = b.CreateAdd(b.CreateMul(b.CreateSExt(y, b.getInt64Ty()), b.CreateSExt(stride, b.getInt64Ty())),
                                b.CreateSExt(x, b.getInt64Ty()));
  return b.CreateInBoundsGEP(b.getFloatTy(), depth, at);
}

// The depth under the lanes of `in_mask` (others read nothing -- they may lie past the
// framebuffer -- and get 0); 0 everywhere without a depth buffer.
llvm::Value* PixelCodegen::loadDepth(llvm::Value* in_mask) {
  Values z = byShape(
      [&]() -> Values {
        std::vector<llvm::Value*> rows;
        for (const RowPiece& p : rowPieces()) {
          auto* type = llvm::FixedVectorType::get(b_.getFloatTy(), p.count);
          rows.push_back(b_.CreateMaskedLoad(type, rowAddress(b_, depth_, depth_stride_, p.x, p.y), llvm::Align(4),
                                             slice(in_mask, p.first, p.count), llvm::Constant::getNullValue(type)));
        }
        return {b_.CreateBitCast(concat(rows), iv_)};
      },
      [&]() -> Values {
        llvm::Value* g = b_.CreateMaskedGather(fv_, depthAddress(lane_px_, lane_py_), llvm::Align(4), in_mask,
                                               llvm::Constant::getNullValue(fv_));
        return {b_.CreateBitCast(g, iv_)};
      },
      has_depth_, {splatI(0)});
  return z[0];
}

// ZCommit: the lanes of `mask` write z, where the state writes depth (the depth buffer's other
// entries are not touched -- they may be another thread's or past the framebuffer).
void PixelCodegen::storeDepth(llvm::Value* z, llvm::Value* mask) {
  llvm::Value* zf = b_.CreateBitCast(z, fv_);
  byShape(
      [&]() -> Values {
        for (const RowPiece& p : rowPieces())
          storeLanes(slice(zf, p.first, p.count), rowAddress(b_, depth_, depth_stride_, p.x, p.y),
                     slice(mask, p.first, p.count), false);
        return {};
      },
      [&]() -> Values {
        b_.CreateMaskedScatter(zf, depthAddress(lane_px_, lane_py_), llvm::Align(4), mask);
        return {};
      },
      b_.CreateAnd(depth_write_, any(mask)));
}

// The lanes of `mask` store `value` at consecutive addresses from `address`. `owned`: the
// whole range is this thread's and inside its buffer (the tile's G-buffer), so it may be read
// and written back unchanged where the mask is off -- cheaper than a masked store without
// AVX-512's.
void PixelCodegen::storeLanes(llvm::Value* value, llvm::Value* address, llvm::Value* mask, bool owned) {
  if (owned && variant_.isa != NativeIsa::Avx512) {
    llvm::Value* old = b_.CreateAlignedLoad(value->getType(), address, llvm::Align(4));
    b_.CreateAlignedStore(b_.CreateSelect(mask, value, old), address, llvm::Align(4));
    return;
  }
  b_.CreateMaskedStore(value, address, llvm::Align(4), mask);
}

// runAndCommit's commit: the alive lanes' shading state, channels and surface to the tile's
// G-buffer.
void PixelCodegen::commit(llvm::Value* alive) {
  // The surface: P / w (when the lighting reads P) and N, or zeros if the primitive sets none.
  std::vector<llvm::Value*> surface;
  if (variant_.commit_surface) {
    auto value = [&](int k) { return b_.CreateBitCast(b_.CreateLoad(iv_, surface_[static_cast<size_t>(k)]), fv_); };
    const bool has = variant_.writes_normal;
    if (variant_.surface_eye) {
      llvm::Value* w = has ? value(3) : splatF(1.0f);
      for (int k = 0; k < 3; ++k) surface.push_back(has ? b_.CreateFDiv(value(k), w) : splatF(0.0f));
    }
    for (int k = 0; k < 3; ++k) surface.push_back(has ? value(4 + k) : splatF(0.0f));
  }
  std::vector<llvm::Value*> channels;
  for (int ch = 0; ch < variant_.channels; ++ch) channels.push_back(b_.CreateLoad(iv_, staging_[static_cast<size_t>(ch)]));
  auto plane = [&](llvm::Value* table, int index) {
    return invariantLoad(b_.getPtrTy(), b_.CreateConstInBoundsGEP1_32(b_.getPtrTy(), table, static_cast<unsigned>(index)));
  };
  const int surface_first = variant_.surface_eye ? 0 : 3;
  llvm::Value* ids = b_.CreateVectorSplat(width_, shade_id_);
  byShape(
      [&]() -> Values {
        for (const RowPiece& p : rowPieces()) {
          llvm::Value* t = b_.CreateAdd(b_.CreateMul(b_.CreateSub(p.y, tile_y0_), b_.getInt32(kNativeTileSize)),
                                        b_.CreateSub(p.x, tile_x0_));
          llvm::Value* offset = b_.CreateSExt(t, b_.getInt64Ty());
          llvm::Value* m = slice(alive, p.first, p.count);
          storeLanes(slice(ids, p.first, p.count), b_.CreateInBoundsGEP(b_.getInt32Ty(), shade_ids_, offset), m, true);
          for (int ch = 0; ch < variant_.channels; ++ch)
            storeLanes(slice(channels[static_cast<size_t>(ch)], p.first, p.count),
                       b_.CreateInBoundsGEP(b_.getInt32Ty(), plane(planes_, ch), offset), m, true);
          for (size_t k = 0; k < surface.size(); ++k)
            storeLanes(slice(surface[k], p.first, p.count),
                       b_.CreateInBoundsGEP(b_.getFloatTy(), plane(surface_planes_, surface_first + static_cast<int>(k)),
                                            offset),
                       m, true);
        }
        return {};
      },
      [&]() -> Values {
        // Each lane to its own entry: (y - tile_y0) * 64 + (x - tile_x0).
        llvm::Value* t = b_.CreateAdd(
            b_.CreateMul(b_.CreateSub(lane_py_, b_.CreateVectorSplat(width_, tile_y0_)), splatI(kNativeTileSize)),
            b_.CreateSub(lane_px_, b_.CreateVectorSplat(width_, tile_x0_)));
        llvm::Value* offset = b_.CreateSExt(t, llvm::FixedVectorType::get(b_.getInt64Ty(), width_));
        b_.CreateMaskedScatter(ids, b_.CreateInBoundsGEP(b_.getInt32Ty(), shade_ids_, offset), llvm::Align(4), alive);
        for (int ch = 0; ch < variant_.channels; ++ch)
          b_.CreateMaskedScatter(channels[static_cast<size_t>(ch)],
                                 b_.CreateInBoundsGEP(b_.getInt32Ty(), plane(planes_, ch), offset), llvm::Align(4), alive);
        for (size_t k = 0; k < surface.size(); ++k)
          b_.CreateMaskedScatter(
              surface[k], b_.CreateInBoundsGEP(b_.getFloatTy(), plane(surface_planes_, surface_first + static_cast<int>(k)), offset),
              llvm::Align(4), alive);
        return {};
      });
}

}  // namespace pf
