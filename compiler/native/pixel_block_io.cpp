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

// Lane i's pixel: (bx + (first_lane + i) % 8, by + (first_lane + i) / 8) in an aligned block,
// (lane_x[i], lane_y[i]) in packed ones; X and Y are its centre, computed as the interpreter
// does (the column's offset plus float(bx); float(x) + 0.5).
void PixelCodegen::pixelCoordinates(llvm::Value*& x, llvm::Value*& y) {
  llvm::Value* half = splatF(0.5f);
  if (variant_.shape == NativeBlockShape::Aligned) {
    std::vector<llvm::Constant*> index;
    for (unsigned i = 0; i < width_; ++i) index.push_back(b_.getInt32(i));
    llvm::Value* lane = b_.CreateAdd(b_.CreateVectorSplat(width_, first_lane_), llvm::ConstantVector::get(index));
    llvm::Value* column = b_.CreateAnd(lane, splatI(kNativeBlockSize - 1));
    llvm::Value* row = b_.CreateLShr(lane, splatI(3));
    llvm::Value* fx = b_.CreateVectorSplat(width_, b_.CreateSIToFP(bx_, b_.getFloatTy()));
    llvm::Value* fy = b_.CreateVectorSplat(width_, b_.CreateSIToFP(by_, b_.getFloatTy()));
    x = b_.CreateBitCast(b_.CreateFAdd(b_.CreateFAdd(b_.CreateSIToFP(column, fv_), half), fx), iv_, "X");
    y = b_.CreateBitCast(b_.CreateFAdd(b_.CreateFAdd(b_.CreateSIToFP(row, fv_), half), fy), iv_, "Y");
    return;
  }
  lane_px_ = b_.CreateAlignedLoad(iv_, b_.CreateInBoundsGEP(b_.getInt32Ty(), lane_x_, first_lane_), llvm::Align(4), "px");
  lane_py_ = b_.CreateAlignedLoad(iv_, b_.CreateInBoundsGEP(b_.getInt32Ty(), lane_y_, first_lane_), llvm::Align(4), "py");
  x = b_.CreateBitCast(b_.CreateFAdd(b_.CreateSIToFP(lane_px_, fv_), half), iv_, "X");
  y = b_.CreateBitCast(b_.CreateFAdd(b_.CreateSIToFP(lane_py_, fv_), half), iv_, "Y");
}

// Packed lanes' depth entries: depth + (y * stride + x), the offset in 32-bit arithmetic as
// the interpreter computes it.
llvm::Value* PixelCodegen::depthAddress(llvm::Value* x, llvm::Value* y) {
  llvm::Value* offset = b_.CreateAdd(b_.CreateMul(y, b_.CreateVectorSplat(width_, depth_stride_)), x);
  return b_.CreateInBoundsGEP(b_.getFloatTy(), depth_, b_.CreateSExt(offset, llvm::FixedVectorType::get(b_.getInt64Ty(), width_)));
}

// The depth under the lanes of `in_mask` (others read nothing -- they may lie past the
// framebuffer -- and get 0).
llvm::Value* PixelCodegen::loadDepth(llvm::Value* in_mask) {
  if (variant_.shape != NativeBlockShape::Aligned) {
    llvm::Value* z = b_.CreateMaskedGather(fv_, depthAddress(lane_px_, lane_py_), llvm::Align(4), in_mask,
                                           llvm::Constant::getNullValue(fv_));
    return b_.CreateBitCast(z, iv_, "Z");
  }
  std::vector<llvm::Value*> rows;
  for (const RowPiece& p : rowPieces()) {
    auto* type = llvm::FixedVectorType::get(b_.getFloatTy(), p.count);
    llvm::Value* at = b_.CreateAdd(b_.CreateMul(b_.CreateSExt(p.y, b_.getInt64Ty()), b_.CreateSExt(depth_stride_, b_.getInt64Ty())),
                                   b_.CreateSExt(p.x, b_.getInt64Ty()));
    rows.push_back(b_.CreateMaskedLoad(type, b_.CreateInBoundsGEP(b_.getFloatTy(), depth_, at), llvm::Align(4),
                                       slice(in_mask, p.first, p.count), llvm::Constant::getNullValue(type)));
  }
  return b_.CreateBitCast(concat(rows), iv_, "Z");
}

