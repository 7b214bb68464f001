// A host code's Newton–Raphson loop with a nonlinear bulk material, taking
// only the contact contributions from tfem.
//
// The scene is the seed scene of examples/host_q4.cpp (two blocks, Q4
// elements, the same grid, node and equation numbers; read that file first:
// the mesh, constraints and load below are the same code, shortened), with
// a small-strain *hyperelastic stiffening* law in the bulk instead of linear
// elasticity (plane strain, ε_zz = 0, ε the 3D small strain):
//
//   W(ε) = ½ κ (tr ε)² + μ e + μ α e² / (2 ε0²),   e = ε_d : ε_d,
//   σ = ∂W/∂ε = κ (tr ε) 1 + 2 μ g ε_d,            g = 1 + α e / ε0²,
//
// κ, μ the bulk and shear moduli of the block's (E, ν), ε_d the deviator
// of ε. The shear stiffness grows with the distortion: by a factor 2 where
// the deviatoric strain reaches ε0 / √α (here ε0 = 1e-3 by default, the
// order of the strain of the soft lower block). W is convex, its tangent
// C = κ 1⊗1 + 2 μ g P_dev + 4 μ α / ε0² ε_d⊗ε_d is symmetric positive
// definite, so the host keeps its Cholesky factorisation, and Newton
// converges quadratically. With α = 0 (--linear) it is linear elasticity
// (κ 1⊗1 + 2 μ P_dev is the plane-strain D of (E, ν)), and the result is
// host_q4's to round-off.
//
// The loop (the host's, not tfem's): an outer active-set loop around an
// inner Newton loop.
//   for each active set:
//     Newton to ‖R(u)‖ ≤ tol ‖f_ext‖, warm-started from the previous u:
//       R(u)   = f_int(u) + r_c(u) − f_ext      (r_c: tfem_contact_evaluate)
//       K_t(u) = ∂f_int/∂u + K_c                (K_c: its values, fixed pattern)
//       K_t Δu = −R,  u ← u + Δu
//     tfem_contact_update(u): done when the set is unchanged.
// Why not update the active set at every Newton iterate: the inversion test
// and cycle detection of tfem_contact_update reason about solutions of a
// fixed active set; an unconverged iterate can flip elements that the
// converged solution would not, and a set seen on the way counts as visited
// (a false cycle, TFEM_STATUS_NOT_CONVERGED). The contact law is linear for a
// fixed set, so the inner Newton sees a smooth problem and converges
// quadratically; with the warm start, later sets need few iterations. In the
// linear limit the scheme is exactly host_q4's loop (one Newton step per
// set).
//
// Usage:
//   host_newton [--h H | --n N] [--c C] [--alpha A] [--eps0 E] [--linear]
//               [--tol T] [--json] [--dump FILE] [--compare FILE]
//               [--max-newton N]
//     --h / --n     element size (1/16 by default) or 1/N
//     --alpha, --eps0  the stiffening law (1, 1e-3); --linear: α = 0
//     --tol         Newton tolerance on ‖R‖ / ‖f_ext‖ (1e-10)
//     --dump FILE   nodal displacements ("x y ux uy" lines, as host_q4 --dump)
//     --compare FILE  exit 1 unless the displacements match that dump to
//                   1e-10 of the largest displacement
//     --max-newton N  exit 1 if an active set needs more Newton iterations

#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "tfem.h"

namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

struct Scene {
  double length = 1.0, h1 = 0.25, h2 = 0.25;
  double e1 = 1e10, nu1 = 0.3, e2 = 1e11, nu2 = 0.3;
  double c = 0.1, p = 1e7;
  double h = 1.0 / 16.0;
};

// --- Mesh, constraints, load: as in host_q4.cpp. ----------------------------

std::vector<double> subdivide(double a, double b, const std::vector<double>& stops, double h) {
  std::vector<double> knots{a};
  for (double s : stops)
    if (s > a && s < b) knots.push_back(s);
  knots.push_back(b);
  std::vector<double> out{a};
  for (size_t w = 0; w + 1 < knots.size(); ++w) {
    const double lo = knots[w], hi = knots[w + 1];
    const long n = std::max(1L, static_cast<long>(std::ceil((hi - lo) / h - 1e-9)));
    for (long k = 1; k <= n; ++k)
      out.push_back(k == n ? hi : lo + (hi - lo) * static_cast<double>(k) / static_cast<double>(n));
  }
  return out;
}

