// The probe primitive the block-rejection tests share (block_rejection_test.cpp,
// native_rejection_test.cpp): conditions of the kinds primitives use before their first loop --
// an affine edge, a circle's discriminant, a ratio, and a condition on a NaN-prone square root.
#pragma once

namespace pf::test {

inline const char* const kRejectionProbe = R"(
primitive probe(float k[1][8]; varying float X, Y; inout varying float Z) {
    float e = k[0][0] * X + k[0][1] * Y + k[0][2];
    if (e < 0 || (e == 0 && k[0][7] > 0)) return;
    float dx = X - k[0][3];
    float dy = Y - k[0][4];
    float disc = k[0][5] * k[0][5] - dx * dx - dy * dy;
    if (disc < 0) return;
    float r = sqrt(disc) / (k[0][6] - X);
    if (!(r < 2.5)) return;
    Z = 0.5;
}
)";

}  // namespace pf::test
