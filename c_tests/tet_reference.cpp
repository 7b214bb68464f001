// Independent reference for the tempered linear tetrahedron (3D elasticity).
//
// Written from the element's formula with Eigen in long double precision,
// without calling tfem, so that a test can drive it as a separate program:
//   Jm = [x1-x0, x2-x0, x3-x0] (columns),  J = det Jm  (6 x signed volume)
//   a_k = J grad(phi_k) = column k of cof(Jm) (k = 1..3),  a_0 = -(a_1+a_2+a_3)
//   eps J = A u  (Voigt [exx, eyy, ezz, gyz, gxz, gxy], engineering shears)
//   K = A^T D A / (6 T),  T = max(J, jmin)
// cof(Jm) is built from 2x2 minors, not from an inverse, so a_k and K stay
// defined for flat (J = 0) and inverted (J < 0) tetrahedra. For J >= jmin
// this is the textbook V B^T D B with V = J/6, B = A/J. jmin = 0 with J <= 0
// has no matrix.
//
// Usage:
//   tet_reference < lines      each line: x0 y0 z0 x1 y1 z1 x2 y2 z2 x3 y3 z3
//                              E nu jmin; prints the 144 entries of K (12x12,
//                              row-major, dofs [u0x u0y u0z u1x ...]) with
//                              %.17g, or "error" (reason on stderr). Empty
//                              lines are skipped, so output line i answers
//                              the i-th non-empty input line.
//   tet_reference --self-test  the checks of self_test() below; exit 0 when
//                              all pass.
// Inputs are refused ("error") as tfem's Material refuses them: E finite and
// > 0, nu in (-1, 0.5); also jmin finite and >= 0 and every coordinate finite.
//
// K is computed in long double and rounded once to double on output. The
// coordinate differences are therefore exact here, where a double
// implementation rounds them: for slivers, whose J is ill-conditioned, a
// comparison needs the allowance of element_reference.cpp (eps times the
// sum of the absolute terms of det Jm, relative to |J|) where K depends on 1/J.

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
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <iostream>
#include <random>
#include <string>
#include <vector>

using Real = long double;
using V3 = Eigen::Matrix<Real, 3, 1>;
using M3 = Eigen::Matrix<Real, 3, 3>;
using M34 = Eigen::Matrix<Real, 3, 4>;
using M6 = Eigen::Matrix<Real, 6, 6>;
using M6x12 = Eigen::Matrix<Real, 6, 12>;
using M12 = Eigen::Matrix<Real, 12, 12>;
using V12 = Eigen::Matrix<Real, 12, 1>;

// Nodes as the columns of a 3x4 matrix.
static M34 nodes_from(const double x[12]) {
  M34 X;
  for (int k = 0; k < 4; ++k)
    for (int i = 0; i < 3; ++i) X(i, k) = x[3 * k + i];
  return X;
}

static M3 jacobian(const M34& X) {
  M3 Jm;
  for (int k = 1; k <= 3; ++k) Jm.col(k - 1) = X.col(k) - X.col(0);
  return Jm;
}

// The signed cofactors: C(i, j) = (-1)^(i+j) times the minor of Jm without
// row i and column j. Cyclic indices give the sign without a branch.
static M3 cofactor(const M3& Jm) {
  M3 C;
  for (int i = 0; i < 3; ++i) {
    int i1 = (i + 1) % 3, i2 = (i + 2) % 3;
    for (int j = 0; j < 3; ++j) {
      int j1 = (j + 1) % 3, j2 = (j + 2) % 3;
      C(i, j) = Jm(i1, j1) * Jm(i2, j2) - Jm(i1, j2) * Jm(i2, j1);
    }
  }
  return C;
}

struct Geometry {
  Real J;
  M34 a;  // column k: a_k = J grad(phi_k)
};

static Geometry geometry(const M34& X) {
  M3 Jm = jacobian(X);
  M3 C = cofactor(Jm);
  Geometry g;
  // Laplace expansion along the first column, from the same cofactors.
  g.J = Jm(0, 0) * C(0, 0) + Jm(1, 0) * C(1, 0) + Jm(2, 0) * C(2, 0);
  g.a.col(0) = -(C.col(0) + C.col(1) + C.col(2));
  for (int k = 1; k <= 3; ++k) g.a.col(k) = C.col(k - 1);
  return g;
}

