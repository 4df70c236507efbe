// libigl's C++ as the peer of `harmonic_report` and `skinning_report` (issue 23): the harmonic
// field k = 1 end to end (`igl::harmonic`, the lowest 5% of the box in y at 0 and the highest
// 5% at 1), dual-quaternion skinning (`igl::dqs`) and matrix LBS (`M * T` with `M` from
// `igl::lbs_matrix`, precomputed), on libigl's armadillo with its 5-bone dense weights, and ARAP
// (`igl::arap_precomputation` with spokes and rims, one `igl::arap_solve` iteration), the scene
// of `arap_report`: the lowest 5% fixed, the highest 5% turned by 0.6 rad about (1, 0.2, 0.4)
// through the top centre of the box and shifted by 0.15 of its diagonal in x.
// One thread; medians of 15 runs with their range, in ms. Built and run by `run.sh`.
#include <igl/arap.h>
#include <igl/dqs.h>
#include <igl/harmonic.h>
#include <igl/lbs_matrix.h>
#include <igl/readDMAT.h>
#include <igl/readOBJ.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <string>
#include <vector>

template <class F>
static void report(const char *what, F &&f) {
  std::vector<double> t;
  for (int i = 0; i < 3; ++i) f();
  for (int i = 0; i < 15; ++i) {
    auto a = std::chrono::steady_clock::now();
    f();
    auto b = std::chrono::steady_clock::now();
    t.push_back(std::chrono::duration<double, std::milli>(b - a).count());
  }
  std::sort(t.begin(), t.end());
  std::printf("  %-44s %8.3f [%.3f, %.3f] ms\n", what, t[7], t.front(), t.back());
}

int main(int argc, char **argv) {
  if (argc < 2) {
    std::fprintf(stderr, "usage: peer MESHES_DIR (the shared data's meshes/)\n");
    return 2;
  }
  const std::string dir = argv[1];
  Eigen::MatrixXd V, W;
  Eigen::MatrixXi F;
  if (!igl::readOBJ(dir + "/libigl/armadillo.obj", V, F) ||
      !igl::readDMAT(dir + "/libigl/armadillo-weights.dmat", W) || W.rows() != V.rows()) {
    std::fprintf(stderr, "cannot read libigl/armadillo.obj and its weights under %s\n", dir.c_str());
    return 1;
  }
  std::printf("libigl/armadillo.obj (%ld vertices, %ld bones), libigl %s\n", (long)V.rows(),
              (long)W.cols(), IGL_PEER_VERSION);

  // Harmonic field: the same sets as `scenes::spline_ends` (closed slabs of the box in y).
  const double lo = V.col(1).minCoeff(), h = V.col(1).maxCoeff() - lo;
  std::vector<int> b;
  std::vector<double> bc;
  for (int v = 0; v < V.rows(); ++v) {
    const double y = V(v, 1);
    if (y >= lo && y <= lo + 0.05 * h) { b.push_back(v); bc.push_back(0.0); }
  }
  for (int v = 0; v < V.rows(); ++v) {
    const double y = V(v, 1);
    if (y >= lo + 0.95 * h && y <= lo + h) { b.push_back(v); bc.push_back(1.0); }
  }
  Eigen::VectorXi B = Eigen::Map<Eigen::VectorXi>(b.data(), b.size());
  Eigen::VectorXd BC = Eigen::Map<Eigen::VectorXd>(bc.data(), bc.size());
  Eigen::MatrixXd Z;
  std::printf("  (%zu constrained)\n", b.size());
  report("igl::harmonic, k = 1, end to end", [&] { igl::harmonic(V, F, B, BC, 1, Z); });

  // Skinning: one rigid transform per bone (a turn about an axis through the mesh's centre and
  // a shift), the same for both methods.
  const int m = (int)W.cols();
  const Eigen::RowVector3d c = V.colwise().mean();
  std::vector<Eigen::Quaterniond, Eigen::aligned_allocator<Eigen::Quaterniond>> vQ;
  std::vector<Eigen::Vector3d> vT;
  Eigen::MatrixXd T(4 * m, 3);
  for (int j = 0; j < m; ++j) {
    const double f = (j + 1.0) / m;
    Eigen::Quaterniond q(Eigen::AngleAxisd(0.8 * f, Eigen::Vector3d(0.3, 1.0, 0.2).normalized()));
    Eigen::Vector3d t = c.transpose() - q * c.transpose() + Eigen::Vector3d(0.1 * f, 0.0, 0.0);
    vQ.push_back(q);
    vT.push_back(t);
    Eigen::Matrix<double, 3, 4> A;
    A.leftCols<3>() = q.toRotationMatrix();
    A.col(3) = t;
    T.block(4 * j, 0, 4, 3) = A.transpose();
  }
  Eigen::MatrixXd U;
  report("igl::dqs", [&] { igl::dqs(V, W, vQ, vT, U); });
  Eigen::MatrixXd M;
  igl::lbs_matrix(V, W, M);
  report("matrix LBS: U = M * T (M precomputed)", [&] { U.noalias() = M * T; });

  // ARAP: fixed = the lowest slab (b's first part), handle = the highest.
  const size_t nfixed = std::count(bc.begin(), bc.end(), 0.0);
  const Eigen::RowVector3d bmin = V.colwise().minCoeff(), bmax = V.colwise().maxCoeff();
  const Eigen::Vector3d top(0.5 * (bmin(0) + bmax(0)), bmax(1), 0.5 * (bmin(2) + bmax(2)));
  const Eigen::Quaterniond q(Eigen::AngleAxisd(0.6, Eigen::Vector3d(1.0, 0.2, 0.4).normalized()));
  const Eigen::Vector3d shift = 0.15 * (bmax - bmin).norm() * Eigen::Vector3d::UnitX();
  Eigen::MatrixXd targets(b.size(), 3);
  for (size_t k = 0; k < b.size(); ++k) {
    const Eigen::Vector3d p = V.row(b[k]).transpose();
    targets.row(k) = (k < nfixed ? p : Eigen::Vector3d(q * (p - top) + top + shift)).transpose();
  }
  igl::ARAPData data;
  data.energy = igl::ARAP_ENERGY_TYPE_SPOKES_AND_RIMS;
  data.max_iter = 1;
  report("igl::arap_precomputation (spokes and rims)", [&] {
    igl::ARAPData d;
    d.energy = igl::ARAP_ENERGY_TYPE_SPOKES_AND_RIMS;
    igl::arap_precomputation(V, F, 3, B, d);
  });
  igl::arap_precomputation(V, F, 3, B, data);
  Eigen::MatrixXd P = V;
  data.max_iter = 3;
  igl::arap_solve(targets, data, P);
  data.max_iter = 1;
  Eigen::MatrixXd warm = P;
  report("igl::arap_solve, one iteration", [&] { P = warm; igl::arap_solve(targets, data, P); });
  return 0;
}
