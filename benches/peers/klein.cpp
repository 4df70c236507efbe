// klein (jeremyong/klein, PGA f32, SSE4.1) as the peer of the PGA rows of `peer_ops`.
//
//   klein-peer INPUT OUT_PREFIX
//
// Reads the operands from INPUT, times each row (the median of PASSES passes over N operands),
// and writes OUT_PREFIX.times and OUT_PREFIX.out with every output in our blade order. klein
// names its blades as `algebras/pga3d.toml` does, so the mapping is the identity on names; only
// the lanes differ: a point is (e123, e032, e013, e021), a motor (s, e23, e31, e12) and
// (e0123, e01, e02, e03); `mat4x4` is column-major on (x, y, z, w) = (e032, e013, e021, e123),
// written out row-major like our `point_matrix().m`. Built by `run.sh` (-O3 -DNDEBUG -msse4.1).
#include <klein/klein.hpp>

#include "peer_io.hpp"

using namespace peer;

int main(int argc, char **argv) {
  if (argc != 3) {
    std::fprintf(stderr, "usage: klein-peer INPUT OUT_PREFIX\n");
    return 2;
  }
  Input in = read_input(argv[1]);
  auto f = [](const std::vector<double> &v, std::size_t k) { return static_cast<float>(v[k]); };
  std::vector<kln::motor> ma(N), mb(N);
  std::vector<kln::point> pts(N), pout(N);
  std::vector<kln::rotor> ra(N), rb(N), rout(N);
  std::vector<kln::line> lines(N), lout(N);
  std::vector<kln::motor> mout(N);
  std::vector<kln::mat4x4> mats(N);
  for (std::size_t i = 0; i < N; ++i) {
    auto &a = in["pga.motor_a"], &b = in["pga.motor_b"], &p = in["pga.point"];
    ma[i] = kln::motor(f(a, 8 * i), f(a, 8 * i + 1), f(a, 8 * i + 2), f(a, 8 * i + 3),
                       f(a, 8 * i + 4), f(a, 8 * i + 5), f(a, 8 * i + 6), f(a, 8 * i + 7));
    mb[i] = kln::motor(f(b, 8 * i), f(b, 8 * i + 1), f(b, 8 * i + 2), f(b, 8 * i + 3),
                       f(b, 8 * i + 4), f(b, 8 * i + 5), f(b, 8 * i + 6), f(b, 8 * i + 7));
    float w_first[4] = {f(p, 4 * i + 3), f(p, 4 * i), f(p, 4 * i + 1), f(p, 4 * i + 2)};
    pts[i].load(w_first);
    float r[4], s[4];
    for (int k = 0; k < 4; ++k) r[k] = f(in["pga.rotor_a"], 4 * i + k);
    for (int k = 0; k < 4; ++k) s[k] = f(in["pga.rotor_b"], 4 * i + k);
    ra[i].load_normalized(r);
    rb[i].load_normalized(s);
    auto &l = in["pga.line"];
    lines[i] = kln::line(f(l, 6 * i), f(l, 6 * i + 1), f(l, 6 * i + 2), f(l, 6 * i + 3),
                         f(l, 6 * i + 4), f(l, 6 * i + 5));
  }

  auto points_out = [&] {
    std::vector<double> v;
    for (auto &p : pout) v.insert(v.end(), {p.e032(), p.e013(), p.e021(), p.e123()});
    return v;
  };
  auto motors_out = [&] {
    std::vector<double> v;
    for (auto &m : mout)
      v.insert(v.end(), {m.scalar(), m.e23(), m.e31(), m.e12(), m.e01(), m.e02(), m.e03(),
                         m.e0123()});
    return v;
  };

  Record rec;
  double ns = time_pass([&] {
    for (std::size_t i = 0; i < N; ++i) pout[i] = ma[i](pts[i]);
    clobber(pout.data());
  });
  rec.add("pga.motor_point", ns, points_out());

  ns = time_pass([&] {
    ma[0](pts.data(), pout.data(), N);  // klein's batch call: one motor on many points
    clobber(pout.data());
  });
  rec.add("pga.batch", ns, points_out());

  ns = time_pass([&] {
    for (std::size_t i = 0; i < N; ++i) mout[i] = ma[i] * mb[i];
    clobber(mout.data());
  });
  rec.add("pga.motor_motor", ns, motors_out());

  ns = time_pass([&] {
    for (std::size_t i = 0; i < N; ++i) rout[i] = ra[i] * rb[i];
    clobber(rout.data());
  });
  std::vector<double> v;
  for (auto &r : rout) v.insert(v.end(), {r.scalar(), r.e23(), r.e31(), r.e12()});
  rec.add("pga.rotor_rotor", ns, v);

  ns = time_pass([&] {
    for (std::size_t i = 0; i < N; ++i) mout[i] = kln::exp(lines[i]);
    clobber(mout.data());
  });
  rec.add("pga.exp", ns, motors_out());

  ns = time_pass([&] {
    for (std::size_t i = 0; i < N; ++i) lout[i] = kln::log(ma[i]);
    clobber(lout.data());
  });
  v.clear();
  for (auto &l : lout)
    v.insert(v.end(), {l.e01(), l.e02(), l.e03(), l.e23(), l.e31(), l.e12()});
  rec.add("pga.log", ns, v);

  ns = time_pass([&] {
    for (std::size_t i = 0; i < N; ++i) mats[i] = ma[i].as_mat4x4();
    clobber(mats.data());
  });
  v.clear();
  for (auto &m : mats)
    for (int r = 0; r < 4; ++r)
      for (int c = 0; c < 4; ++c) v.push_back(m.data[4 * c + r]);
  rec.add("pga.motor_matrix", ns, v);

  rec.write(argv[2]);
  return 0;
}
