// Independent check of tfem's tempered element matrices.
//
// The reference below is written from the formula of docs/method.md §2 with
// Eigen in long double precision, without calling tfem:
//   F = [x2-x1, x3-x1; y2-y1, y3-y1],  J = det F,  adj(F)
//   rows of G = grad_xi(phi_i) * adj(F)
//   elasticity: K = B^T D B / (2 T),  Laplacian: K = kappa G G^T / (2 T)
//   T = max(J, jmin) (tempered) or |J| (jmin = 0, plain FEM)
// D uses the textbook E/((1+nu)(1-2nu)) form (tfem uses the Lamé form).
// The axisymmetric ring element (TFEM_PLANE_MODE_AXISYMMETRIC) is checked
// the same way with the dense 4x4 D of [e_rr, e_zz, e_tt, g_rz] (see the
// section before main), plus a spectral sweep of tfem's ring matrices.
//
// Tolerance: 1e-12 relative to the largest entry. Where K depends on 1/J
// (T = J or |J|), J itself is ill-conditioned for slivers: rounding the
// coordinate differences to double perturbs J by up to
// eps (|F00 F11| + |F01 F10|), so that bound (times 8) is added; it is
// derived from the input, not fitted.

// Eigen 3.4.0's eigensolver trips GCC 12's -Wmaybe-uninitialized (a known
// false positive inside its product kernels); the build uses -Werror.
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#endif
#include <Eigen/Dense>
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic pop
#endif
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

