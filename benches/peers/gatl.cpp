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
#include <gatl/ga3c.hpp>

#include <cmath>

#include "peer_io.hpp"
#include "gatl_ik.hpp"

using namespace ga3c;
using namespace peer;

// Our blade name (`s`, `eo1`, `e12i`, ...) as GATL's bitset and the sign of our blade in it.
static std::pair<bitset_t, double> blade(const std::string &name) {
  std::vector<int> idx;  // GATL indices: e1..e3 = 1..3, no = 4, ni = 5
  for (char ch : name.substr(1)) idx.push_back(ch == 'o' ? 4 : ch == 'i' ? 5 : ch - '0');
  bitset_t bits = 0;
  int swaps = 0;
  for (std::size_t a = 0; a < idx.size(); ++a) {
    bits |= bitset_t(1) << (idx[a] - 1);
    for (std::size_t b = a + 1; b < idx.size(); ++b) swaps += idx[a] > idx[b];
  }
  return {bits, swaps % 2 ? -1.0 : 1.0};
}

// Appends one result in our blade order; the largest component outside it goes to `stray`.
template <class E>
static void append(const E &e, const std::vector<std::string> &blades, std::vector<double> &v,
                   double &stray) {
  std::map<bitset_t, double> c;
  for_each_component(e, [&](bitset_t b, double x, entry_source_t, entry_source_t, bool &) {
    c[b] += x;
  });
  for (auto &name : blades) {
    auto [bits, sign] = blade(name);
    v.push_back(sign * c[bits]);
    c.erase(bits);
  }
  for (auto &[bits, x] : c) stray = std::max(stray, std::abs(x));
}

// Every result in our blade order.
template <class E>
static std::vector<double> ours(const std::vector<E> &out, const std::vector<std::string> &blades,
                                double &stray) {
  std::vector<double> v;
  for (auto &e : out) append(e, blades, v, stray);
  return v;
}

static auto make_vector(const double *v) { return v[0] * no + v[1] * e1 + v[2] * e2 + v[3] * e3 + v[4] * ni; }
static auto make_bivector(const double *b) {
  return b[0] * (no ^ e1) + b[1] * (no ^ e2) + b[2] * (no ^ e3) + b[3] * (no ^ ni) +
         b[4] * (e1 ^ e2) + b[5] * (e1 ^ e3) + b[6] * (e2 ^ e3) + b[7] * (e1 ^ ni) +
         b[8] * (e2 ^ ni) + b[9] * (e3 ^ ni);
}
static auto make_motor(const double *m) {
  return scalar(m[0]) + m[1] * (e1 ^ e2) + m[2] * (e1 ^ e3) + m[3] * (e2 ^ e3) + m[4] * (e1 ^ ni) +
         m[5] * (e2 ^ ni) + m[6] * (e3 ^ ni) + m[7] * (e1 ^ e2 ^ e3 ^ ni);
}
static auto make_point(const double *p) { return no + p[0] * e1 + p[1] * e2 + p[2] * e3 + p[3] * ni; }

template <class M, class P>
static auto sandwich(const M &m, const P &p) {
  auto [lazy, m_, p_] = make_lazy_context_tuple(m, p);
  return lazy.eval(m_ * p_ * ~m_);
}

// The operands of a section, built by `make` from each operand's coefficients.
template <class F>
static auto operands(Input &in, const char *section, std::size_t width, F make) {
  std::vector<decltype(make(in[section].data()))> v;
  for (std::size_t i = 0; i < N; ++i) v.push_back(make(in[section].data() + width * i));
  return v;
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

#include "gatl_ops.hpp"

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
  {
    auto l = gatl_ops::side(in, 'a'), r = gatl_ops::side(in, 'b');
    gatl_ops::all_pairs(rec, l, r, stray, std::make_integer_sequence<int, 6>{});
    gatl_ops::all_unary(rec, l, stray, std::make_integer_sequence<int, 6>{});
  }
  rec.write(argv[2]);
  return stray > 1e-9 ? 1 : 0;
}
