// Independent check of tfem's tempered element matrices.
//
// The reference below is written from the formula of docs/method.md §2 with
// Eigen in long double precision, without calling tfem:
//   F = [x2-x1, x3-x1; y2-y1, y3-y1],  J = det F,  adj(F)
//   rows of G = grad_xi(phi_i) * adj(F)
//   elasticity: K = B^T D B / (2 T),  Laplacian: K = kappa G G^T / (2 T)
//   T = max(J, jmin) (tempered) or |J| (jmin = 0, plain FEM)
// D uses the textbook E/((1+nu)(1-2nu)) form (tfem uses the Lamé form).
//
// Tolerance: 1e-12 relative to the largest entry. Where K depends on 1/J
// (T = J or |J|), J itself is ill-conditioned for slivers: rounding the
// coordinate differences to double perturbs J by up to
// eps (|F00 F11| + |F01 F10|), so that bound (times 8) is added; it is
// derived from the input, not fitted.

#include <Eigen/Dense>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <string>
#include <vector>

extern "C" {
#include "tfem.h"
}

using Real = long double;
using M2 = Eigen::Matrix<Real, 2, 2>;
using M3 = Eigen::Matrix<Real, 3, 3>;
using M36 = Eigen::Matrix<Real, 3, 6>;
using M6 = Eigen::Matrix<Real, 6, 6>;
using M32 = Eigen::Matrix<Real, 3, 2>;

struct Geometry {
  M32 G;
  Real J;
  Real condJ;  // |F00 F11| + |F01 F10|, the scale of J's rounding
};

static Geometry geometry(const double xy[6]) {
  M2 F;
  F << (Real)xy[2] - xy[0], (Real)xy[4] - xy[0], (Real)xy[3] - xy[1], (Real)xy[5] - xy[1];
  M2 adj;
  adj << F(1, 1), -F(0, 1), -F(1, 0), F(0, 0);
  M32 grad_ref;
  grad_ref << -1, -1, 1, 0, 0, 1;
  Geometry g;
  g.G = grad_ref * adj;
  g.J = F.determinant();
  g.condJ = std::fabs(F(0, 0) * F(1, 1)) + std::fabs(F(0, 1) * F(1, 0));
  return g;
}

static Real denominator(const Geometry& g, double jmin, bool* depends_on_j) {
  if (jmin > 0) {
    *depends_on_j = g.J >= jmin;
    return g.J > jmin ? g.J : (Real)jmin;
  }
  *depends_on_j = true;
  return std::fabs(g.J);
}

static M3 d_matrix(double E, double nu, int plane) {
  M3 D = M3::Zero();
  if (plane == TFEM_PLANE_MODE_STRAIN) {
    Real c = (Real)E / ((1 + (Real)nu) * (1 - 2 * (Real)nu));
    D << 1 - (Real)nu, nu, 0, nu, 1 - (Real)nu, 0, 0, 0, (1 - 2 * (Real)nu) / 2;
    D *= c;
  } else {
    Real c = (Real)E / (1 - (Real)nu * nu);
    D << 1, nu, 0, nu, 1, 0, 0, 0, (1 - (Real)nu) / 2;
    D *= c;
  }
  return D;
}

static int failures = 0, checks = 0;
static double worst = 0;

static void compare(const char* what, const double* lib, const Real* ref, int n, Real tol) {
  Real scale = 0, err = 0;
  for (int i = 0; i < n; ++i) scale = std::max(scale, std::fabs(ref[i]));
  for (int i = 0; i < n; ++i) err = std::max(err, std::fabs((Real)lib[i] - ref[i]));
  Real rel = scale > 0 ? err / scale : err;
  ++checks;
  if (!(rel <= tol) || !std::isfinite((double)rel)) {
    ++failures;
    if (failures < 20) std::printf("FAIL %s: relative error %.3Le > tolerance %.3Le\n", what, rel, tol);
  }
  if ((double)(rel / tol) > worst) worst = (double)(rel / tol);
}

