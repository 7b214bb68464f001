// A host code of its own, using tfem only for contact.
//
// The seed scene (docs/method.md §4): two elastic blocks, the soft lower
// block Ω1 = [0, L] × [−H1, 0] under the stiff upper block
// Ω2 = [0, L] × [0, H2], touching along y = 0 with distinct coincident
// interface nodes; a pressure p on the top of Ω2 over [L/2 − C, L/2 + C];
// the bottom of Ω1 supported (u_y = 0) over the same segment; u_x = 0 on the
// symmetry line x = L/2 in both blocks. Plane strain.
//
// Everything but contact is this program's own, as it would be in an
// existing finite-element code:
//   - a structured mesh of bilinear quadrilaterals (Q4) with grid lines on
//     x = L/2 and x = L/2 ± C, mirror-symmetric about x = L/2 (the same grid
//     lines as tfem's P1 scene, src/studies/scenes.rs, without the
//     diagonals);
//   - its own node numbers and its own equation numbers (constrained DOFs
//     eliminated);
//   - Q4 plane-strain elasticity with 2×2 Gauss integration, assembled into
//     an Eigen::SparseMatrix, factorised by Eigen::SimplicialLLT;
//   - its own active-set loop.
// tfem's contact context (tfem_contact_*, include/tfem.h) is told the
// interface nodes of each block, their coordinates, the equations of their
// unknowns and the interface edges; it builds the contact mesh B once and,
// at each evaluation, returns the contact tangent in a fixed pattern over
// the host's equations and the contact residual per interface node. Between
// solves, tfem_contact_update applies the inversion test and says whether
// the active set changed.
//
// Usage:
//   host_q4 [--h H]... [--n N]... [--c C] [--reference FILE] [--json]
//           [--dump FILE] [--min-rate R] [--lc-bound K] [--repeat K]
//     --h H        element size (several --h: one run each); --n N: h = 1/N
//     --c C        half-width of the loaded and supported segments (0.1)
//     --reference  the reference values (docs/reference/two_blocks_canonical.json)
//     --json       one JSON object per run, on one line
//     --dump FILE  the nodal displacements of the (last) run: "x y ux uy" lines
//     --min-rate R with several h: exit 1 unless the log-log rate fitted to
//                  the errors of gap_edge, v_top and compliance is at least R
//     --lc-bound K exit 1 unless |ℓc − reference| ≤ K·h at every size
//     --repeat K   run each size K times and report the smallest time of each
//                  phase (for measurements on a busy machine)
//
// Build (against the shared library in target/release):
//   g++ -std=c++17 -O2 -Wall -Wextra -Iinclude -isystem /usr/include/eigen3
//       examples/host_q4.cpp -Ltarget/release -ltfem -Wl,-rpath,$PWD/target/release

#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "tfem.h"

#ifndef HOST_Q4_REFERENCE
// Relative to the repository root; the CMake build passes the absolute path.
#define HOST_Q4_REFERENCE "docs/reference/two_blocks_canonical.json"
#endif

namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

// ---------------------------------------------------------------------------
// The scene's parameters (the canonical ones of docs/method.md §4).

struct Scene {
  double length = 1.0, h1 = 0.25, h2 = 0.25;
  double e1 = 1e10, nu1 = 0.3;  // lower block Ω1 (soft)
  double e2 = 1e11, nu2 = 0.3;  // upper block Ω2 (stiff)
  double c = 0.1, p = 1e7;
  double h = 1.0 / 32.0;
};

// ---------------------------------------------------------------------------
// Grid lines, as tfem's structured triangulator places them
// (src/studies/meshgen.rs): each interval between stops is cut into
// ceil(length / h) equal parts.

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

// Mirror-symmetric about (a + b)/2, which is a grid line: the left half is
// subdivided and reflected, so that both halves are the same to the bit.
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

// ---------------------------------------------------------------------------
// The host's mesh: nodes of Ω1 first (row by row from y = −H1 up), then the
// nodes of Ω2 (from y = 0 up). The interface y = 0 has a row of nodes in
// each block, at the same coordinates.

