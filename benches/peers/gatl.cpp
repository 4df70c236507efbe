// GATL (laffernandes/gatl, C++17 templates, `ga3c`: CGA of R^3) as the peer of the CGA f64 rows
// of `peer_ops`.
//
//   gatl-peer INPUT OUT_PREFIX
//
// Operands are GATL expressions with compile-time basis blades and run-time coefficients
// (`x * (no ^ e1) + ...`), built before timing; each timed op is one GATL call on them:
// `gp(a, b)`, and for a motor on a point the lazy `M P ~M` (GATL's way to fuse a sandwich).
// Blade order and signs: GATL's basis is e1, e2, e3, no, ni (bits 0..4) with no . ni = -1, the
// metric of `algebras/cga.toml`, whose basis order is eo, e1, e2, e3, ei. Our blade `eo12i` is
// `no ^ e1 ^ e2 ^ ni`, which GATL stores as `e1 ^ e2 ^ no ^ ni` times the sign of the
// permutation that sorts (4, 1, 2, 5) ascending: `blade()` computes bits and sign for each of
// our blade names. Components of a result that our type does not hold must be zero (checked).
// Built by `run.sh` (-O3 -DNDEBUG, no -march).
#include "gatl_common.hpp"
#include "gatl_ik.hpp"

template <class M, class P>
static auto sandwich(const M &m, const P &p) {
  auto [lazy, m_, p_] = make_lazy_context_tuple(m, p);
  return lazy.eval(m_ * p_ * ~m_);
}

// Times `out[i] = op(a[i], b[i])` and records the outputs in our blade order.
template <class A, class B, class Op>
static void row(Record &rec, const char *key, const std::vector<A> &a, const std::vector<B> &b,
                Op op, const std::vector<std::string> &blades, double &stray) {
  std::vector<decltype(op(a[0], b[0]))> out(N);
  double ns = time_pass([&] {
    for (std::size_t i = 0; i < N; ++i) out[i] = op(a[i], b[i]);
    clobber(out.data());
  });
  double s = 0;
  rec.add(key, ns, ours(out, blades, s));
  if (s > 1e-9) std::fprintf(stderr, "gatl-peer: %s has components outside our type, up to %g\n", key, s);
  stray = std::max(stray, s);
}

// The operation set (gatl_ops.cpp, one object per left grade GA: its binary rows (GA, 0..5) and
// its unary rows of grade GA).
namespace gatl_ops {
template <int GA> void rows(Record &rec, Input &in, double &stray);
}

// Times ga-benchmark's inverse kinematics (gatl_ik.hpp), one solve per 5 angles, and records
// (R1, R2, R3, T2, R4, Rg, Jg_f) per solve as our Rotor, 4 Motors, Translator, Vector (45 values;
// the order of peer_ops' ik.rs).
template <class Exp>
static void ik_row(Record &rec, const char *key, const std::vector<double> &ang, double &stray) {
  std::vector<decltype(gatl_ik::solve<Exp>(0.0, 0.0, 0.0, 0.0, 0.0))> out(N);
  double ns = time_pass([&] {
    for (std::size_t i = 0; i < N; ++i) {
      const double *a = ang.data() + 5 * i;
      out[i] = gatl_ik::solve<Exp>(a[0], a[1], a[2], a[3], a[4]);
    }
    clobber(out.data());
  });
  const std::vector<std::string> rot = {"s", "e12", "e13", "e23"}, tra = {"s", "e1i", "e2i", "e3i"},
                                 mot = {"s", "e12", "e13", "e23", "e1i", "e2i", "e3i", "e123i"},
                                 vec = {"eo", "e1", "e2", "e3", "ei"};
  std::vector<double> v;
  double s = 0;
  for (auto &o : out) {
    auto &[r1, r2, r3, t2, r4, rg, jg] = o;
    append(r1, rot, v, s), append(r2, mot, v, s), append(r3, mot, v, s), append(t2, tra, v, s);
    append(r4, mot, v, s), append(rg, mot, v, s), append(jg, vec, v, s);
  }
  rec.add(key, ns, std::move(v));
  if (s > 1e-9) std::fprintf(stderr, "gatl-peer: %s has components outside our types, up to %g\n", key, s);
  stray = std::max(stray, s);
}

int main(int argc, char **argv) {
  if (argc != 3) {
    std::fprintf(stderr, "usage: gatl-peer INPUT OUT_PREFIX\n");
    return 2;
  }
  Input in = read_input(argv[1]);
  auto va = operands(in, "cga.vector_a", 5, make_vector), vb = operands(in, "cga.vector_b", 5, make_vector);
  auto ba = operands(in, "cga.bivector_a", 10, make_bivector), bb = operands(in, "cga.bivector_b", 10, make_bivector);
  auto ma = operands(in, "cga.motor_a", 8, make_motor), mb = operands(in, "cga.motor_b", 8, make_motor);
  auto pts = operands(in, "cga.point", 4, make_point);

  const std::vector<std::string> even = {"s",   "eo1", "eo2", "eo3",   "eoi",   "e12",   "e13",  "e23",
                                         "e1i", "e2i", "e3i", "eo123", "eo12i", "eo13i", "eo23i", "e123i"};
  // A scalar plus a bivector: our `ScalarBivector`, the product of two vectors.
  const std::vector<std::string> sb = {"s", "eo1", "eo2", "eo3", "eoi", "e12", "e13", "e23", "e1i", "e2i", "e3i"};
  const std::vector<std::string> mot = {"s", "e12", "e13", "e23", "e1i", "e2i", "e3i", "e123i"};
  const std::vector<std::string> pt = {"eo", "e1", "e2", "e3", "ei"};
  auto gp2 = [](auto const &a, auto const &b) { return gp(a, b); };
  auto sw = [](auto const &m, auto const &p) { return sandwich(m, p); };

  Record rec;
  double stray = 0;
  row(rec, "cga.vector_vector", va, vb, gp2, sb, stray);
  row(rec, "cga.bivector_bivector", ba, bb, gp2, even, stray);
  row(rec, "cga.motor_motor", ma, mb, gp2, mot, stray);
  row(rec, "cga.motor_point", ma, pts, sw, pt, stray);
  ik_row<gatl_ik::Taylor>(rec, "cga.ik_taylor", in["cga.ik_angles"], stray);
  ik_row<gatl_ik::Closed>(rec, "cga.ik_exp", in["cga.ik_angles"], stray);
  gatl_ops::rows<0>(rec, in, stray), gatl_ops::rows<1>(rec, in, stray), gatl_ops::rows<2>(rec, in, stray);
  gatl_ops::rows<3>(rec, in, stray), gatl_ops::rows<4>(rec, in, stray), gatl_ops::rows<5>(rec, in, stray);
  rec.write(argv[2]);
  return stray > 1e-9 ? 1 : 0;
}