static void check_case(const std::string& name, const double xy[6], double E, double nu, int plane, double jmin) {
  Geometry g = geometry(xy);
  bool dep = false;
  Real T = denominator(g, jmin, &dep);
  const Real eps = 2.220446049250313e-16L;
  Real tol = 1e-12L;
  if (dep && T > 0) tol += 8 * eps * g.condJ / std::fabs(g.J);

  double K[36], L[9];
  tfem_status s = tfem_element_stiffness(xy, E, nu, plane, jmin, K);
  tfem_status sl = tfem_laplacian_stiffness(xy, 2.5, jmin, L);
  if (T == 0) {
    // Plain FEM on J = 0 has no matrix: tfem must refuse, not return Inf/NaN.
    ++checks;
    if (s != TFEM_STATUS_DEGENERATE_ELEMENT || sl != TFEM_STATUS_DEGENERATE_ELEMENT) {
      ++failures;
      std::printf("FAIL %s: expected DEGENERATE_ELEMENT, got %d/%d\n", name.c_str(), s, sl);
    }
    return;
  }
  if (s != TFEM_STATUS_OK || sl != TFEM_STATUS_OK) {
    ++failures;
    char msg[256];
    tfem_last_error(NULL, msg, sizeof msg);
    std::printf("FAIL %s: status %d/%d (%s)\n", name.c_str(), s, sl, msg);
    return;
  }
  M36 B = M36::Zero();
  for (int i = 0; i < 3; ++i) {
    B(0, 2 * i) = g.G(i, 0);
    B(1, 2 * i + 1) = g.G(i, 1);
    B(2, 2 * i) = g.G(i, 1);
    B(2, 2 * i + 1) = g.G(i, 0);
  }
  M6 Kref = B.transpose() * d_matrix(E, nu, plane) * B / (2 * T);
  M3 Lref = (Real)2.5 * g.G * g.G.transpose() / (2 * T);
  Real kr[36], lr[9];
  for (int r = 0; r < 6; ++r)
    for (int c = 0; c < 6; ++c) kr[6 * r + c] = Kref(r, c);
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) lr[3 * r + c] = Lref(r, c);
  compare((name + " elasticity").c_str(), K, kr, 36, tol);
  compare((name + " laplacian").c_str(), L, lr, 9, tol);
}

static void rotate(double xy[6], double angle, double tx, double ty) {
  double c = std::cos(angle), s = std::sin(angle);
  for (int i = 0; i < 3; ++i) {
    double x = xy[2 * i], y = xy[2 * i + 1];
    xy[2 * i] = c * x - s * y + tx;
    xy[2 * i + 1] = s * x + c * y + ty;
  }
}

int main() {
  std::mt19937_64 rng(20261122);
  std::uniform_real_distribution<double> U(-1, 1);
  const int planes[2] = {TFEM_PLANE_MODE_STRAIN, TFEM_PLANE_MODE_STRESS};
  int count = 0;
  auto each = [&](const std::string& name, double xy[6]) {
    for (int p : planes) {
      double h = 0;
      for (int i = 0; i < 3; ++i) {
        int j = (i + 1) % 3;
        h = std::max(h, std::hypot(xy[2 * j] - xy[2 * i], xy[2 * j + 1] - xy[2 * i + 1]));
      }
      for (double jmin : {0.0, h * h * h / 10.0, h * h * h / 1e4, 1e-30}) {
        check_case(name, xy, 2.1e11, 0.3, p, jmin);
        check_case(name + " nu=0.49", xy, 7.0e4, 0.49, p, jmin);
        ++count;
      }
    }
  };

  double regular[6] = {0, 0, 1, 0, 0.5, std::sqrt(3.0) / 2};
  each("regular", regular);
  double right[6] = {0, 0, 1, 0, 0, 1};
  each("right", right);

  for (int k = 0; k < 3000; ++k) {
    double xy[6];
    for (double& v : xy) v = U(rng);
    each("random " + std::to_string(k), xy);
  }
  for (int e = 1; e <= 12; ++e) {
    double ar = std::pow(10.0, -e);
    double xy[6] = {0, 0, 1, 0, 0.37, ar};
    rotate(xy, U(rng) * 3, U(rng), U(rng));
    each("sliver 1e-" + std::to_string(e), xy);
  }
  for (int e = 3; e <= 15; ++e) {
    double xy[6] = {0, 0, 1, 0, 0.5, std::pow(10.0, -e)};
    each("cap 1e-" + std::to_string(e), xy);
  }
  double collinear[6] = {0, 0, 2, 1, 4, 2};
  each("collinear", collinear);
  double two_coincident[6] = {0.3, 0.7, 0.3, 0.7, 1.2, -0.4};
  each("two coincident nodes", two_coincident);
  double all_coincident[6] = {1, 2, 1, 2, 1, 2};
  each("all nodes coincident", all_coincident);
  double inverted[6] = {0, 0, 0, 1, 1, 0};
  each("inverted", inverted);
  double inverted_flat[6] = {0, 0, 1, 0, 0.5, -1e-9};
  each("inverted flat", inverted_flat);
  // J just above and just below Jmin.
  for (double f : {1 + 1e-9, 1 - 1e-9, 1 + 1e-3, 1 - 1e-3}) {
    double jmin = 1e-4;
    double xy[6] = {0, 0, 1, 0, 0.5, jmin * f};
    for (int p : planes) {
      check_case("J = Jmin*" + std::to_string(f), xy, 1e9, 0.25, p, jmin);
      ++count;
    }
  }

  std::printf("element_reference: %d element cases, %d matrix comparisons, worst error/tolerance %.3g\n",
              count, checks, worst);
  std::printf("%d passed, %d failed\n", checks - failures, failures);
  return failures == 0 ? 0 : 1;
}