std::vector<double> subdivide_symmetric(double a, double b, const std::vector<double>& stops,
                                        double h) {
  const double mid = 0.5 * (a + b);
  std::vector<double> left;
  for (double s : stops)
    if (s > a && s < mid) left.push_back(s);
  const std::vector<double> half = subdivide(a, mid, left, h);
  std::vector<double> out = half;
  for (size_t k = half.size() - 1; k-- > 0;) out.push_back(mid + (mid - half[k]));
  out.back() = b;
  return out;
}

struct Mesh {
  std::vector<double> xs, ys1, ys2;
  std::vector<std::array<double, 2>> x;
  std::vector<int> body;
  std::vector<std::array<int, 4>> quads;
  std::vector<int> quad_body;
  int nx = 0, n_lower = 0;
  int lower(int i, int j) const { return j * nx + i; }
  int upper(int i, int j) const { return n_lower + j * nx + i; }
};

Mesh build_mesh(const Scene& s) {
  Mesh m;
  const double mid = 0.5 * s.length;
  m.xs = subdivide_symmetric(0.0, s.length, {mid - s.c, mid + s.c}, s.h);
  m.ys1 = subdivide(-s.h1, 0.0, {}, s.h);
  m.ys2 = subdivide(0.0, s.h2, {}, s.h);
  m.nx = static_cast<int>(m.xs.size());
  auto grid = [&](const std::vector<double>& ys, int body) {
    const int first = static_cast<int>(m.x.size());
    for (double y : ys)
      for (double x : m.xs) {
        m.x.push_back({x, y});
        m.body.push_back(body);
      }
    for (int j = 0; j + 1 < static_cast<int>(ys.size()); ++j)
      for (int i = 0; i + 1 < m.nx; ++i) {
        const int a = first + j * m.nx + i;
        m.quads.push_back({a, a + 1, a + 1 + m.nx, a + m.nx});
        m.quad_body.push_back(body);
      }
  };
  grid(m.ys1, 1);
  m.n_lower = static_cast<int>(m.x.size());
  grid(m.ys2, 2);
  return m;
}

struct Dofs {
  std::vector<int> equation;  // per DOF 2·node + component; −1: constrained
  int n = 0;
  double u(const Eigen::VectorXd& sol, int node, int comp) const {
    const int e = equation[2 * node + comp];
    return e < 0 ? 0.0 : sol[e];
  }
};

bool in_segment(const Scene& s, double x) {
  const double mid = 0.5 * s.length;
  return x >= mid - s.c && x <= mid + s.c;
}

Dofs number_dofs(const Scene& s, const Mesh& m) {
  std::vector<char> fixed(2 * m.x.size(), 0);
  for (size_t v = 0; v < m.x.size(); ++v) {
    if (m.x[v][0] == 0.5 * s.length) fixed[2 * v] = 1;
    if (m.body[v] == 1 && m.x[v][1] == -s.h1 && in_segment(s, m.x[v][0])) fixed[2 * v + 1] = 1;
  }
  Dofs d;
  d.equation.assign(fixed.size(), -1);
  for (size_t g = 0; g < fixed.size(); ++g)
    if (!fixed[g]) d.equation[g] = d.n++;
  return d;
}

Eigen::VectorXd pressure_load(const Scene& s, const Mesh& m, const Dofs& d) {
  Eigen::VectorXd f = Eigen::VectorXd::Zero(d.n);
  const int top = static_cast<int>(m.ys2.size()) - 1;
  for (int i = 0; i + 1 < m.nx; ++i) {
    if (!(in_segment(s, m.xs[i]) && in_segment(s, m.xs[i + 1]))) continue;
    const double half = 0.5 * s.p * (m.xs[i + 1] - m.xs[i]);
    for (int v : {m.upper(i, top), m.upper(i + 1, top)}) {
      const int e = d.equation[2 * v + 1];
      if (e >= 0) f[e] -= half;
    }
  }
  return f;
}