// Returns the relative error (largest difference over largest reference entry).
static Real compare(const char* what, const double* lib, const Real* ref, int n, Real tol) {
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
  return rel;
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

// ---------------------------------------------------------------------------
// The axisymmetric ring element (TFEM_PLANE_MODE_AXISYMMETRIC; include/tfem.h,
// src/fem/element.rs section_stiffness_into). x = r >= 0 is the radius,
// y = z the axis. Strain order [e_rr, e_zz, e_tt, g_rz]:
//   B^4 = the plane element's B^ (rows e_rr, e_zz, g_rz from g_i) with a zero
//         hoop row inserted, H4 = the hoop row alone, 1/(3 rbar) on each u_r
//         (u_r/r at the centroid, the one-point rule),
//   K = 2 pi rbar (B^4 + J H4)^T D4 (B^4 + J H4) / (2T),  T as in the plane,
// and K = 0 for rbar = 0 (a ring of radius 0 has no volume). For plain FEM
// this must be the textbook one-point ring element 2 pi rbar (|J|/2) B^T D4 B
// with B = B^4/J + H4, written below as a second, separate formula.

using M4 = Eigen::Matrix<Real, 4, 4>;
using M46 = Eigen::Matrix<Real, 4, 6>;
const Real kPi = 3.141592653589793238462643383279502884L;

static M4 d4_matrix(double E, double nu) {
  Real n = nu, c = (Real)E / ((1 + n) * (1 - 2 * n));
  M4 D;
  D << 1 - n, n, n, 0,  //
      n, 1 - n, n, 0,   //
      n, n, 1 - n, 0,   //
      0, 0, 0, (1 - 2 * n) / 2;
  return c * D;
}

static M46 ring_b_hat(const Geometry& g) {
  M46 B = M46::Zero();
  for (int i = 0; i < 3; ++i) {
    B(0, 2 * i) = g.G(i, 0);
    B(1, 2 * i + 1) = g.G(i, 1);
    B(3, 2 * i) = g.G(i, 1);
    B(3, 2 * i + 1) = g.G(i, 0);
  }
  return B;
}

static M46 hoop_row(Real rbar) {
  M46 H = M46::Zero();
  for (int i = 0; i < 3; ++i) H(2, 2 * i) = 1 / (3 * rbar);
  return H;
}

// Whether x_k - x_1 and y_k - y_1 are doubles (no rounding in tfem's F).
static bool differences_are_exact(const double xy[6]) {
  for (int k = 2; k < 6; ++k) {
    Real exact = (Real)xy[k] - xy[k % 2];
    if ((Real)(double)exact != exact) return false;
  }
  return true;
}

static Real mean_radius(const double xy[6]) { return ((Real)xy[0] + xy[2] + xy[4]) / 3; }

// The tempered ring element, with g.J as the Jacobian (a perturbed copy of
// the geometry gives K's sensitivity to J's rounding). T must be > 0.
static M6 ring_reference(const Geometry& g, Real rbar, double E, double nu, double jmin) {
  if (rbar == 0) return M6::Zero();
  bool dep = false;
  Real T = denominator(g, jmin, &dep);
  M46 B = ring_b_hat(g) + g.J * hoop_row(rbar);
  return 2 * kPi * rbar * B.transpose() * d4_matrix(E, nu) * B / (2 * T);
}

// The textbook plain-FEM ring element (one-point rule, area |J|/2). J != 0.
static M6 ring_textbook(const Geometry& g, Real rbar, double E, double nu) {
  M46 B = ring_b_hat(g) / g.J + hoop_row(rbar);
  return 2 * kPi * rbar * (std::fabs(g.J) / 2) * B.transpose() * d4_matrix(E, nu) * B;
}

static void to_array(const M6& K, Real out[36]) {
  for (int r = 0; r < 6; ++r)
    for (int c = 0; c < 6; ++c) out[6 * r + c] = K(r, c);
}

static double worst_ring_rel = 0;
static int ring_cases = 0;

// tfem's ring element against the reference. Tolerance: 1e-12 relative as
// in the plane, plus what rounding J (by eps_J = 8 eps condJ, see the top)
// does to the reference. K depends on J not only through 1/T but also
// through the hoop terms J/T and J^2/T, which move even where T = Jmin, so
// the bound is the reference's own change under J -> J +- eps_J.
static void check_ring_case(const std::string& name, const double xy[6], double E, double nu, double jmin) {
  Geometry g = geometry(xy);
  Real rbar = mean_radius(xy);
  bool dep = false;
  Real T = denominator(g, jmin, &dep);
  ++ring_cases;
  double K[36];
  tfem_status s = tfem_element_stiffness(xy, E, nu, TFEM_PLANE_MODE_AXISYMMETRIC, jmin, K);
  if (T == 0) {
    // Plain FEM on J = 0 (rings included) has no matrix: refused.
    ++checks;
    if (s != TFEM_STATUS_DEGENERATE_ELEMENT) {
      ++failures;
      std::printf("FAIL %s ring: expected DEGENERATE_ELEMENT, got %d\n", name.c_str(), s);
    }
    return;
  }
  if (s != TFEM_STATUS_OK) {
    ++failures;
    char msg[256];
    tfem_last_error(NULL, msg, sizeof msg);
    std::printf("FAIL %s ring: status %d (%s)\n", name.c_str(), s, msg);
    return;
  }
  M6 Kref = ring_reference(g, rbar, E, nu, jmin);
  const Real eps = 2.220446049250313e-16L;
  Real scale = Kref.cwiseAbs().maxCoeff(), tol = 1e-12L;
  // Where tfem's coordinate differences are exact, J carries only the few
  // eps |J| of its own determinant, not eps condJ.
  Real dJ = 8 * eps * (differences_are_exact(xy) ? std::fabs(g.J) : g.condJ), moved = 0;
  if (scale > 0 && dJ > 0) {
    for (Real sign : {-1, 1}) {
      Geometry p = g;
      p.J += sign * dJ;
      bool pdep = false;
      if (denominator(p, jmin, &pdep) > 0)
        moved = std::max(moved, (ring_reference(p, rbar, E, nu, jmin) - Kref).cwiseAbs().maxCoeff() / scale);
      else
        moved = std::max(moved, dJ / std::fabs(g.J));  // plain FEM within J's rounding of J = 0
    }
  }
  tol += moved;
  Real kr[36];
  to_array(Kref, kr);
  Real rel = compare((name + " ring").c_str(), K, kr, 36, tol);
  worst_ring_rel = std::max(worst_ring_rel, (double)rel);
  if (jmin == 0) {
    // Plain FEM must be the textbook element 2 pi rbar (|J|/2) B^T D4 B: the
    // reference's (B^4 + J H4) algebra must agree with it in long double,
    // and so must tfem.
    M6 Ktext = ring_textbook(g, rbar, E, nu);
    Real kt[36];
    to_array(Ktext, kt);
    compare((name + " ring vs textbook").c_str(), K, kt, 36, tol);
    Real gap = (Kref - Ktext).cwiseAbs().maxCoeff() / scale;
    ++checks;
    if (!(gap <= 1e-15L)) {
      ++failures;
      std::printf("FAIL %s: reference and textbook ring elements differ by %.3Le\n", name.c_str(), gap);
    }
  }
}

// Spectrum of tfem's ring matrix (E = 1, nu = 0.3, Jmin = 1e-3): a Gram form
// (B^4 + J H4)^T D4 (B^4 + J H4) / (2T) must be symmetric positive
// semidefinite for every J, inverted included; the rigid axial translation
// u_z = const strains nothing; the radial one u_r = const stretches the hoop
// (e_tt = u_r/r), so it stores energy wherever J != 0 (at J = 0 the hoop
// term, weighted by J/T, vanishes). Returns lambda_min / lambda_max.
static double check_ring_spectrum(const std::string& name, const double xy[6]) {
  const double E = 1, nu = 0.3, jmin = 1e-3, eps = 2.220446049250313e-16;
  check_ring_case(name, xy, E, nu, jmin);
  double k[36];
  if (tfem_element_stiffness(xy, E, nu, TFEM_PLANE_MODE_AXISYMMETRIC, jmin, k) != TFEM_STATUS_OK) {
    return 0;  // reported by check_ring_case
  }
  Eigen::Map<const Eigen::Matrix<double, 6, 6, Eigen::RowMajor>> K(k);
  double kmax = K.cwiseAbs().maxCoeff();
  auto fail = [&](const char* what, double value) {
    ++failures;
    std::printf("FAIL %s ring sweep: %s (%.3e)\n", name.c_str(), what, value);
  };

  ++checks;
  double asym = (K - K.transpose()).cwiseAbs().maxCoeff();
  if (!(asym <= 4 * eps * kmax)) fail("K is not symmetric", asym);

  Eigen::SelfAdjointEigenSolver<Eigen::Matrix<double, 6, 6>> es(K, Eigen::EigenvaluesOnly);
  double lo = es.eigenvalues().minCoeff(), hi = es.eigenvalues().maxCoeff();
  ++checks;
  if (!(hi > 0 && lo >= -1e-12 * hi)) fail("smallest eigenvalue below -1e-12 x largest", lo);

  Eigen::Matrix<double, 6, 1> uz, ur;
  uz << 0, 1, 0, 1, 0, 1;
  ur << 1, 0, 1, 0, 1, 0;
  ++checks;
  double residual = (K * uz).cwiseAbs().maxCoeff();
  if (!(residual <= 1e-12 * kmax)) fail("u_z = const has K u != 0", residual);
  if (geometry(xy).J != 0) {
    ++checks;
    double energy = ur.dot(K * ur);
    if (!(energy > 0)) fail("u_r = const stores no energy", energy);
  }
  return hi > 0 ? lo / hi : 0;
}

// Reference comparisons for the ring element over the cases of the plane
// (regular, axis-touching, flat, inverted, random) and every Jmin regime.
static void ring_reference_cases(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> R(0, 2), Z(-1, 1);
  auto each = [&](const std::string& name, const double xy[6]) {
    double h = 0;
    for (int i = 0; i < 3; ++i) {
      int j = (i + 1) % 3;
      h = std::max(h, std::hypot(xy[2 * j] - xy[2 * i], xy[2 * j + 1] - xy[2 * i + 1]));
    }
    for (double jmin : {0.0, h * h * h / 10.0, h * h * h / 1e4, 1e-30}) {
      check_ring_case(name, xy, 2.1e11, 0.3, jmin);
      check_ring_case(name + " nu=0.49", xy, 7.0e4, 0.49, jmin);
    }
  };
  // Away from the axis.
  const double regular[6] = {1, 0, 2, 0, 1.5, std::sqrt(3.0) / 2};
  each("ring regular", regular);
  const double far[6] = {30, -1, 31.2, -0.7, 30.4, 0.6};
  each("ring far from the axis", far);
  // Touching the axis: one node, two nodes (an edge on the axis).
  const double one_on_axis[6] = {0, 0, 1, 0, 1, 1};
  each("ring one node on the axis", one_on_axis);
  const double apex_on_axis[6] = {1, 0, 2, 1, 0, 0.5};
  each("ring apex on the axis", apex_on_axis);
  const double edge_on_axis[6] = {0, 0, 1, 0, 0, 1};
  each("ring edge on the axis", edge_on_axis);
  // All on the axis: rbar = 0, K = 0 (tempered), refused (plain FEM, J = 0).
  const double on_axis[6] = {0, 0, 0, 1, 0, 2.5};
  each("ring all nodes on the axis", on_axis);
  const double point_on_axis[6] = {0, 1, 0, 1, 0, 1};
  each("ring point on the axis", point_on_axis);
  // Flat: J = 0 exactly, J tiny, and a sliver hugging the axis.
  const double flat[6] = {1, 0, 2, 0, 1.5, 0};
  each("ring flat", flat);
  const double collinear[6] = {1, 0, 2, 1, 3, 2};
  each("ring collinear", collinear);
  const double along_axis[6] = {0, 0, 1e-5, 0.5, 0, 1};
  each("ring sliver along the axis", along_axis);
  for (int e = 3; e <= 15; ++e) {
    const double cap[6] = {1, 0, 2, 0, 1.5, std::pow(10.0, -e)};
    each("ring cap 1e-" + std::to_string(e), cap);
    const double cap_on_axis[6] = {0, 0, 1, 0, 0.5, std::pow(10.0, -e)};
    each("ring cap on the axis 1e-" + std::to_string(e), cap_on_axis);
  }
  const double all_coincident[6] = {1, 2, 1, 2, 1, 2};
  each("ring all nodes coincident", all_coincident);
  // Inverted (J < 0), also flat and touching the axis.
  const double inverted[6] = {1, 0, 1.5, 1, 2, 0};
  each("ring inverted", inverted);
  const double inverted_on_axis[6] = {0, 0, 0, 1, 1, 0};
  each("ring inverted on the axis", inverted_on_axis);
  const double inverted_flat[6] = {1, 0, 2, 0, 1.5, -1e-9};
  each("ring inverted flat", inverted_flat);
  // Random triangles in r in [0, 2], every fourth with a node on the axis.
  for (int k = 0; k < 1000; ++k) {
    double xy[6];
    for (int i = 0; i < 3; ++i) {
      xy[2 * i] = R(rng);
      xy[2 * i + 1] = Z(rng);
    }
    if (k % 4 == 0) xy[2 * (k / 4 % 3)] = 0;
    each("ring random " + std::to_string(k), xy);
  }
}

// The sweep: the element (1,0), (2,0), (1.5,t) as its apex crosses the base
// (t = 1 ... 1e-8, 0, -1e-8 ... -1, so J = t), elements touching the axis,
// and a flat one along it. Returns the smallest lambda_min / lambda_max.
static double ring_sweep(int* count) {
  double worst_ratio = 1;
  auto run = [&](const std::string& name, const double xy[6]) {
    worst_ratio = std::min(worst_ratio, check_ring_spectrum(name, xy));
    ++*count;
  };
  std::vector<double> ts;
  for (int k = 0; k <= 9; ++k) ts.push_back(std::pow(10.0, -8.0 * k / 9));
  ts.push_back(0);
  for (int k = 9; k >= 0; --k) ts.push_back(-std::pow(10.0, -8.0 * k / 9));
  char label[64];
  for (double t : ts) {
    std::snprintf(label, sizeof label, "t = %.3g", t);
    const double xy[6] = {1, 0, 2, 0, 1.5, t};
    run(label, xy);
  }
  for (double t : {1.0, -1.0, 1e-3, -1e-3}) {
    std::snprintf(label, sizeof label, "axis apex t = %.3g", t);
    const double apex[6] = {0, 0, 1, 0, 0.5, t};
    run(label, apex);
    std::snprintf(label, sizeof label, "axis edge t = %.3g", t);
    const double edge[6] = {0, 0, 1, 0, 0, t};
    run(label, edge);
  }
  const double along_axis[6] = {0, 0, 1e-5, 0.5, 0, 1};
  run("flat along the axis", along_axis);
  return worst_ratio;
}

// A ring lies at r >= 0: a node at r < 0 is an invalid argument, not a
// matrix (the same corners are a valid plane-strain element).
static void check_negative_radius_refused() {
  const double xy[6] = {-1e-3, 0, 1, 0, 0.5, 1};
  double K[36];
  ++checks;
  tfem_status ring = tfem_element_stiffness(xy, 1, 0.3, TFEM_PLANE_MODE_AXISYMMETRIC, 1e-3, K);
  tfem_status plane = tfem_element_stiffness(xy, 1, 0.3, TFEM_PLANE_MODE_STRAIN, 1e-3, K);
  if (ring != TFEM_STATUS_INVALID_ARGUMENT || plane != TFEM_STATUS_OK) {
    ++failures;
    std::printf("FAIL negative radius: axisymmetric status %d (expected %d), plane strain %d\n", ring,
                TFEM_STATUS_INVALID_ARGUMENT, plane);
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

  int plane_checks = checks;
  double plane_worst = worst;
  worst = 0;
  ring_reference_cases(rng);
  int sweep = 0;
  double ratio = ring_sweep(&sweep);
  check_negative_radius_refused();

  std::printf("element_reference: %d element cases, %d matrix comparisons, worst error/tolerance %.3g\n",
              count, plane_checks, plane_worst);
  std::printf("axisymmetric: %d element cases, %d checks, worst error/tolerance %.3g, "
              "largest relative error %.3g\n",
              ring_cases, checks - plane_checks, worst, worst_ring_rel);
  std::printf("axisymmetric sweep: %d elements, smallest eigenvalue/largest %.3g\n", sweep, ratio);
  std::printf("%d passed, %d failed\n", checks - failures, failures);
  return failures == 0 ? 0 : 1;
}
