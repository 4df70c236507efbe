// ga-benchmark's binary operation set for 3D CGA f64 on GATL (a subset: the products of grade
// pairs (1,1), (1,2), (2,2), (1,4) on blades), included by gatl.cpp after its helpers; our side
// is benches/examples/peer_ops/ops.rs, which lists the same rows (products identically zero for
// a pair have none). Each row times `out[i] = op(a[i], b[i])` with ga-benchmark's GATL call
// (gp, op, lcont, rcont, sp, dot, hip, cp, rp, igp) and records the first CHECKED outputs as
// all 32 coefficients in our `Mv` blade order.
#pragma once

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

// A grade-4 blade from our Quadvector coefficients (eo123 eo12i eo13i eo23i e123i).
inline auto make_quadvector(const double *q) {
  return q[0] * (no ^ e1 ^ e2 ^ e3) + q[1] * (no ^ e1 ^ e2 ^ ni) + q[2] * (no ^ e1 ^ e3 ^ ni) +
         q[3] * (no ^ e2 ^ e3 ^ ni) + q[4] * (e1 ^ e2 ^ e3 ^ ni);
}

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
  stray = std::max(stray, s);
}

// The rows of one pair, keys `ops.PAIR.PRODUCT`; `RcSp` adds the right contraction and scalar
// product, `Rp` the regressive product.
template <bool RcSp, bool Rp, class A, class B>
void pair_rows(Record &rec, const std::string &pair, const std::vector<A> &a,
               const std::vector<B> &b, double &stray) {
  auto k = [&](const char *op) { return "ops." + pair + "." + op; };
  op_row(rec, k("gp"), a, b, [](auto const &x, auto const &y) { return gp(x, y); }, stray);
  op_row(rec, k("op"), a, b, [](auto const &x, auto const &y) { return op(x, y); }, stray);
  op_row(rec, k("lc"), a, b, [](auto const &x, auto const &y) { return lcont(x, y); }, stray);
  if constexpr (RcSp) {
    op_row(rec, k("rc"), a, b, [](auto const &x, auto const &y) { return rcont(x, y); }, stray);
    op_row(rec, k("sp"), a, b, [](auto const &x, auto const &y) { return sp(x, y); }, stray);
  }
  op_row(rec, k("dot"), a, b, [](auto const &x, auto const &y) { return dot(x, y); }, stray);
  op_row(rec, k("hip"), a, b, [](auto const &x, auto const &y) { return hip(x, y); }, stray);
  op_row(rec, k("cp"), a, b, [](auto const &x, auto const &y) { return cp(x, y); }, stray);
  if constexpr (Rp) {
    // Ours is GATL's complement form times (-1)^((5 - ga)(5 - gb)) in one basis order (our
    // `RegressiveProduct` doc), +1 for (1, 4); GATL's pseudoscalar e1^e2^e3^no^ni is minus ours,
    // which flips its complement form: the sign below.
    op_row(rec, k("rp"), a, b, [](auto const &x, auto const &y) { return -rp(x, y); }, stray);
  }
  op_row(rec, k("igp"), a, b, [](auto const &x, auto const &y) { return igp(x, y); }, stray);
}

}  // namespace gatl_ops
