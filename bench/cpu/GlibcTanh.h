//===- GlibcTanh.h - glibc's tanhf, written to vectorise --------*- C++ -*-===//
//
// glibc's tanhf (fdlibm's, through 2.36 at least) computes tanh from its
// expm1f in plain f32 arithmetic and bit manipulation. This is the same
// algorithm with every branch computed and the right result selected, so a
// `#pragma omp simd` loop maps it onto SIMD lanes and every value gets the
// bits glibc's tanhf returns (sim's --sim-expand-tanh does the same in MLIR;
// utils/check-tanh.sh checks sim's on all 2^32 inputs). Build without
// contraction (-ffp-contract=off): every multiply and add rounds, as glibc's.
//
//===----------------------------------------------------------------------===//

#ifndef SIM_BENCH_CPU_GLIBCTANH_H
#define SIM_BENCH_CPU_GLIBCTANH_H

#include <bit>
#include <cstdint>

#pragma omp declare simd
inline float glibcTanhf(float x) {
  auto bits = [](float v) { return std::bit_cast<uint32_t>(v); };
  auto real = [](uint32_t v) { return std::bit_cast<float>(v); };
  uint32_t jx = bits(x), ix = jx & 0x7fffffffu;
  bool finiteSmall = ix < 0x41b00000u; // |x| < 22
  float ax = finiteSmall ? real(ix) : 1.0f;
  bool big = ix >= 0x3f800000u; // |x| >= 1
  float u = big ? 2.0f * ax : -2.0f * ax;
  // expm1f(u), u in [2, 44) or (-2, -2^-54].
  uint32_t hu = bits(u) & 0x7fffffffu;
  bool negative = (bits(u) & 0x80000000u) != 0;
  bool nearLn2 = hu < 0x3F851592u; // |u| < 1.5 ln2
  const float ln2Hi = real(0x3f317180u), ln2Lo = real(0x3717f7d1u);
  int32_t kFar = (int32_t)(real(0x3fb8aa3bu) * u + (negative ? -0.5f : 0.5f));
  float tFar = (float)kFar;
  float hi = nearLn2 ? u + ln2Hi : u - tFar * ln2Hi;
  float lo = nearLn2 ? -ln2Lo : tFar * ln2Lo;
  float reduced = hi - lo;
  float c = (hi - reduced) - lo;
  bool reduce = hu > 0x3eb17218u; // |u| > 0.5 ln2
  int32_t k = reduce ? (nearLn2 ? -1 : kFar) : 0;
  float xr = reduce ? reduced : u;
  float hfx = 0.5f * xr;
  float hxs = xr * hfx;
  float r1 = 1.0f + hxs * (real(0xbd088889u) +
                           hxs * (real(0x3ad00d01u) +
                                  hxs * (real(0xb8a670cdu) +
                                         hxs * (real(0x36867e54u) +
                                                hxs * real(0xb457edbbu)))));
  float t = 3.0f - r1 * hfx;
  float e = hxs * ((r1 - t) / (6.0f - xr * t));
  float whenZero = xr - (xr * e - hxs);
  float ek = ((xr * (e - c) - c)) - hxs;
  float whenMinusOne = 0.5f * (xr - ek) - 0.5f;
  uint32_t exponent = (uint32_t)k << 23;
  float whenFar = real(bits(1.0f - (ek - xr)) + exponent) - 1.0f;
  int32_t kShift = k < 1 ? 1 : (k > 30 ? 30 : k);
  float tLow = real(0x3f800000u - (0x1000000u >> kShift));
  float whenLow = real(bits(tLow - (ek - xr)) + exponent);
  int32_t kBias = k < 0 ? 0 : (k > 126 ? 126 : k);
  float tHigh = real((uint32_t)(0x7f - kBias) << 23);
  float whenHigh = real(bits((xr - (ek + tHigh)) + 1.0f) + exponent);
  float expm1 = k < 23 ? whenLow : whenHigh;
  expm1 = (k <= -2 || k > 56) ? whenFar : expm1;
  expm1 = k == -1 ? whenMinusOne : expm1;
  expm1 = k == 0 ? whenZero : expm1;
  expm1 = hu < 0x33000000u ? u : expm1;
  // tanhf.
  // Both paths divide by expm1 + 2: one division with the path's numerator.
  float quotient = (big ? 2.0f : -expm1) / (expm1 + 2.0f);
  float z = big ? 1.0f - quotient : quotient;
  z = finiteSmall ? z : 1.0f - 1.0e-30f;
  float r = (int32_t)jx >= 0 ? z : -z;
  r = ix < 0x24000000u ? x * (1.0f + x) : r;
  r = ix == 0 ? x : r;
  // glibc's 1/x +- 1 for inf and NaN: +-1 for inf, which r already is, and
  // the NaN itself (quieted) for NaN, which x + x returns too.
  return ix > 0x7f800000u ? x + x : r;
}

#endif // SIM_BENCH_CPU_GLIBCTANH_H
