#pragma once
// TRIDEM_HD marks a function that runs on the host and, under nvcc, on the device too.
// Physics is written once with it (ARCHITECTURE.md, "Rules of the house").
#if defined(__CUDACC__)
#define TRIDEM_HD __host__ __device__
#else
#define TRIDEM_HD
#endif

// Unrolls a loop of fixed trip count on the device, so that the small arrays it indexes
// stay in registers instead of local memory. The host compilers decide for themselves.
#if defined(__CUDA_ARCH__)
#define TRIDEM_UNROLL _Pragma("unroll")
#else
#define TRIDEM_UNROLL
#endif

#include <math.h>

namespace tridem {
/// Index of the lowest set bit of a non-zero mask.
TRIDEM_HD inline int lowest_bit(unsigned mask) {
#if defined(__CUDA_ARCH__)
  return __ffs(static_cast<int>(mask)) - 1;
#else
  return __builtin_ctz(mask);
#endif
}
}  // namespace tridem

namespace tridem::math {
// Overloads that keep float arithmetic in float on host and device alike (the global
// ::cos of <math.h> would promote a float to double on the host).
TRIDEM_HD inline float sqrt(float x) { return ::sqrtf(x); }
TRIDEM_HD inline double sqrt(double x) { return ::sqrt(x); }
TRIDEM_HD inline float cos(float x) { return ::cosf(x); }
TRIDEM_HD inline double cos(double x) { return ::cos(x); }
TRIDEM_HD inline float sin(float x) { return ::sinf(x); }
TRIDEM_HD inline double sin(double x) { return ::sin(x); }

/// a / b. In float on the device: the reciprocal's approximation times a (__fdividef),
/// which is what -prec-div=false's division computes for every b of magnitude between
/// 2^-126 and 2^126, without its tests and rescaling for the others (seven instructions
/// of the nine; a pair's areas and lengths, in metres about the pair, are never near those
/// bounds). Elsewhere the plain division.
TRIDEM_HD inline float divide(float a, float b) {
#if defined(__CUDA_ARCH__)
  return __fdividef(a, b);
#else
  return a / b;
#endif
}
TRIDEM_HD inline double divide(double a, double b) { return a / b; }

/// The larger and the smaller of a and b, for b a number: a NaN a gives b, as `a > b ? a :
/// b` does. In float on the device one instruction (FMNMX) instead of a compare and a
/// select; elsewhere the comparison.
TRIDEM_HD inline float max(float a, float b) {
#if defined(__CUDA_ARCH__)
  return fmaxf(a, b);
#else
  return a > b ? a : b;
#endif
}
TRIDEM_HD inline float min(float a, float b) {
#if defined(__CUDA_ARCH__)
  return fminf(a, b);
#else
  return a < b ? a : b;
#endif
}
TRIDEM_HD inline double max(double a, double b) { return a > b ? a : b; }
TRIDEM_HD inline double min(double a, double b) { return a < b ? a : b; }
}  // namespace tridem::math