// --- The nonlinear material. ------------------------------------------------

// Strains and stresses in Voigt order (xx, yy, xy) with the engineering
// shear γ = 2 ε_xy; σ_zz is not needed (plane strain, ε_zz = 0).
struct Stiffening {
  double kappa, mu, alpha, eps0;

  Stiffening(double e, double nu, double alpha_, double eps0_)
      : kappa(e / (3.0 * (1.0 - 2.0 * nu))), mu(e / (2.0 * (1.0 + nu))), alpha(alpha_),
        eps0(eps0_) {}

  // σ(ε) and its tangent C = dσ/dε.
  void evaluate(const Eigen::Vector3d& eps, Eigen::Vector3d& sigma, Eigen::Matrix3d& c) const {
    const double tr = eps[0] + eps[1], m = tr / 3.0;
    // s = (ε_d,xx, ε_d,yy, ε_xy); ε_d,zz = −m. e = ε_d : ε_d.
    const Eigen::Vector3d s(eps[0] - m, eps[1] - m, 0.5 * eps[2]);
    const double e = s[0] * s[0] + s[1] * s[1] + m * m + 2.0 * s[2] * s[2];
    const double g = 1.0 + alpha * e / (eps0 * eps0);
    const Eigen::Vector3d one(1.0, 1.0, 0.0);
    sigma = kappa * tr * one + 2.0 * mu * g * s;
    // ds/dε: the deviatoric projection in Voigt form (engineering shear).
    Eigen::Matrix3d p;
    p << 2.0 / 3.0, -1.0 / 3.0, 0.0,  //
        -1.0 / 3.0, 2.0 / 3.0, 0.0,   //
        0.0, 0.0, 0.5;
    // de/dε = 2 s (with γ: de/dγ = γ = 2 s_xy).
    c = kappa * one * one.transpose() + 2.0 * mu * g * p +
        4.0 * mu * alpha / (eps0 * eps0) * s * s.transpose();
  }
};

// --- Q4, 2×2 Gauss: internal force and tangent of one element. --------------

using Matrix8 = Eigen::Matrix<double, 8, 8>;
using Vector8 = Eigen::Matrix<double, 8, 1>;

void q4_internal(const std::array<std::array<double, 2>, 4>& xe, const Vector8& ue,
                 const Stiffening& law, Vector8& fe, Matrix8& ke) {
  static const double gp = 1.0 / std::sqrt(3.0);
  static const double xi_a[4] = {-1, 1, 1, -1}, eta_a[4] = {-1, -1, 1, 1};
  fe.setZero();
  ke.setZero();
  for (double xi : {-gp, gp})
    for (double eta : {-gp, gp}) {
      double dn[4][2];
      for (int a = 0; a < 4; ++a) {
        dn[a][0] = 0.25 * xi_a[a] * (1.0 + eta_a[a] * eta);
        dn[a][1] = 0.25 * eta_a[a] * (1.0 + xi_a[a] * xi);
      }
      double j[2][2] = {{0, 0}, {0, 0}};
      for (int a = 0; a < 4; ++a)
        for (int r = 0; r < 2; ++r)
          for (int c = 0; c < 2; ++c) j[r][c] += dn[a][r] * xe[a][c];
      const double det = j[0][0] * j[1][1] - j[0][1] * j[1][0];
      Eigen::Matrix<double, 3, 8> b = Eigen::Matrix<double, 3, 8>::Zero();
      for (int a = 0; a < 4; ++a) {
        const double dx = (j[1][1] * dn[a][0] - j[0][1] * dn[a][1]) / det;
        const double dy = (-j[1][0] * dn[a][0] + j[0][0] * dn[a][1]) / det;
        b(0, 2 * a) = dx;
        b(1, 2 * a + 1) = dy;
        b(2, 2 * a) = dy;
        b(2, 2 * a + 1) = dx;
      }
      Eigen::Vector3d sigma;
      Eigen::Matrix3d c;
      law.evaluate(b * ue, sigma, c);
      fe.noalias() += b.transpose() * sigma * det;
      ke.noalias() += b.transpose() * c * b * det;
    }
}