// Strain-displacement matrix of a node, from its gradient g (a_k, or a
// textbook grad(phi_k)).
static void strain_block(Eigen::Ref<Eigen::Matrix<Real, 6, 3>> out, const V3& g) {
  out.setZero();
  out(0, 0) = g(0);
  out(1, 1) = g(1);
  out(2, 2) = g(2);
  out(3, 1) = g(2);
  out(3, 2) = g(1);
  out(4, 0) = g(2);
  out(4, 2) = g(0);
  out(5, 0) = g(1);
  out(5, 1) = g(0);
}

static M6x12 a_matrix(const Geometry& g) {
  M6x12 A;
  for (int k = 0; k < 4; ++k) strain_block(A.block<6, 3>(0, 3 * k), g.a.col(k));
  return A;
}

// Lamé form.
static M6 d_matrix(Real E, Real nu) {
  Real lambda = E * nu / ((1 + nu) * (1 - 2 * nu));
  Real mu = E / (2 * (1 + nu));
  M6 D = M6::Zero();
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) D(i, j) = lambda;
    D(i, i) += 2 * mu;
    D(3 + i, 3 + i) = mu;
  }
  return D;
}

// The textbook form E/((1+nu)(1-2nu)) [1-nu, nu, ...; (1-2nu)/2 shears],
// kept separate from the Lamé form so that the self-test checks D too.
static M6 d_matrix_textbook(Real E, Real nu) {
  Real c = E / ((1 + nu) * (1 - 2 * nu));
  M6 D = M6::Zero();
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) D(i, j) = i == j ? 1 - nu : nu;
    D(3 + i, 3 + i) = (1 - 2 * nu) / 2;
  }
  return c * D;
}

// The tempered stiffness; false (and *why) where there is none.
static bool stiffness(const M34& X, Real E, Real nu, Real jmin, M12* K, std::string* why) {
  if (!X.allFinite()) return *why = "a coordinate is not finite", false;
  if (!(std::isfinite(E) && E > 0)) return *why = "E must be finite and > 0", false;
  if (!(std::isfinite(nu) && nu > -1 && nu < 0.5)) return *why = "nu must lie in (-1, 0.5)", false;
  if (!(std::isfinite(jmin) && jmin >= 0)) return *why = "jmin must be finite and >= 0", false;
  Geometry g = geometry(X);
  Real T = std::max(g.J, jmin);
  if (!(T > 0)) return *why = "J <= 0 with jmin = 0 (plain FEM has no matrix)", false;
  M6x12 A = a_matrix(g);
  *K = A.transpose() * d_matrix(E, nu) * A / (6 * T);
  if (!K->allFinite()) return *why = "K is not finite (overflow)", false;
  return true;
}

// ---------------------------------------------------------------------------
// Self-test.

static int checks = 0, failures = 0;

static void expect(bool ok, const std::string& what, Real value) {
  ++checks;
  if (!ok) {
    ++failures;
    std::printf("FAIL %s (%.3Le)\n", what.c_str(), value);
  }
}

// V B^T D B with B from the textbook gradients grad(phi_k) = Jinv^T e_k
// (k = 1..3, rows of Jinv) and grad(phi_0) = -(their sum), for a given
// inverse of Jm.
static M12 textbook(const M3& Jm, const M3& Jinv, Real E, Real nu) {
  M6x12 B;
  V3 g0 = V3::Zero();
  for (int k = 1; k <= 3; ++k) {
    V3 gk = Jinv.row(k - 1).transpose();
    g0 -= gk;
    strain_block(B.block<6, 3>(0, 3 * k), gk);
  }
  strain_block(B.block<6, 3>(0, 0), g0);
  Real V = Jm.determinant() / 6;
  return V * B.transpose() * d_matrix_textbook(E, nu) * B;
}

static Real rel_diff(const M12& K, const M12& R) {
  Real scale = R.cwiseAbs().maxCoeff();
  Real err = (K - R).cwiseAbs().maxCoeff();
  return scale > 0 ? err / scale : err;
}

