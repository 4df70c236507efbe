// ga-benchmark's inverse-kinematics workload (AlgorithmInverseKinematics, a 5-joint arm in 3D
// CGA, f64) on GATL, included by gatl.cpp; our side is benches/examples/peer_ops/ik.rs.
//
// One solve takes five joint angles and returns (R1, R2, R3, T2, R4, Rg, Jg_f): the rotors
// of the joints, the translator of the second joint and the moved gripper point. The arm's
// dimensions are GATL compile-time constants (c<...>), as in ga-benchmark; the angles are run
// time. `Exp` picks the exponential: ga-benchmark's 4th-order Taylor series `expp` (Taylor),
// or GATL's closed-form blade exponential `exp` (Closed; the generators here are lines and a
// translation, blades whose square is a scalar, where it is exact).
#pragma once
#include <tuple>

namespace gatl_ik {

using namespace ga3c;

// ga-benchmark's `expp`: 1 + x + x^2/2 + x^3/6 + x^4/24, evaluated lazily by GATL.
struct Taylor {
  template <class T>
  static auto exp(const T &arg) {
    auto lazy = make_lazy_context(arg);
    auto x = lazy.template argument<0>();
    return lazy.eval(c<1> + x + x * x / c<2> + x * x * x / c<6> + x * x * x * x / c<24>);
  }
  template <class T>
  static auto null_exp(const T &arg) {
    return exp(arg);
  }
};

// GATL's own exponential (closed form on blades), with tolerance 0: at its default tolerance
// (1e-8 on the blade's square) it returns 1 + B for small angles, off by up to 5e-9. For a
// blade whose square GATL knows to be zero (the translation generator t ^ ni) `exp` does not
// compile (it divides by that zero constant), so `null_exp` writes its closed form 1 + B.
struct Closed {
  template <class T>
  static auto exp(const T &arg) {
    // A tolerance that outlives the call: GATL's `exp` keeps a reference to `scalar(tol)` in
    // its lazy context past the statement that makes it (blade_exponential.hpp,
    // `make_lazy_context(arg, scalar(tol))`), so a temporary tolerance, its own default
    // included, is read after its end (seen: runs of one binary on one input differing, the
    // 1 + B branch taken at a half turn). `scalar` of a stored scalar returns a reference to it.
    static const auto zero = scalar(0.0);
    return ga3c::exp(arg, zero);
  }
  template <class T>
  static auto null_exp(const T &arg) {
    return c<1> + arg;
  }
};

// One solve. Joint positions in mm: J1 (d1, 0, d2), J2 one link l12 above it, J3 at the end
// of link l23 and d3 higher, the gripper Jg d4 + d5 further along x. Jg's x is a double (and
// its z the constant 1720: GATL's `point` does not compile a double beside a sum of constants):
// ga-benchmark's `c<1142> / c<10>` is evaluated in GATL's integral constant type, so `point`
// stores Jg's x as 1334 while its ni part uses 1334.2 (Jg is not null) and `dual(J3 ^ Jg ^ ni)`
// has direction 254 with moment 1720 * 254.2 (ga-benchmark's sanity values for Rg and Jg_f
// carry this).
// The other dimensions are integers and stay compile-time constants.
template <class Exp>
auto solve(double a1, double a2, double a3, double a4, double a5) {
  auto d1 = c<200>, d2 = c<680>, d3 = c<150>;  // d4 = 140 is in jg_x
  double jg_x = 200.0 + 880.0 + 140.0 + 114.2;  // d1 + l23 + d4 + d5
  auto l12 = c<890>, l23 = c<880>;
  auto j1 = point(d1, c<0>, d2);
  auto j2 = point(d1, c<0>, d2 + l12);
  auto j3 = point(d1 + l23, c<0>, d2 + l12 + d3);
  auto jg = point(jg_x, c<0>, c<1720>);  // z = d2 + l12 + d3 (a sum fails here too)

  // Joint 1 turns about the z axis.
  auto lz = dual(no ^ point(c<0>, c<0>, c<1>) ^ ni);
  auto r1 = Exp::exp((a1 / c<2>) * lz);

  // Joint 2 turns about the line through J1 along y, carried by joint 1.
  auto l2 = apply_rotor(r1, dual(j1 ^ point(d1, c<1>, d2) ^ ni));
  auto r2 = Exp::exp((a2 / c<2>) * l2);
  auto j2_f = apply_rotor(r2 * r1, j2);

  // Joint 3 about the line through J2 along y, carried by joints 1 and 2.
  auto l3 = apply_rotor(r2 * r1, dual(j2 ^ point(d1, c<1>, d2 + l12) ^ ni));
  auto r3 = Exp::exp((a3 / c<2>) * l3);

  // The translation that joint 2 gave J2, as a translator.
  auto j2_r1 = apply_rotor(r1, j2);
  auto t2v = euclidean_vector(sp(j2_f, e(c<1>)) - sp(j2_r1, e(c<1>)),
                              sp(j2_f, e(c<2>)) - sp(j2_r1, e(c<2>)),
                              sp(j2_f, e(c<3>)) - sp(j2_r1, e(c<3>)));
  auto t2 = Exp::null_exp((-c<1> / c<2>) * (t2v ^ ni));

  // Joint 4 about the (unit) line J3 Jg, joint 5 about the line through J3 along y.
  auto l4 = apply_rotor(r3 * t2 * r1, unit(dual(j3 ^ jg ^ ni)));
  auto r4 = Exp::exp((a4 / c<2>) * l4);
  auto lg = apply_rotor(r4 * r3 * t2 * r1, dual(j3 ^ point(d1 + l23, c<1>, d2 + l12 + d3) ^ ni));
  auto rg = Exp::exp((a5 / c<2>) * lg);
  auto jg_f = apply_rotor(rg * r3 * t2 * r1, jg);
  return std::make_tuple(r1, r2, r3, t2, r4, rg, jg_f);
}

}  // namespace gatl_ik