// --- tfem's contact context (as in host_q4.cpp). ----------------------------

void check(tfem_status status, const tfem_contact* ctx, const char* call) {
  if (status == TFEM_STATUS_OK) return;
  char message[2048];
  tfem_contact_last_error(ctx, message, sizeof message);
  std::fprintf(stderr, "%s failed (status %d): %s\n", call, static_cast<int>(status), message);
  std::exit(1);
}

int add_side(tfem_contact* ctx, const Scene& s, const Mesh& m, const Dofs& d, int body) {
  std::vector<int> nodes, edges;
  std::vector<double> xy;
  std::vector<int64_t> equations;
  const int row = body == 1 ? static_cast<int>(m.ys1.size()) - 1 : 0;
  auto node = [&](int i) { return body == 1 ? m.lower(i, row) : m.upper(i, 0); };
  for (int i = 0; i < m.nx; ++i) {
    const int v = node(i);
    nodes.push_back(v);
    xy.insert(xy.end(), {m.x[v][0], m.x[v][1]});
    equations.insert(equations.end(), {d.equation[2 * v], d.equation[2 * v + 1]});
  }
  for (int i = 0; i + 1 < m.nx; ++i) {  // the block on the left of each edge
    if (body == 1)
      edges.insert(edges.end(), {node(i + 1), node(i)});
    else
      edges.insert(edges.end(), {node(i), node(i + 1)});
  }
  int side = -1;
  check(tfem_contact_add_side(ctx, body, body, body == 1 ? s.e1 : s.e2, body == 1 ? s.nu1 : s.nu2,
                              TFEM_PLANE_MODE_STRAIN, static_cast<int>(nodes.size()), nodes.data(),
                              xy.data(), equations.data(), static_cast<int>(edges.size() / 2),
                              edges.data(), &side),
        ctx, "tfem_contact_add_side");
  return side;
}

void usage(const char* self) {
  std::fprintf(stderr,
               "usage: %s [--h H | --n N] [--c C] [--alpha A] [--eps0 E] [--linear] [--tol T] "
               "[--json] [--dump FILE] [--compare FILE] [--max-newton N]\n",
               self);
  std::exit(2);
}

}  // namespace