struct Mesh {
  std::vector<double> xs, ys1, ys2;        // grid lines
  std::vector<std::array<double, 2>> x;    // node coordinates
  std::vector<int> body;                   // 1 or 2, per node
  std::vector<std::array<int, 4>> quads;   // counter-clockwise
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

// ---------------------------------------------------------------------------
// Constraints and equation numbers: DOF 2·node + component; equation −1 for
// a constrained DOF (all constraints are homogeneous here), else the next
// number, node by node.

struct Dofs {
  std::vector<int> equation;  // per DOF
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
  const double mid = 0.5 * s.length;
  for (size_t v = 0; v < m.x.size(); ++v) {
    if (m.x[v][0] == mid) fixed[2 * v] = 1;  // symmetry: u_x = 0 in both blocks
    // Support: u_y = 0 on the bottom of Ω1 over [L/2 − C, L/2 + C].
    if (m.body[v] == 1 && m.x[v][1] == -s.h1 && in_segment(s, m.x[v][0])) fixed[2 * v + 1] = 1;
  }
  Dofs d;
  d.equation.assign(fixed.size(), -1);
  for (size_t g = 0; g < fixed.size(); ++g)
    if (!fixed[g]) d.equation[g] = d.n++;
  return d;
}

// The consistent load of the pressure on the top of Ω2: −p·(edge length)/2
// on u_y of both ends of each loaded edge (exact for a bilinear field along
// the edge, so that f·u is ∫ p (−u_y)).
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

// ---------------------------------------------------------------------------
// Q4 plane-strain elasticity, 2×2 Gauss.

Eigen::Matrix3d plane_strain(double e, double nu) {
  const double k = e / ((1.0 + nu) * (1.0 - 2.0 * nu));
  Eigen::Matrix3d d;
  d << k * (1.0 - nu), k * nu, 0.0,  //
      k * nu, k * (1.0 - nu), 0.0,   //
      0.0, 0.0, k * (1.0 - 2.0 * nu) / 2.0;
  return d;
}

using Matrix8 = Eigen::Matrix<double, 8, 8>;

// The stiffness of the quadrilateral with corners xe (counter-clockwise):
// Σ_gauss Bᵀ D B det J, B the strain–displacement matrix (engineering shear)
// over the DOFs x0 y0 x1 y1 x2 y2 x3 y3.
Matrix8 q4_stiffness(const std::array<std::array<double, 2>, 4>& xe, const Eigen::Matrix3d& d) {
  static const double g = 1.0 / std::sqrt(3.0);
  static const double xi_a[4] = {-1, 1, 1, -1}, eta_a[4] = {-1, -1, 1, 1};
  Matrix8 k = Matrix8::Zero();
  for (double xi : {-g, g})
    for (double eta : {-g, g}) {
      double dn[4][2];  // dN_a/dξ, dN_a/dη
      for (int a = 0; a < 4; ++a) {
        dn[a][0] = 0.25 * xi_a[a] * (1.0 + eta_a[a] * eta);
        dn[a][1] = 0.25 * eta_a[a] * (1.0 + xi_a[a] * xi);
      }
      double j[2][2] = {{0, 0}, {0, 0}};  // j[r][c] = ∂x_c/∂ξ_r
      for (int a = 0; a < 4; ++a)
        for (int r = 0; r < 2; ++r)
          for (int c = 0; c < 2; ++c) j[r][c] += dn[a][r] * xe[a][c];
      const double det = j[0][0] * j[1][1] - j[0][1] * j[1][0];
      const double jinv[2][2] = {{j[1][1] / det, -j[0][1] / det}, {-j[1][0] / det, j[0][0] / det}};
      Eigen::Matrix<double, 3, 8> b = Eigen::Matrix<double, 3, 8>::Zero();
      for (int a = 0; a < 4; ++a) {
        const double dx = jinv[0][0] * dn[a][0] + jinv[0][1] * dn[a][1];
        const double dy = jinv[1][0] * dn[a][0] + jinv[1][1] * dn[a][1];
        b(0, 2 * a) = dx;
        b(1, 2 * a + 1) = dy;
        b(2, 2 * a) = dy;
        b(2, 2 * a + 1) = dx;
      }
      k.noalias() += b.transpose() * d * b * det;  // Gauss weights are 1
    }
  return k;
}

// ---------------------------------------------------------------------------
// tfem's contact context.

void check(tfem_status status, const tfem_contact* ctx, const char* call) {
  if (status == TFEM_STATUS_OK) return;
  char message[2048];
  tfem_contact_last_error(ctx, message, sizeof message);
  std::fprintf(stderr, "%s failed (status %d): %s\n", call, static_cast<int>(status), message);
  std::exit(1);
}

// One side of the interface: the row of interface nodes of one block, with
// their coordinates and the equations of their unknowns (−1: constrained,
// index base 0), and its edges, each given with the block on its left
// (counter-clockwise boundary orientation: the lower block's top runs from
// right to left, the upper block's bottom from left to right).
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
  for (int i = 0; i + 1 < m.nx; ++i) {
    if (body == 1)
      edges.insert(edges.end(), {node(i + 1), node(i)});
    else
      edges.insert(edges.end(), {node(i), node(i + 1)});
  }
  const double young = body == 1 ? s.e1 : s.e2, poisson = body == 1 ? s.nu1 : s.nu2;
  int side = -1;
  check(tfem_contact_add_side(ctx, /*tag=*/body, body, young, poisson, TFEM_PLANE_MODE_STRAIN,
                              static_cast<int>(nodes.size()), nodes.data(), xy.data(),
                              equations.data(), static_cast<int>(edges.size() / 2), edges.data(),
                              &side),
        ctx, "tfem_contact_add_side");
  return side;
}