// The six rigid-body modes: translations e_i and rotations u = w x x.
static std::vector<V12> rigid_modes(const M34& X) {
  std::vector<V12> modes;
  for (int i = 0; i < 3; ++i) {
    V12 r = V12::Zero();
    for (int k = 0; k < 4; ++k) r(3 * k + i) = 1;
    modes.push_back(r);
  }
  for (int i = 0; i < 3; ++i) {
    V3 w = V3::Zero();
    w(i) = 1;
    V12 r;
    for (int k = 0; k < 4; ++k) r.segment<3>(3 * k) = w.cross(V3(X.col(k)));
    modes.push_back(r);
  }
  return modes;
}

static Real worst_kernel = 0, worst_textbook = 0;

struct Expect {
  bool textbook;    // J > jmin: compare with V B^T D B
  bool tempered;    // 0 < |J|, J < jmin: compare with (J^2 / (6 jmin)) B^T D B
  int zero_eigs;    // expected number of zero eigenvalues (-1: don't count)
};

// Runs checks (1)-(4) on one element; returns K's eigenvalues.
static Eigen::Matrix<Real, 12, 1> check(const std::string& name, const M34& X, Real E, Real nu, Real jmin,
                                        Expect ex) {
  M12 K;
  std::string why;
  Eigen::Matrix<Real, 12, 1> none = Eigen::Matrix<Real, 12, 1>::Zero();
  if (!stiffness(X, E, nu, jmin, &K, &why)) {
    expect(false, name + ": no matrix: " + why, 0);
    return none;
  }
  Real knorm = K.norm();
  expect(K.allFinite() && knorm > 0, name + ": K finite and nonzero", knorm);

  // (1) Rigid-body modes: |K r| <= 1e-12 |K|_F |r|.
  int m = 0;
  for (const V12& r : rigid_modes(X)) {
    Real ratio = (K * r).norm() / (knorm * r.norm());
    worst_kernel = std::max(worst_kernel, ratio);
    expect(ratio <= 1e-12L, name + ": rigid mode " + std::to_string(m) + " not in the kernel", ratio);
    ++m;
  }

  // (2) Against the textbook element, with Jm.inverse() (Eigen's closed form
  // for 3x3) and, as a second route that shares nothing with the cofactors,
  // with an LU factorisation.
  M3 Jm = jacobian(X);
  Real J = geometry(X).J;
  if (ex.textbook) {
    for (int route = 0; route < 2; ++route) {
      M3 Jinv = route == 0 ? M3(Jm.inverse()) : M3(Jm.fullPivLu().inverse());
      Real d = rel_diff(K, textbook(Jm, Jinv, E, nu));
      worst_textbook = std::max(worst_textbook, d);
      expect(d <= 1e-13L, name + (route == 0 ? ": K != V B^T D B (inverse)" : ": K != V B^T D B (LU)"), d);
    }
  }
  if (ex.tempered) {
    M3 Jinv = Jm.inverse();
    Real V = Jm.determinant() / 6;
    M12 R = (J / jmin) * textbook(Jm, Jinv, E, nu);  // (J/jmin) V B^T D B = A^T D A / (6 jmin)
    Real d = rel_diff(K, R);
    worst_textbook = std::max(worst_textbook, d);
    expect(d <= 1e-13L && V != 0, name + ": K != (J/jmin) V B^T D B", d);
  }

  // (3), (4) Symmetric, positive semidefinite; the count of zero eigenvalues.
  Real scale = K.cwiseAbs().maxCoeff();
  Real asym = (K - K.transpose()).cwiseAbs().maxCoeff();
  expect(asym <= 1e-15L * scale, name + ": K not symmetric", asym / scale);
  Eigen::SelfAdjointEigenSolver<M12> es(K, Eigen::EigenvaluesOnly);
  Eigen::Matrix<Real, 12, 1> ev = es.eigenvalues();  // ascending
  Real hi = ev(11);
  expect(hi > 0 && ev(0) >= -1e-12L * hi, name + ": K not PSD (lambda_min / lambda_max)", ev(0) / hi);
  if (ex.zero_eigs >= 0) {
    int zeros = 0;
    for (int i = 0; i < 12; ++i) zeros += std::fabs(ev(i)) <= 1e-12L * hi;
    expect(zeros == ex.zero_eigs, name + ": zero eigenvalues " + std::to_string(zeros) + ", expected " +
                                      std::to_string(ex.zero_eigs),
           zeros);
    // A clear gap: the smallest nonzero eigenvalue is 1e3 above the zero
    // threshold, not a rounding error. (The thin tets' softest mode, which
    // scales as (J / h^3)^2, sits at 5e-9 of the largest.)
    if (zeros == ex.zero_eigs && zeros < 12)
      expect(ev(zeros) >= 1e-9L * hi, name + ": no clear gap above the zero eigenvalues", ev(zeros) / hi);
  }
  return ev / hi;
}