int main(int argc, char** argv) {
  Scene s;
  double alpha = 1.0, eps0 = 1e-3, tol = 1e-10;
  bool json = false;
  const char *dump = nullptr, *compare = nullptr;
  int max_newton_allowed = 50;
  for (int k = 1; k < argc; ++k) {
    const std::string a = argv[k];
    const bool has_value = k + 1 < argc;
    if (a == "--json") json = true;
    else if (a == "--linear") alpha = 0.0;
    else if (a == "--h" && has_value) s.h = std::atof(argv[++k]);
    else if (a == "--n" && has_value) s.h = 1.0 / std::atof(argv[++k]);
    else if (a == "--c" && has_value) s.c = std::atof(argv[++k]);
    else if (a == "--alpha" && has_value) alpha = std::atof(argv[++k]);
    else if (a == "--eps0" && has_value) eps0 = std::atof(argv[++k]);
    else if (a == "--tol" && has_value) tol = std::atof(argv[++k]);
    else if (a == "--dump" && has_value) dump = argv[++k];
    else if (a == "--compare" && has_value) compare = argv[++k];
    else if (a == "--max-newton" && has_value) max_newton_allowed = std::atoi(argv[++k]);
    else usage(argv[0]);
  }
  if (!(s.h > 0.0 && s.c > 0.0 && 2.0 * s.c <= s.length && alpha >= 0.0 && eps0 > 0.0))
    usage(argv[0]);

  const Clock::time_point start = Clock::now();
  const Mesh m = build_mesh(s);
  const Dofs d = number_dofs(s, m);
  const Eigen::VectorXd f_ext = pressure_load(s, m, d);
  const Stiffening laws[2] = {Stiffening(s.e1, s.nu1, alpha, eps0),
                              Stiffening(s.e2, s.nu2, alpha, eps0)};

  tfem_contact* ctx = tfem_contact_create(0);
  if (!ctx) return 1;
  const int lower_side = add_side(ctx, s, m, d, 1), upper_side = add_side(ctx, s, m, d, 2);
  check(tfem_contact_add_pair(ctx, lower_side, upper_side, nullptr), ctx, "tfem_contact_add_pair");
  int n_if = 0, n_el = 0;
  int64_t n_entries = 0;
  check(tfem_contact_sizes(ctx, &n_if, &n_el, &n_entries), ctx, "tfem_contact_sizes");
  std::vector<int64_t> rows(n_entries), cols(n_entries);
  check(tfem_contact_pattern(ctx, rows.data(), cols.data(), rows.size()), ctx,
        "tfem_contact_pattern");

  // The tangent's structure (lower triangle, Q4 ∪ contact), built once with
  // zeros; then the slot of every element entry and every contact entry in
  // its values, so that each Newton iteration writes values in place.
  std::vector<Eigen::Triplet<double>> triplets;
  auto eq = [&](int q, int a) { return d.equation[2 * m.quads[q][a / 2] + a % 2]; };
  for (size_t q = 0; q < m.quads.size(); ++q)
    for (int a = 0; a < 8; ++a)
      for (int b = 0; b < 8; ++b)
        if (eq(q, a) >= 0 && eq(q, b) >= 0 && eq(q, a) >= eq(q, b))
          triplets.emplace_back(eq(q, a), eq(q, b), 0.0);
  for (int64_t k = 0; k < n_entries; ++k)
    if (rows[k] >= cols[k])
      triplets.emplace_back(static_cast<int>(rows[k]), static_cast<int>(cols[k]), 0.0);
  Eigen::SparseMatrix<double> kt(d.n, d.n);
  kt.setFromTriplets(triplets.begin(), triplets.end());
  triplets = {};
  auto slot_of = [&](int i, int j) -> int {  // −1: upper triangle or no equation
    if (i < 0 || j < 0 || i < j) return -1;
    const int* inner = kt.innerIndexPtr();
    const int lo = kt.outerIndexPtr()[j], hi = kt.outerIndexPtr()[j + 1];
    return static_cast<int>(std::lower_bound(inner + lo, inner + hi, i) - inner);
  };
  std::vector<std::array<int, 64>> element_slots(m.quads.size());
  for (size_t q = 0; q < m.quads.size(); ++q)
    for (int a = 0; a < 8; ++a)
      for (int b = 0; b < 8; ++b) element_slots[q][8 * a + b] = slot_of(eq(q, a), eq(q, b));
  std::vector<int> contact_slots(n_entries);
  for (int64_t k = 0; k < n_entries; ++k)
    contact_slots[k] = slot_of(static_cast<int>(rows[k]), static_cast<int>(cols[k]));

  Eigen::SimplicialLLT<Eigen::SparseMatrix<double>, Eigen::Lower> llt;
  llt.analyzePattern(kt);

  std::vector<double> values(n_entries), r_c(2 * n_if), u_if(2 * n_if);
  Eigen::VectorXd u = Eigen::VectorXd::Zero(d.n), residual(d.n);
  const double f_norm = f_ext.norm();
  double t_assembly = 0, t_factorization = 0, t_evaluate = 0;
  int evaluations = 0;

  // R(u) and K_t(u): the host's element loop, then tfem's contact terms.
  auto assemble = [&]() {
    Clock::time_point t = Clock::now();
    std::fill(kt.valuePtr(), kt.valuePtr() + kt.nonZeros(), 0.0);
    residual = -f_ext;
    Vector8 ue, fe;
    Matrix8 ke;
    for (size_t q = 0; q < m.quads.size(); ++q) {
      std::array<std::array<double, 2>, 4> xe;
      for (int a = 0; a < 4; ++a) xe[a] = m.x[m.quads[q][a]];
      for (int a = 0; a < 8; ++a) ue[a] = eq(q, a) < 0 ? 0.0 : u[eq(q, a)];
      q4_internal(xe, ue, laws[m.quad_body[q] - 1], fe, ke);
      for (int a = 0; a < 8; ++a) {
        if (eq(q, a) < 0) continue;
        residual[eq(q, a)] += fe[a];
        for (int b = 0; b < 8; ++b)
          if (element_slots[q][8 * a + b] >= 0) kt.valuePtr()[element_slots[q][8 * a + b]] += ke(a, b);
      }
    }
    t_assembly += seconds_since(t);
    t = Clock::now();
    check(tfem_contact_gather(ctx, u.data(), u.size(), u_if.data(), u_if.size()), ctx,
          "tfem_contact_gather");
    check(tfem_contact_evaluate(ctx, u_if.data(), u_if.size(), values.data(), values.size(),
                                r_c.data(), r_c.size()),
          ctx, "tfem_contact_evaluate");
    t_evaluate += seconds_since(t);
    ++evaluations;
    check(tfem_contact_scatter_add(ctx, r_c.data(), r_c.size(), residual.data(), residual.size()),
          ctx, "tfem_contact_scatter_add");
    for (int64_t k = 0; k < n_entries; ++k)
      if (contact_slots[k] >= 0) kt.valuePtr()[contact_slots[k]] += values[k];
  };

  std::vector<std::vector<double>> history;  // ‖R‖/‖f_ext‖ per Newton iterate, per active set
  int max_newton = 0, total_newton = 0;
  bool failed = false;
  for (int changed = 1; changed && !failed;) {
    history.emplace_back();
    std::vector<double>& h = history.back();
    for (int it = 0;; ++it) {
      assemble();
      h.push_back(residual.norm() / f_norm);
      if (!json)
        std::printf("active set %zu, Newton %2d: |R|/|f| = %.3e\n", history.size(), it, h.back());
      if (h.back() <= tol) break;
      if (it == max_newton_allowed || !std::isfinite(h.back())) {
        std::fprintf(stderr, "Newton did not converge in %d iterations (active set %zu)\n", it,
                     history.size());
        failed = true;
        break;
      }
      Clock::time_point t = Clock::now();
      llt.factorize(kt);
      t_factorization += seconds_since(t);
      if (llt.info() != Eigen::Success) {
        std::fprintf(stderr, "factorisation failed (a block unrestrained?)\n");
        return 1;
      }
      u -= llt.solve(residual);
    }
    const int steps = static_cast<int>(h.size()) - 1;  // solves of this set
    max_newton = std::max(max_newton, steps);
    total_newton += steps;
    // u_if is the gather of the converged u (assemble() did it last).
    if (!failed)
      check(tfem_contact_update(ctx, u_if.data(), u_if.size(), &changed), ctx,
            "tfem_contact_update");
  }

  // The seed quantities, as host_q4 computes them.
  std::vector<int> tri(3 * n_el), active(n_el);
  check(tfem_contact_elements(ctx, tri.data(), tri.size()), ctx, "tfem_contact_elements");
  check(tfem_contact_get_active(ctx, active.data(), active.size()), ctx, "tfem_contact_get_active");
  double lc = 0.0;
  int n_active = 0;
  for (int k = 0; k < n_el; ++k) {
    if (!active[k]) continue;
    ++n_active;
    for (int a = 0; a < 3; ++a) {
      const int p = tri[3 * k + a], q = tri[3 * k + (a + 1) % 3];
      if (m.body[p] == m.body[q]) lc += std::hypot(m.x[q][0] - m.x[p][0], m.x[q][1] - m.x[p][1]);
    }
  }
  lc *= 0.5;
  const int top = static_cast<int>(m.ys2.size()) - 1, i_mid = (m.nx - 1) / 2;
  const double gap_edge =
      d.u(u, m.upper(0, 0), 1) - d.u(u, m.lower(0, static_cast<int>(m.ys1.size()) - 1), 1);
  const double v_top = d.u(u, m.upper(i_mid, top), 1);
  const double compliance = f_ext.dot(u);
  tfem_contact_destroy(ctx);
  const double t_total = seconds_since(start);

  if (dump) {
    std::FILE* out = std::fopen(dump, "w");
    if (!out) return 1;
    for (size_t v = 0; v < m.x.size(); ++v)
      std::fprintf(out, "%.17g %.17g %.17g %.17g\n", m.x[v][0], m.x[v][1],
                   d.u(u, static_cast<int>(v), 0), d.u(u, static_cast<int>(v), 1));
    std::fclose(out);
  }
  // Against another host's dump (host_q4 --dump at the same h and C).
  double compare_difference = -1.0;
  if (compare) {
    std::FILE* in = std::fopen(compare, "r");
    if (!in) {
      std::fprintf(stderr, "cannot read %s\n", compare);
      return 1;
    }
    double diff = 0.0, scale = 0.0, x, y, ux, uy;
    size_t v = 0;
    while (std::fscanf(in, "%lf %lf %lf %lf", &x, &y, &ux, &uy) == 4) {
      if (v >= m.x.size() || x != m.x[v][0] || y != m.x[v][1]) {
        std::fprintf(stderr, "%s: node %zu is not this mesh's\n", compare, v);
        return 1;
      }
      const int node = static_cast<int>(v++);
      diff = std::max({diff, std::fabs(ux - d.u(u, node, 0)), std::fabs(uy - d.u(u, node, 1))});
      scale = std::max({scale, std::fabs(ux), std::fabs(uy)});
    }
    std::fclose(in);
    if (v != m.x.size()) {
      std::fprintf(stderr, "%s holds %zu nodes, this mesh %zu\n", compare, v, m.x.size());
      return 1;
    }
    compare_difference = diff / scale;
  }

  if (json) {
    std::printf("{\"element\":\"Q4\",\"h\":%.17g,\"c\":%.17g,\"alpha\":%.17g,\"eps0\":%.17g,"
                "\"unknowns\":%d,\"active_set_iterations\":%zu,\"newton_total\":%d,"
                "\"newton_max_per_set\":%d,\"active_contact_elements\":%d,\"contact_elements\":%d,"
                "\"lc\":%.17g,\"gap_edge\":%.17g,\"v_top\":%.17g,\"compliance\":%.17g,",
                s.h, s.c, alpha, eps0, d.n, history.size(), total_newton, max_newton, n_active,
                n_el, lc, gap_edge, v_top, compliance);
    if (compare) std::printf("\"compare_relative_difference\":%.6g,", compare_difference);
    std::printf("\"time_assembly_s\":%.6g,\"time_factorization_s\":%.6g,"
                "\"contact_evaluations\":%d,\"time_contact_evaluate_per_call_s\":%.6g,"
                "\"time_total_s\":%.6g,\"residuals\":[",
                t_assembly, t_factorization, evaluations, t_evaluate / evaluations, t_total);
    for (size_t k = 0; k < history.size(); ++k) {
      std::printf("%s[", k ? "," : "");
      for (size_t i = 0; i < history[k].size(); ++i)
        std::printf("%s%.6g", i ? "," : "", history[k][i]);
      std::printf("]");
    }
    std::printf("]}\n");
  } else {
    std::printf("h = %g, 2C/L = %g, α = %g, ε0 = %g: %d unknowns, %zu active sets, "
                "%d Newton iterations (at most %d per set), %d of %d contact elements active\n",
                s.h, 2.0 * s.c / s.length, alpha, eps0, d.n, history.size(), total_newton,
                max_newton, n_active, n_el);
    std::printf("  lc = %.7g, gap_edge = %.7g, v_top = %.7g, compliance = %.7g\n", lc, gap_edge,
                v_top, compliance);
    if (compare) std::printf("  max |u − u(%s)| / max |u| = %.3e\n", compare, compare_difference);
    std::printf("  time: assembly %.4f s, factorisations %.4f s, contact evaluation %.2e s per "
                "call (%d calls), total %.4f s\n",
                t_assembly, t_factorization, t_evaluate / evaluations, evaluations, t_total);
  }
  if (failed) return 1;
  if (max_newton > max_newton_allowed) {
    std::fprintf(stderr, "an active set needed %d Newton iterations (at most %d allowed)\n",
                 max_newton, max_newton_allowed);
    return 1;
  }
  if (compare && !(compare_difference <= 1e-10)) {
    std::fprintf(stderr, "the displacements differ from %s by %.3e of the largest\n", compare,
                 compare_difference);
    return 1;
  }
  return 0;
}