// ---------------------------------------------------------------------------
// The reference values (docs/reference/two_blocks_canonical.json), read with
// a few string searches: the case whose "C" is ours, then each quantity's
// "value".

const char* const kQuantities[4] = {"lc", "gap_edge", "v_top", "compliance"};

bool read_reference(const std::string& path, double c, double out[4]) {
  std::ifstream in(path);
  if (!in) return false;
  std::stringstream buffer;
  buffer << in.rdbuf();
  const std::string text = buffer.str();
  for (size_t at = text.find("\"canonical_"); at != std::string::npos;) {
    const size_t next = text.find("\"canonical_", at + 1);
    const std::string block = text.substr(at, next == std::string::npos ? std::string::npos : next - at);
    at = next;
    const size_t pc = block.find("\"C\":");
    if (pc == std::string::npos || std::fabs(std::strtod(block.c_str() + pc + 4, nullptr) - c) > 1e-12)
      continue;
    for (int q = 0; q < 4; ++q) {
      const size_t pq = block.find("\"" + std::string(kQuantities[q]) + "\":");
      const size_t pv = pq == std::string::npos ? pq : block.find("\"value\":", pq);
      if (pv == std::string::npos) return false;
      out[q] = std::strtod(block.c_str() + pv + 8, nullptr);
    }
    return true;
  }
  return false;
}

// ---------------------------------------------------------------------------
// One run: mesh, assembly, the active-set loop, the seed quantities.

struct Result {
  double h = 0;
  int unknowns = 0, iterations = 0, elements = 0, active = 0;
  double value[4] = {0, 0, 0, 0};  // lc, gap_edge, v_top, compliance
  double max_penetration = 0;
  int64_t matrix_nnz = 0, factor_nnz = 0;
  double t_assembly = 0, t_analysis = 0, t_factorization = 0, t_solve = 0;
  // Contact setup: tfem's (sides, pair, B, pattern) and the host's (where
  // each pattern entry lands in its matrix). Assembly: the Q4 elements and
  // the matrix over the union of both patterns.
  double t_contact_setup = 0, t_evaluate = 0, t_contact_add = 0, t_total = 0;
  int evaluations = 0;
};

