// What gatl.cpp and gatl_ops.cpp (the operation set, compiled once per left grade) share: GATL's
// `ga3c`, the mapping of our blade names to GATL's (see gatl.cpp), and building operands.
#pragma once
#include <gatl/ga3c.hpp>

#include <cmath>

#include "peer_io.hpp"

using namespace ga3c;
using namespace peer;

// Our blade name (`s`, `eo1`, `e12i`, ...) as GATL's bitset and the sign of our blade in it.
inline std::pair<bitset_t, double> blade(const std::string &name) {
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
inline void append(const E &e, const std::vector<std::string> &blades, std::vector<double> &v,
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
inline std::vector<double> ours(const std::vector<E> &out, const std::vector<std::string> &blades,
                                double &stray) {
  std::vector<double> v;
  for (auto &e : out) append(e, blades, v, stray);
  return v;
}

inline auto make_vector(const double *v) { return v[0] * no + v[1] * e1 + v[2] * e2 + v[3] * e3 + v[4] * ni; }
inline auto make_bivector(const double *b) {
  return b[0] * (no ^ e1) + b[1] * (no ^ e2) + b[2] * (no ^ e3) + b[3] * (no ^ ni) +
         b[4] * (e1 ^ e2) + b[5] * (e1 ^ e3) + b[6] * (e2 ^ e3) + b[7] * (e1 ^ ni) +
         b[8] * (e2 ^ ni) + b[9] * (e3 ^ ni);
}
inline auto make_motor(const double *m) {
  return scalar(m[0]) + m[1] * (e1 ^ e2) + m[2] * (e1 ^ e3) + m[3] * (e2 ^ e3) + m[4] * (e1 ^ ni) +
         m[5] * (e2 ^ ni) + m[6] * (e3 ^ ni) + m[7] * (e1 ^ e2 ^ e3 ^ ni);
}
inline auto make_point(const double *p) { return no + p[0] * e1 + p[1] * e2 + p[2] * e3 + p[3] * ni; }

// The operands of a section, built by `make` from each operand's coefficients.
template <class F>
inline auto operands(Input &in, const char *section, std::size_t width, F make) {
  std::vector<decltype(make(in[section].data()))> v;
  for (std::size_t i = 0; i < N; ++i) v.push_back(make(in[section].data() + width * i));
  return v;
}

