// ga-benchmark's operation set for 3D CGA f64 on GATL, on blades of every grade 0..5: its
// binary products for every pair of grades and its unary operations for every grade, included
// by gatl.cpp after its helpers. Our side is benches/src/peer_ops_set.rs (binary; products
// identically zero for a pair have no row, the same rule as its `products`) and
// benches/src/peer_ops_unary.rs. Each row times `out[i] = op(a[i], b[i])` (or `op(a[i])`) with
// ga-benchmark's GATL call (gp, op, lcont, rcont, sp, dot, hip, cp, rp, igp; reverse, involute,
// conjugate, dual, undual, inv, unit, rnorm_sqr) and records the first CHECKED outputs as all
// 32 coefficients in our `Mv` blade order.
#pragma once

#include <tuple>

namespace gatl_ops {

constexpr std::size_t CHECKED = 1000;

// Our `Mv` blade order.
inline const std::vector<std::string> &mv_blades() {
  static const std::vector<std::string> b = {
      "s",    "eo",   "e1",   "e2",   "e3",    "ei",    "eo1",   "eo2",   "eo3",   "eoi",   "e12",
      "e13",  "e23",  "e1i",  "e2i",  "e3i",   "eo12",  "eo13",  "eo1i",  "eo23",  "eo2i",  "eo3i",
      "e123", "e12i", "e13i", "e23i", "eo123", "eo12i", "eo13i", "eo23i", "e123i", "eo123i"};
  return b;
}

// Blades from our coefficients (ga-benchmark's grade-0 operand is GATL's `scalar`).
inline auto make_scalar(const double *s) { return scalar(s[0]); }
// Our Trivector: eo12 eo13 eo1i eo23 eo2i eo3i e123 e12i e13i e23i.
inline auto make_trivector(const double *t) {
  return t[0] * (no ^ e1 ^ e2) + t[1] * (no ^ e1 ^ e3) + t[2] * (no ^ e1 ^ ni) +
         t[3] * (no ^ e2 ^ e3) + t[4] * (no ^ e2 ^ ni) + t[5] * (no ^ e3 ^ ni) +
         t[6] * (e1 ^ e2 ^ e3) + t[7] * (e1 ^ e2 ^ ni) + t[8] * (e1 ^ e3 ^ ni) +
         t[9] * (e2 ^ e3 ^ ni);
}
// Our Quadvector: eo123 eo12i eo13i eo23i e123i.
inline auto make_quadvector(const double *q) {
  return q[0] * (no ^ e1 ^ e2 ^ e3) + q[1] * (no ^ e1 ^ e2 ^ ni) + q[2] * (no ^ e1 ^ e3 ^ ni) +
         q[3] * (no ^ e2 ^ e3 ^ ni) + q[4] * (e1 ^ e2 ^ e3 ^ ni);
}
// Our Pseudoscalar: eo123i.
inline auto make_pseudoscalar(const double *p) { return p[0] * (no ^ e1 ^ e2 ^ e3 ^ ni); }

// Times `out[i] = op(a[i], b[i])` and records the outputs in our blade order.
template <class A, class B, class Op>
void op_row(Record &rec, const std::string &key, const std::vector<A> &a, const std::vector<B> &b,
            Op op, double &stray) {
  std::vector<decltype(op(a[0], b[0]))> out(N);
  double ns = time_pass([&] {
    for (std::size_t i = 0; i < N; ++i) out[i] = op(a[i], b[i]);
    clobber(out.data());
  });
  std::vector<double> v;
  double s = 0;
  for (std::size_t i = 0; i < CHECKED; ++i) append(out[i], mv_blades(), v, s);
  rec.add(key, ns, std::move(v));
  if (s > 1e-9) std::fprintf(stderr, "gatl-peer: %s has components outside Mv, up to %g\n", key.c_str(), s);
  stray = std::max(stray, s);
}

// Times `out[i] = op(a[i])` and records the outputs in our blade order.
template <class A, class Op>
void unary_row(Record &rec, const std::string &key, const std::vector<A> &a, Op op, double &stray) {
  std::vector<decltype(op(a[0]))> out(N);
  double ns = time_pass([&] {
    for (std::size_t i = 0; i < N; ++i) out[i] = op(a[i]);
    clobber(out.data());
  });
  std::vector<double> v;
  double s = 0;
  for (std::size_t i = 0; i < CHECKED; ++i) append(out[i], mv_blades(), v, s);
  rec.add(key, ns, std::move(v));
  stray = std::max(stray, s);
}

// The rows of grade pair (GA, GB), keys `ops.GAGB.PRODUCT`: the products that are not
// identically zero on such blades (the rule of `products` in peer_ops_set.rs).
template <int GA, int GB, class A, class B>
void pair_rows(Record &rec, const std::vector<A> &a, const std::vector<B> &b, double &stray) {
  const std::string pair = std::to_string(GA) + std::to_string(GB);
  auto k = [&](const char *op) { return "ops." + pair + "." + op; };
  op_row(rec, k("gp"), a, b, [](auto const &x, auto const &y) { return gp(x, y); }, stray);
  if constexpr (GA + GB <= 5)
    op_row(rec, k("op"), a, b, [](auto const &x, auto const &y) { return op(x, y); }, stray);
  if constexpr (GA <= GB)
    op_row(rec, k("lc"), a, b, [](auto const &x, auto const &y) { return lcont(x, y); }, stray);
  if constexpr (GA >= GB)
    op_row(rec, k("rc"), a, b, [](auto const &x, auto const &y) { return rcont(x, y); }, stray);
  if constexpr (GA == GB)
    op_row(rec, k("sp"), a, b, [](auto const &x, auto const &y) { return sp(x, y); }, stray);
  op_row(rec, k("dot"), a, b, [](auto const &x, auto const &y) { return dot(x, y); }, stray);
  if constexpr (GA > 0 && GB > 0)
    op_row(rec, k("hip"), a, b, [](auto const &x, auto const &y) { return hip(x, y); }, stray);
  if constexpr (GA > 0 && GA < 5 && GB > 0 && GB < 5)
    op_row(rec, k("cp"), a, b, [](auto const &x, auto const &y) { return cp(x, y); }, stray);
  if constexpr (GA + GB >= 5) {
    // Ours is GATL's complement form times (-1)^((5 - ga)(5 - gb)) in one basis order (our
    // `RegressiveProduct` doc); GATL's pseudoscalar e1^e2^e3^no^ni is minus ours, which flips
    // its complement form once more.
    op_row(rec, k("rp"), a, b, [](auto const &x, auto const &y) {
      if constexpr ((5 - GA) * (5 - GB) % 2 != 0) return rp(x, y); else return -rp(x, y);
    }, stray);
  }
  op_row(rec, k("igp"), a, b, [](auto const &x, auto const &y) { return igp(x, y); }, stray);
}

// The unary rows of grade G, keys `un.G.OP`. GATL's dual and undual use its pseudoscalar
// e1^e2^e3^no^ni, minus ours (eo^e1^e2^e3^ei): both are negated.
template <int G, class A>
void unary_rows(Record &rec, const std::vector<A> &a, double &stray) {
  auto k = [&](const char *op) { return "un." + std::to_string(G) + "." + op; };
  unary_row(rec, k("rev"), a, [](auto const &x) { return reverse(x); }, stray);
  unary_row(rec, k("inv"), a, [](auto const &x) { return involute(x); }, stray);
  unary_row(rec, k("conj"), a, [](auto const &x) { return conjugate(x); }, stray);
  unary_row(rec, k("dual"), a, [](auto const &x) { return -dual(x); }, stray);
  unary_row(rec, k("undual"), a, [](auto const &x) { return -undual(x); }, stray);
  unary_row(rec, k("inverse"), a, [](auto const &x) { return inv(x); }, stray);
  unary_row(rec, k("normalize"), a, [](auto const &x) { return unit(x); }, stray);
  unary_row(rec, k("nsq"), a, [](auto const &x) { return rnorm_sqr(x); }, stray);
}

// Every operation row from the input's blades of grade 0..5 (sections cga.bladeG_a, _b).
inline auto side(Input &in, char s) {
  auto sec = [&](int g) { return std::string("cga.blade") + char('0' + g) + "_" + s; };
  return std::make_tuple(operands(in, sec(0).c_str(), 1, make_scalar),
                         operands(in, sec(1).c_str(), 5, make_vector),
                         operands(in, sec(2).c_str(), 10, make_bivector),
                         operands(in, sec(3).c_str(), 10, make_trivector),
                         operands(in, sec(4).c_str(), 5, make_quadvector),
                         operands(in, sec(5).c_str(), 1, make_pseudoscalar));
}

template <int GA, int... GB, class L, class R>
void row_of_pairs(Record &rec, const L &l, const R &r, double &stray,
                  std::integer_sequence<int, GB...>) {
  (pair_rows<GA, GB>(rec, std::get<GA>(l), std::get<GB>(r), stray), ...);
}

}  // namespace gatl_ops