Result run(const Scene& s, const char* dump) {
  const Clock::time_point start = Clock::now();
  Result r;
  r.h = s.h;
  const Mesh m = build_mesh(s);
  const Dofs d = number_dofs(s, m);
  r.unknowns = d.n;

  // The contact context: one side per block, one pair. Default options:
  // frictionless, E_c = the softer block's E, λ = the interface's length
  // (= L: the canonical λ = 1 m).
  Clock::time_point t = Clock::now();
  tfem_contact* ctx = tfem_contact_create(0);
  if (!ctx) {
    std::fprintf(stderr, "tfem_contact_create failed\n");
    std::exit(1);
  }
  const int lower_side = add_side(ctx, s, m, d, 1);
  const int upper_side = add_side(ctx, s, m, d, 2);
  check(tfem_contact_add_pair(ctx, lower_side, upper_side, nullptr), ctx, "tfem_contact_add_pair");
  int n_if = 0, n_el = 0;
  int64_t n_entries = 0;
  check(tfem_contact_sizes(ctx, &n_if, &n_el, &n_entries), ctx, "tfem_contact_sizes");
  std::vector<int64_t> rows(n_entries), cols(n_entries);
  check(tfem_contact_pattern(ctx, rows.data(), cols.data(), rows.size()), ctx,
        "tfem_contact_pattern");
  r.elements = n_el;
  r.t_contact_setup = seconds_since(t);

  // Bulk assembly into the lower triangle (SimplicialLLT reads only that),
  // over the union of the Q4 pattern and the contact pattern, so that the
  // matrix's structure, and its symbolic analysis, serve every iteration.
  t = Clock::now();
  std::vector<Eigen::Triplet<double>> triplets;
  triplets.reserve(36 * m.quads.size() + rows.size() / 2);
  const Eigen::Matrix3d dmat[2] = {plane_strain(s.e1, s.nu1), plane_strain(s.e2, s.nu2)};
  for (size_t q = 0; q < m.quads.size(); ++q) {
    const std::array<int, 4>& quad = m.quads[q];
    std::array<std::array<double, 2>, 4> xe;
    for (int a = 0; a < 4; ++a) xe[a] = m.x[quad[a]];
    const Matrix8 ke = q4_stiffness(xe, dmat[m.quad_body[q] - 1]);
    for (int a = 0; a < 8; ++a) {
      const int i = d.equation[2 * quad[a / 2] + a % 2];
      if (i < 0) continue;
      for (int b = 0; b < 8; ++b) {
        const int j = d.equation[2 * quad[b / 2] + b % 2];
        if (j >= 0 && i >= j) triplets.emplace_back(i, j, ke(a, b));
      }
    }
  }
  for (int64_t k = 0; k < n_entries; ++k)
    if (rows[k] >= cols[k])
      triplets.emplace_back(static_cast<int>(rows[k]), static_cast<int>(cols[k]), 0.0);
  Eigen::SparseMatrix<double> kmat(d.n, d.n);
  kmat.setFromTriplets(triplets.begin(), triplets.end());
  triplets = {};
  const std::vector<double> bulk(kmat.valuePtr(), kmat.valuePtr() + kmat.nonZeros());
  const Eigen::VectorXd f = pressure_load(s, m, d);
  r.t_assembly = seconds_since(t);
  r.matrix_nnz = kmat.nonZeros();

  // Where each contact entry lands in the matrix's values (−1: the upper
  // triangle, left out): the contributions are then added in O(entries).
  // Counted with the contact setup.
  t = Clock::now();
  std::vector<int64_t> slot(n_entries, -1);
  for (int64_t k = 0; k < n_entries; ++k) {
    if (rows[k] < cols[k]) continue;
    const int* inner = kmat.innerIndexPtr();
    const int lo = kmat.outerIndexPtr()[cols[k]], hi = kmat.outerIndexPtr()[cols[k] + 1];
    slot[k] = std::lower_bound(inner + lo, inner + hi, static_cast<int>(rows[k])) - inner;
  }
  r.t_contact_setup += seconds_since(t);

  t = Clock::now();
  Eigen::SimplicialLLT<Eigen::SparseMatrix<double>, Eigen::Lower> llt;
  llt.analyzePattern(kmat);
  r.t_analysis = seconds_since(t);

  // The active-set loop. The contact law is linear for a fixed active set:
  // the tangent values are K_c and the residual at u = 0 is −f0 (the load
  // of initial gaps: zero here, the blocks touch). Each iteration adds them
  // to K and f, solves, and asks tfem whether the set changed.
  std::vector<double> values(n_entries), r0(2 * n_if), zero(2 * n_if, 0.0), u_if(2 * n_if);
  Eigen::VectorXd u(d.n), rhs(d.n);
  for (;;) {
    ++r.iterations;
    t = Clock::now();
    check(tfem_contact_evaluate(ctx, zero.data(), zero.size(), values.data(), values.size(),
                                r0.data(), r0.size()),
          ctx, "tfem_contact_evaluate");
    r.t_evaluate += seconds_since(t);
    ++r.evaluations;

    t = Clock::now();
    std::copy(bulk.begin(), bulk.end(), kmat.valuePtr());
    for (int64_t k = 0; k < n_entries; ++k)
      if (slot[k] >= 0) kmat.valuePtr()[slot[k]] += values[k];
    rhs = f;
    for (double& v : r0) v = -v;
    check(tfem_contact_scatter_add(ctx, r0.data(), r0.size(), rhs.data(), rhs.size()), ctx,
          "tfem_contact_scatter_add");
    r.t_contact_add += seconds_since(t);

    t = Clock::now();
    llt.factorize(kmat);
    r.t_factorization += seconds_since(t);
    if (llt.info() != Eigen::Success) {
      std::fprintf(stderr, "factorisation failed at iteration %d (a block unrestrained?)\n",
                   r.iterations);
      std::exit(1);
    }
    t = Clock::now();
    u = llt.solve(rhs);
    r.t_solve += seconds_since(t);

    check(tfem_contact_gather(ctx, u.data(), u.size(), u_if.data(), u_if.size()), ctx,
          "tfem_contact_gather");
    int changed = 0;
    check(tfem_contact_update(ctx, u_if.data(), u_if.size(), &changed), ctx, "tfem_contact_update");
    if (!changed) break;
  }
  r.factor_nnz = llt.matrixL().nestedExpression().nonZeros();

  // ℓc: half the summed interface-edge length of the active elements of B.
  // An element's interface edge joins its two nodes on the same block.
  std::vector<int> tri(3 * n_el), active(n_el);
  check(tfem_contact_elements(ctx, tri.data(), tri.size()), ctx, "tfem_contact_elements");
  check(tfem_contact_get_active(ctx, active.data(), active.size()), ctx, "tfem_contact_get_active");
  double lc = 0.0;
  for (int k = 0; k < n_el; ++k) {
    if (!active[k]) continue;
    ++r.active;
    for (int a = 0; a < 3; ++a) {
      const int p = tri[3 * k + a], q = tri[3 * k + (a + 1) % 3];
      if (m.body[p] == m.body[q]) lc += std::hypot(m.x[q][0] - m.x[p][0], m.x[q][1] - m.x[p][1]);
    }
  }
  r.value[0] = 0.5 * lc;
  // The opening at the corner (0, 0), the top's displacement at (L/2, H2),
  // the work of the pressure f·u.
  const int top = static_cast<int>(m.ys2.size()) - 1, i_mid = (m.nx - 1) / 2;
  r.value[1] = d.u(u, m.upper(0, 0), 1) - d.u(u, m.lower(0, static_cast<int>(m.ys1.size()) - 1), 1);
  r.value[2] = d.u(u, m.upper(i_mid, top), 1);
  r.value[3] = f.dot(u);
  std::vector<double> gaps(n_if);
  check(tfem_contact_gaps(ctx, u_if.data(), u_if.size(), gaps.data(), gaps.size()), ctx,
        "tfem_contact_gaps");
  r.max_penetration = std::max(0.0, -*std::min_element(gaps.begin(), gaps.end()));
  tfem_contact_destroy(ctx);
  r.t_total = seconds_since(start);

  if (dump) {
    std::FILE* out = std::fopen(dump, "w");
    if (!out) {
      std::fprintf(stderr, "cannot write %s\n", dump);
      std::exit(1);
    }
    for (size_t v = 0; v < m.x.size(); ++v)
      std::fprintf(out, "%.17g %.17g %.17g %.17g\n", m.x[v][0], m.x[v][1],
                   d.u(u, static_cast<int>(v), 0), d.u(u, static_cast<int>(v), 1));
    std::fclose(out);
  }
  return r;
}