// ZCommit: the lanes of `mask` write z (the depth buffer's other entries are not touched --
// they may be another thread's or past the framebuffer).
void PixelCodegen::storeDepth(llvm::Value* z, llvm::Value* mask) {
  llvm::Value* zf = b_.CreateBitCast(z, fv_);
  if (variant_.shape != NativeBlockShape::Aligned) {
    b_.CreateMaskedScatter(zf, depthAddress(lane_px_, lane_py_), llvm::Align(4), mask);
    return;
  }
  for (const RowPiece& p : rowPieces()) {
    llvm::Value* at = b_.CreateAdd(b_.CreateMul(b_.CreateSExt(p.y, b_.getInt64Ty()), b_.CreateSExt(depth_stride_, b_.getInt64Ty())),
                                   b_.CreateSExt(p.x, b_.getInt64Ty()));
    storeLanes(slice(zf, p.first, p.count), b_.CreateInBoundsGEP(b_.getFloatTy(), depth_, at),
               slice(mask, p.first, p.count), false);
  }
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
  auto plane = [&](llvm::Value* table, int index) {
    return invariantLoad(b_.getPtrTy(), b_.CreateConstInBoundsGEP1_32(b_.getPtrTy(), table, static_cast<unsigned>(index)));
  };
  const int surface_first = variant_.surface_eye ? 0 : 3;
  llvm::Value* ids = b_.CreateVectorSplat(width_, shade_id_);
  if (variant_.shape != NativeBlockShape::Aligned) {
    // Each lane to its own entry: (y - tile_y0) * 64 + (x - tile_x0).
    llvm::Value* t = b_.CreateAdd(
        b_.CreateMul(b_.CreateSub(lane_py_, b_.CreateVectorSplat(width_, tile_y0_)), splatI(kNativeTileSize)),
        b_.CreateSub(lane_px_, b_.CreateVectorSplat(width_, tile_x0_)));
    auto* i64v = llvm::FixedVectorType::get(b_.getInt64Ty(), width_);
    llvm::Value* offset = b_.CreateSExt(t, i64v);
    b_.CreateMaskedScatter(ids, b_.CreateInBoundsGEP(b_.getInt32Ty(), shade_ids_, offset), llvm::Align(4), alive);
    for (int ch = 0; ch < variant_.channels; ++ch)
      b_.CreateMaskedScatter(b_.CreateLoad(iv_, staging_[static_cast<size_t>(ch)]),
                             b_.CreateInBoundsGEP(b_.getInt32Ty(), plane(planes_, ch), offset), llvm::Align(4), alive);
    for (size_t k = 0; k < surface.size(); ++k)
      b_.CreateMaskedScatter(surface[k],
                             b_.CreateInBoundsGEP(b_.getFloatTy(), plane(surface_planes_, surface_first + static_cast<int>(k)), offset),
                             llvm::Align(4), alive);
    return;
  }
  for (const RowPiece& p : rowPieces()) {
    llvm::Value* t = b_.CreateAdd(b_.CreateMul(b_.CreateSub(p.y, tile_y0_), b_.getInt32(kNativeTileSize)),
                                  b_.CreateSub(p.x, tile_x0_));
    llvm::Value* offset = b_.CreateSExt(t, b_.getInt64Ty());
    llvm::Value* m = slice(alive, p.first, p.count);
    storeLanes(slice(ids, p.first, p.count), b_.CreateInBoundsGEP(b_.getInt32Ty(), shade_ids_, offset), m, true);
    for (int ch = 0; ch < variant_.channels; ++ch)
      storeLanes(slice(b_.CreateLoad(iv_, staging_[static_cast<size_t>(ch)]), p.first, p.count),
                 b_.CreateInBoundsGEP(b_.getInt32Ty(), plane(planes_, ch), offset), m, true);
    for (size_t k = 0; k < surface.size(); ++k)
      storeLanes(slice(surface[k], p.first, p.count),
                 b_.CreateInBoundsGEP(b_.getFloatTy(), plane(surface_planes_, surface_first + static_cast<int>(k)), offset),
                 m, true);
  }
}

}  // namespace pf
