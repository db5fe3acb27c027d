// Compiles the single-source physics for the device, in float and double: the CUDA
// backend calls these same functions, so a host-only construct in src/physics/ must fail
// the build here rather than later. Nothing here is run; the kernel only has to compile.
#include "physics/contact_force.hpp"
#include "physics/integrate.hpp"

namespace tridem::physics {

template <class Real>
__global__ void pair_force_kernel(const Body<Real>* a, const Body<Real>* b,
                                  ContactLaw<Real> law, Real dt, PairSlip<Real>* slip,
                                  PairForce<Real>* out, Pose<Real>* pose, int n) {
  const int i = blockIdx.x * blockDim.x + threadIdx.x;
  if (i >= n) return;
  out[i] = pair_force(a[i], b[i], law, dt, slip[i]);
  const Vec2<Real> r[3] = {a[i].tri.v[0] - a[i].c, a[i].tri.v[1] - a[i].c,
                           a[i].tri.v[2] - a[i].c};
  const Triangle<Real> t = place(a[i].c, Real(0.1), r);
  if (triangles_overlap(t, b[i].tri) || direct_area_overlap(t, b[i].tri))
    integrate_free(pose[i], out[i].force_a, out[i].torque_a, Real(1), Real(1),
                   Vec2<Real>{Real(0), Real(-9.81)}, Real(0.1), dt);
  else
    integrate_prescribed(pose[i], dt);
}

template __global__ void pair_force_kernel<float>(const Body<float>*, const Body<float>*,
                                                  ContactLaw<float>, float, PairSlip<float>*,
                                                  PairForce<float>*, Pose<float>*, int);
template __global__ void pair_force_kernel<double>(const Body<double>*, const Body<double>*,
                                                   ContactLaw<double>, double,
                                                   PairSlip<double>*, PairForce<double>*,
                                                   Pose<double>*, int);

}  // namespace tridem::physics