static M34 tet(std::initializer_list<double> xyz) {
  std::vector<double> v(xyz);
  return nodes_from(v.data());
}

static M3 rotation(std::mt19937_64& rng) {
  std::normal_distribution<double> N;
  Eigen::Quaternion<Real> q((Real)N(rng), (Real)N(rng), (Real)N(rng), (Real)N(rng));
  return q.normalized().toRotationMatrix();
}

static int self_test() {
  std::mt19937_64 rng(7321);
  const Real E = 2.1e11L, nu = 0.3L;
  const Expect full{true, false, 6};

  // Unit right tet, J = 1; also as plain FEM (jmin = 0) and with nu near 0.5.
  M34 right = tet({0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1});
  check("unit right tet", right, E, nu, 1e-6L, full);
  check("unit right tet, jmin = 0", right, E, nu, 0, full);
  check("unit right tet, nu = 0.49", right, 7e4L, 0.49L, 1e-6L, full);
  check("unit right tet, nu = -0.5", right, 1, -0.5L, 1e-6L, full);

  // Regular tet (alternate corners of a cube, edge 2 sqrt 2), as given and
  // rotated and moved off the origin (the rotations then move the nodes).
  M34 regular = tet({1, 1, 1, -1, -1, 1, -1, 1, -1, 1, -1, -1});
  if (geometry(regular).J < 0) regular.col(1).swap(regular.col(2));
  Eigen::Matrix<Real, 12, 1> ev = check("regular tet", regular, E, nu, 1e-6L, full);
  std::printf("regular tet (nu = 0.3): eigenvalues / largest:");
  for (int i = 0; i < 12; ++i) std::printf(" %.3Lg", ev(i));
  std::printf("\n");
  M34 moved = rotation(rng) * regular;
  moved.colwise() += V3(3.5L, -2, 10);
  check("regular tet, rotated and moved", moved, E, nu, 1e-6L, full);

  // Random tets in [-1, 1]^3, oriented, not nearly flat.
  std::uniform_real_distribution<double> U(-1, 1);
  for (int n = 0; n < 200;) {
    M34 X;
    for (int k = 0; k < 4; ++k)
      for (int i = 0; i < 3; ++i) X(i, k) = U(rng);
    Real J = geometry(X).J;
    if (std::fabs(J) < 0.05L) continue;
    if (J < 0) X.col(1).swap(X.col(2));
    check("random tet " + std::to_string(n), X, E, nu, 1e-6L, full);
    ++n;
  }

  // Tempered regime (0 < J < jmin, and inverted J < 0): K = A^T D A / (6 jmin).
  M34 thin = tet({0, 0, 0, 1, 0, 0, 0, 1, 0, 0.2, 0.3, 1e-4});
  check("thin tet, J = 1e-4 < jmin = 1e-2", thin, E, nu, 1e-2L, {false, true, 6});
  check("thin tet, J = 1e-4 > jmin = 1e-6", thin, E, nu, 1e-6L, full);
  M34 inverted = right;
  inverted.col(1).swap(inverted.col(2));
  check("inverted unit right tet, J = -1", inverted, E, nu, 1e-3L, {false, true, 6});
  M34 inverted_thin = thin;
  inverted_thin(2, 3) = -1e-4;
  check("inverted thin tet, J = -1e-4", inverted_thin, E, nu, 1e-2L, {false, true, 6});

  // Flat tets (J = 0 exactly): every a_k is a multiple of the plane's normal
  // n (adj of a rank-2 matrix has rank 1), so A u = sym(g (x) n) J with
  // g = sum c_k u_k: rank 3, 9 zero eigenvalues.
  M34 flat = tet({0, 0, 0, 1, 0, 0, 0, 1, 0, 0.3, 0.4, 0});
  expect(geometry(flat).J == 0, "flat tet: J != 0", geometry(flat).J);
  check("flat tet in z = 0", flat, E, nu, 1e-3L, {false, false, 9});
  M34 tilted = tet({0, 0, 0, 1, 0, 1, 0, 1, 2, 1, 1, 3});  // on x + 2y - z = 0
  expect(geometry(tilted).J == 0, "tilted flat tet: J != 0", geometry(tilted).J);
  check("flat tet in x + 2y - z = 0", tilted, E, nu, 1e-3L, {false, false, 9});
  M34 flat_far = tilted;
  flat_far.colwise() += V3(100, -50, 0);  // x + 2y - z = 0 shifts to another plane, still exact
  check("flat tet, moved", flat_far, E, nu, 1e-3L, {false, false, 9});

  // Collinear and coincident nodes: every 2x2 minor vanishes, K = 0.
  for (const auto& c : {std::make_pair(std::string("collinear"), tet({0, 0, 0, 1, 1, 1, 2, 2, 2, -1, -1, -1})),
                        std::make_pair(std::string("coincident"), tet({1, 2, 3, 1, 2, 3, 1, 2, 3, 1, 2, 3}))}) {
    M12 K;
    std::string why;
    bool ok = stiffness(c.second, E, nu, 1e-3L, &K, &why);
    expect(ok && K.allFinite() && K.cwiseAbs().maxCoeff() == 0, c.first + " nodes: K != 0", ok ? K.norm() : -1);
  }

  // No matrix: jmin = 0 with J <= 0, and invalid inputs.
  auto refused = [](const std::string& what, const M34& X, Real e, Real n, Real jmin) {
    M12 K;
    std::string why;
    expect(!stiffness(X, e, n, jmin, &K, &why), what + ": expected no matrix", 0);
  };
  refused("flat tet, jmin = 0", flat, E, nu, 0);
  refused("inverted tet, jmin = 0", inverted, E, nu, 0);
  refused("nu = 0.5", right, E, 0.5L, 1e-6L);
  refused("E = 0", right, 0, nu, 1e-6L);
  refused("jmin < 0", right, E, nu, -1);

  std::printf("tet_reference self-test: worst |K r| / (|K| |r|) over rigid modes %.3Lg, "
              "worst relative difference from the textbook element %.3Lg\n",
              worst_kernel, worst_textbook);
  std::printf("%d passed, %d failed\n", checks - failures, failures);
  return failures == 0 ? 0 : 1;
}