// Least-squares slope of log|e| against log h.
double fitted_rate(const std::vector<double>& h, const std::vector<double>& e) {
  const size_t n = h.size();
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  for (size_t k = 0; k < n; ++k) {
    const double x = std::log(h[k]), y = std::log(std::fabs(e[k]));
    sx += x, sy += y, sxx += x * x, sxy += x * y;
  }
  return (n * sxy - sx * sy) / (n * sxx - sx * sx);
}

void usage(const char* self) {
  std::fprintf(stderr,
               "usage: %s [--h H]... [--n N]... [--c C] [--reference FILE] [--json] "
               "[--dump FILE] [--min-rate R] [--lc-bound K] [--repeat K]\n",
               self);
  std::exit(2);
}

}  // namespace

int main(int argc, char** argv) {
  Scene scene;
  std::vector<double> sizes;
  std::string reference = HOST_Q4_REFERENCE;
  const char* dump = nullptr;
  bool json = false;
  double min_rate = -1.0, lc_bound = -1.0;
  int repeat = 1;
  for (int k = 1; k < argc; ++k) {
    const std::string a = argv[k];
    const bool has_value = k + 1 < argc;
    if (a == "--json") json = true;
    else if (a == "--h" && has_value) sizes.push_back(std::atof(argv[++k]));
    else if (a == "--n" && has_value) sizes.push_back(1.0 / std::atof(argv[++k]));
    else if (a == "--c" && has_value) scene.c = std::atof(argv[++k]);
    else if (a == "--reference" && has_value) reference = argv[++k];
    else if (a == "--dump" && has_value) dump = argv[++k];
    else if (a == "--min-rate" && has_value) min_rate = std::atof(argv[++k]);
    else if (a == "--lc-bound" && has_value) lc_bound = std::atof(argv[++k]);
    else if (a == "--repeat" && has_value) repeat = std::max(1, std::atoi(argv[++k]));
    else usage(argv[0]);
  }
  if (sizes.empty()) sizes.push_back(scene.h);
  for (double h : sizes)
    if (!(h > 0.0 && scene.c > 0.0 && 2.0 * scene.c <= scene.length)) usage(argv[0]);

  double ref[4];
  const bool have_reference = read_reference(reference, scene.c, ref);
  if (!have_reference)
    std::fprintf(stderr, "no reference values for C = %g in %s: errors not computed\n", scene.c,
                 reference.c_str());

  std::vector<double> hs, errors[4];
  for (double h : sizes) {
    scene.h = h;
    Result r = run(scene, dump);
    for (int k = 1; k < repeat; ++k) {
      const Result again = run(scene, nullptr);
      for (auto [mine, other] : {std::pair{&r.t_contact_setup, again.t_contact_setup},
                                 {&r.t_assembly, again.t_assembly},
                                 {&r.t_analysis, again.t_analysis},
                                 {&r.t_factorization, again.t_factorization},
                                 {&r.t_solve, again.t_solve},
                                 {&r.t_evaluate, again.t_evaluate},
                                 {&r.t_contact_add, again.t_contact_add},
                                 {&r.t_total, again.t_total}})
        *mine = std::min(*mine, other);
    }
    double rel[4] = {0, 0, 0, 0};
    for (int q = 0; q < 4 && have_reference; ++q) {
      rel[q] = (r.value[q] - ref[q]) / ref[q];
      errors[q].push_back(rel[q]);
    }
    hs.push_back(h);
    if (json) {
      std::printf("{\"element\":\"Q4\",\"h\":%.17g,\"c\":%.17g,\"unknowns\":%d,\"iterations\":%d,"
                  "\"contact_elements\":%d,\"active_contact_elements\":%d,",
                  h, scene.c, r.unknowns, r.iterations, r.elements, r.active);
      for (int q = 0; q < 4; ++q) {
        std::printf("\"%s\":%.17g,", kQuantities[q], r.value[q]);
        if (have_reference)
          std::printf("\"%s_reference\":%.17g,\"%s_relative_error\":%.17g,", kQuantities[q],
                      ref[q], kQuantities[q], rel[q]);
      }
      std::printf("\"max_penetration\":%.17g,\"matrix_nnz\":%lld,\"factor_nnz\":%lld,"
                  "\"time_contact_setup_s\":%.6g,\"time_assembly_s\":%.6g,\"time_analysis_s\":%.6g,"
                  "\"time_factorization_s\":%.6g,\"time_solve_s\":%.6g,"
                  "\"contact_evaluations\":%d,\"time_contact_evaluate_s\":%.6g,"
                  "\"time_contact_evaluate_per_call_s\":%.6g,\"time_contact_add_s\":%.6g,"
                  "\"time_total_s\":%.6g}\n",
                  r.max_penetration, static_cast<long long>(r.matrix_nnz),
                  static_cast<long long>(r.factor_nnz), r.t_contact_setup, r.t_assembly, r.t_analysis,
                  r.t_factorization, r.t_solve, r.evaluations, r.t_evaluate,
                  r.t_evaluate / r.evaluations, r.t_contact_add, r.t_total);
    } else {
      std::printf("h = %g, 2C/L = %g: %d unknowns, %d active-set iterations, %d of %d contact "
                  "elements active\n",
                  h, 2.0 * scene.c / scene.length, r.unknowns, r.iterations, r.active, r.elements);
      for (int q = 0; q < 4; ++q) {
        std::printf("  %-10s = %-14.7g", kQuantities[q], r.value[q]);
        if (have_reference) std::printf(" reference %-14.7g relative error %+.3e", ref[q], rel[q]);
        std::printf("\n");
      }
      std::printf("  max penetration %.3e m\n", r.max_penetration);
      std::printf("  time: assembly %.4f s, analysis %.4f s, factorisations %.4f s, solves %.4f s,\n"
                  "        contact setup %.4f s, contact evaluation %.2e s per call (%d calls),\n"
                  "        contact add %.4f s, total %.4f s\n",
                  r.t_assembly, r.t_analysis, r.t_factorization, r.t_solve,
                  r.t_contact_setup, r.t_evaluate / r.evaluations, r.evaluations, r.t_contact_add,
                  r.t_total);
    }
  }

  // The checks of --min-rate and --lc-bound (the tests use them). ℓc is a
  // sum of whole interface edges, so it moves in steps of the grid and its
  // error is not monotone in h: it is held to a bound in h instead of a rate.
  bool ok = true;
  if ((min_rate >= 0.0 || lc_bound >= 0.0) && !have_reference) {
    std::fprintf(stderr, "--min-rate and --lc-bound need the reference values\n");
    return 1;
  }
  if (lc_bound >= 0.0)
    for (size_t k = 0; k < hs.size(); ++k)
      if (std::fabs(errors[0][k] * ref[0]) > lc_bound * hs[k]) {
        std::fprintf(stderr, "h = %g: |lc - reference| = %.3g exceeds %g h\n", hs[k],
                     std::fabs(errors[0][k] * ref[0]), lc_bound);
        ok = false;
      }
  if (hs.size() >= 2 && have_reference) {
    if (!json) std::printf("fitted log-log rates of the errors over %zu sizes:", hs.size());
    else std::printf("{\"rates\":{");
    for (int q = 0; q < 4; ++q) {
      const double rate = fitted_rate(hs, errors[q]);
      if (q > 0 && min_rate >= 0.0 && rate < min_rate) {
        std::fprintf(stderr, "the fitted rate of %s, %.3f, is below %g\n", kQuantities[q], rate,
                     min_rate);
        ok = false;
      }
      if (json) std::printf("%s\"%s\":%.6g", q ? "," : "", kQuantities[q], rate);
      else std::printf(" %s %.3f", kQuantities[q], rate);
    }
    std::printf(json ? "}}\n" : "\n");
  } else if (min_rate >= 0.0) {
    std::fprintf(stderr, "--min-rate needs at least two sizes\n");
    return 1;
  }
  return ok ? 0 : 1;
}