// ---------------------------------------------------------------------------

// Parses exactly 15 numbers; false on anything else.
static bool parse_line(const std::string& line, double v[15]) {
  const char* p = line.c_str();
  int n = 0;
  for (;;) {
    while (*p && std::isspace((unsigned char)*p)) ++p;
    if (!*p) break;
    if (n == 15) return false;
    char* end = nullptr;
    v[n] = std::strtod(p, &end);
    if (end == p || (*end && !std::isspace((unsigned char)*end))) return false;
    ++n;
    p = end;
  }
  return n == 15;
}

int main(int argc, char** argv) {
  if (argc == 2 && std::strcmp(argv[1], "--self-test") == 0) return self_test();
  if (argc != 1) {
    std::fprintf(stderr, "usage: %s [--self-test] < lines of 'x0 y0 z0 ... x3 y3 z3 E nu jmin'\n", argv[0]);
    return 2;
  }
  std::string line;
  long lineno = 0;
  while (std::getline(std::cin, line)) {
    ++lineno;
    if (line.find_first_not_of(" \t\r\n\v\f") == std::string::npos) continue;
    double v[15];
    M12 K;
    std::string why;
    if (!parse_line(line, v)) {
      why = "expected 15 numbers";
    } else if (stiffness(nodes_from(v), v[12], v[13], v[14], &K, &why)) {
      for (int r = 0; r < 12; ++r)
        for (int c = 0; c < 12; ++c) std::printf(c == 0 && r == 0 ? "%.17g" : " %.17g", (double)K(r, c));
      std::printf("\n");
      continue;
    }
    std::fprintf(stderr, "line %ld: %s\n", lineno, why.c_str());
    std::printf("error\n");
  }
  return 0;
}
