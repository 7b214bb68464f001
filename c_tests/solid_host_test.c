/* The 3D contact context for host codes through the C ABI
 * (tfem_solid_contact_*): a host with its own tetrahedra, its own
 * stiffness, its own dense solver and its own active-set loop takes only
 * the contact from tfem, and lands on the exact solution of the contact
 * patch test; then the refusals.
 *
 * Two unit cubes, body 1 on z in [-1, 0] and body 2 on z in [0, 1], each
 * meshed by N x N x N cells of Kuhn's six tetrahedra (built here), plain
 * linear tetrahedra of isotropic elasticity (E = 1, nu = 0.25) assembled
 * by the host into a dense matrix. Rollers on x = 0 (u_x = 0) and y = 0
 * (u_y = 0) for both cubes, the lower cube's bottom fixed in z, a pressure
 * p on the upper cube's top: the upper cube is held only by the contact.
 * The interface sides (side a the lower top, side b the upper bottom,
 * triangles counter-clockwise seen from outside each body) are given to
 * tfem in the host's numbering: nodes, equations and sides in index base
 * 1 (as a Fortran host), and once more in base 0. The exact solution is
 * uniaxial stress: sigma_zz = -p in every tetrahedron (from the host's own
 * displacements), every other component 0; every tetrahedron of B active,
 * contact area 1. */

#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include "tfem.h"

static int passed = 0, failed = 0;

#define CHECK(cond)                                          \
  do {                                                       \
    if (cond) {                                              \
      ++passed;                                              \
    } else {                                                 \
      ++failed;                                              \
      printf("FAIL %s:%d: %s\n", __FILE__, __LINE__, #cond); \
    }                                                        \
  } while (0)

#define OK(call) CHECK((call) == TFEM_STATUS_OK)

/* The call must fail with `expected` and the context's message (the
 * thread's when `c` is NULL) contain `needle`. */
static void expect_error(tfem_solid_contact *c, tfem_status got, tfem_status expected,
                         const char *needle, int line) {
  char msg[512] = "";
  if (c != NULL)
    tfem_solid_contact_last_error(c, msg, sizeof msg);
  else
    tfem_last_error(NULL, msg, sizeof msg);
  if (got == expected && strstr(msg, needle) != NULL) {
    ++passed;
  } else {
    ++failed;
    printf("FAIL line %d: status %d (expected %d), message \"%s\" (expected \"%s\")\n", line,
           (int)got, (int)expected, msg, needle);
  }
}
#define EXPECT_ERROR(c, call, status, needle) expect_error(c, call, status, needle, __LINE__)

enum { N = 2, NP = N + 1, NODES_PER = NP * NP * NP, N_NODES = 2 * NODES_PER };
enum { TETS_PER = 6 * N * N * N, N_TETS = 2 * TETS_PER };
enum { N_FACES = 2 * 6 * 2 * N * N, SIDE_NODES = NP * NP, SIDE_TRIS = 2 * N * N };
enum { N_CONTACT = 3 * SIDE_TRIS, MAX_EQ = 3 * N_NODES };
enum { TAG_LOWER_TOP = 6, TAG_UPPER_BOTTOM = 15, TAG_UPPER_TOP = 16 };
static const double P = 0.1, E = 1.0, NU = 0.25, TOL = 1e-9;

static double xyz[3 * N_NODES];
static int tets[4 * N_TETS], faces[3 * N_FACES], tags[N_FACES];
static int n_tets = 0, n_faces = 0;

/* Node (i, j, k) of the cube starting at node `first`. */
static int id(int first, int i, int j, int k) { return first + i + NP * (j + NP * k); }

/* The grid coordinate `axis` of node `v` of the cube starting at `first`. */
static int grid(int first, int v, int axis) {
  int r = v - first;
  int g[3] = {r % NP, (r / NP) % NP, r / (NP * NP)};
  return g[axis];
}

/* A unit cube from z0 to z0 + 1, its sides tagged tag0 + 1 ... tag0 + 6
 * (x = min, x = max, y = min, y = max, z = min, z = max), from node
 * `first`: Kuhn's six tetrahedra per cell (the odd orders numbered
 * backwards to keep J > 0), and every face of them on a side. */
static void cube(int first, double z0, int tag0) {
  static const int orders[6][3] = {{0, 1, 2}, {1, 2, 0}, {2, 0, 1},
                                   {0, 2, 1}, {2, 1, 0}, {1, 0, 2}};
  for (int k = 0; k < NP; ++k)
    for (int j = 0; j < NP; ++j)
      for (int i = 0; i < NP; ++i) {
        int v = id(first, i, j, k);
        xyz[3 * v] = (double)i / N;
        xyz[3 * v + 1] = (double)j / N;
        xyz[3 * v + 2] = z0 + (double)k / N;
      }
  int start = n_tets;
  for (int k = 0; k < N; ++k)
    for (int j = 0; j < N; ++j)
      for (int i = 0; i < N; ++i)
        for (int o = 0; o < 6; ++o) {
          int p[3] = {0, 0, 0}, *t = &tets[4 * n_tets];
          t[0] = id(first, i, j, k);
          for (int s = 0; s < 3; ++s) {
            p[orders[o][s]] = 1;
            t[s + 1] = id(first, i + p[0], j + p[1], k + p[2]);
          }
          if (o >= 3) {
            int swap = t[2];
            t[2] = t[3];
            t[3] = swap;
          }
          ++n_tets;
        }
  for (int e = start; e < n_tets; ++e)
    for (int skip = 0; skip < 4; ++skip) {
      int f[3], n = 0;
      for (int q = 0; q < 4; ++q)
        if (q != skip) f[n++] = tets[4 * e + q];
      for (int axis = 0; axis < 3; ++axis)
        for (int end = 0; end < 2; ++end) {
          int at = end ? N : 0, on = 1;
          for (int q = 0; q < 3; ++q) on = on && grid(first, f[q], axis) == at;
          if (on) {
            memcpy(&faces[3 * n_faces], f, sizeof f);
            tags[n_faces++] = tag0 + 1 + 2 * axis + end;
          }
        }
    }
}

/* Face f's normal (not normalised: twice its area long). */
static void face_normal(const int *f, double n[3]) {
  const double *a = &xyz[3 * f[0]], *b = &xyz[3 * f[1]], *c = &xyz[3 * f[2]];
  double u[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]};
  double w[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
  n[0] = u[1] * w[2] - u[2] * w[1];
  n[1] = u[2] * w[0] - u[0] * w[2];
  n[2] = u[0] * w[1] - u[1] * w[0];
}

/* ---- The host's own element: a plain linear tetrahedron. */

/* Isotropic elasticity in Voigt order xx yy zz yz xz xy (engineering
 * shears). */
static void elasticity(double d[6][6]) {
  double lambda = E * NU / ((1 + NU) * (1 - 2 * NU)), mu = E / (2 * (1 + NU));
  memset(d, 0, 36 * sizeof(double));
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) d[i][j] = lambda;
    d[i][i] += 2 * mu;
    d[i + 3][i + 3] = mu;
  }
}

/* Tetrahedron e's strain-displacement matrix and volume. */
static void strain_matrix(int e, double b[6][12], double *volume) {
  const int *t = &tets[4 * e];
  double m[3][3]; /* m[j][a] = x_{a+1, j} - x_{0, j}: dx/dxi */
  for (int a = 0; a < 3; ++a)
    for (int j = 0; j < 3; ++j) m[j][a] = xyz[3 * t[a + 1] + j] - xyz[3 * t[0] + j];
  double det = m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) -
               m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
               m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
  /* g = m^-1: g[a][j] = d xi_a / d x_j. */
  double g[3][3];
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      int i1 = (j + 1) % 3, i2 = (j + 2) % 3, j1 = (i + 1) % 3, j2 = (i + 2) % 3;
      g[i][j] = (m[i1][j1] * m[i2][j2] - m[i1][j2] * m[i2][j1]) / det;
    }
  double grad[4][3];
  for (int j = 0; j < 3; ++j) {
    grad[0][j] = -(g[0][j] + g[1][j] + g[2][j]);
    for (int a = 0; a < 3; ++a) grad[a + 1][j] = g[a][j];
  }
  memset(b, 0, 72 * sizeof(double));
  for (int a = 0; a < 4; ++a) {
    double x = grad[a][0], y = grad[a][1], z = grad[a][2];
    b[0][3 * a] = x;
    b[1][3 * a + 1] = y;
    b[2][3 * a + 2] = z;
    b[3][3 * a + 1] = z;
    b[3][3 * a + 2] = y;
    b[4][3 * a] = z;
    b[4][3 * a + 2] = x;
    b[5][3 * a] = y;
    b[5][3 * a + 1] = x;
  }
  *volume = fabs(det) / 6.0;
}

/* ---- The host's numbering, matrix, load and solver. */

static int equation[N_NODES][3]; /* 0-based, -1: fixed */
static int n_eq = 0;
static double k_body[MAX_EQ * MAX_EQ], f_body[MAX_EQ];

static void number_equations(void) {
  for (int v = 0; v < N_NODES; ++v) {
    const double *x = &xyz[3 * v];
    int fixed[3] = {x[0] == 0.0, x[1] == 0.0, x[2] == -1.0};
    for (int c = 0; c < 3; ++c) equation[v][c] = fixed[c] ? -1 : n_eq++;
  }
}

static void assemble(void) {
  double d[6][6], b[6][12], db[6][12], volume;
  elasticity(d);
  for (int e = 0; e < N_TETS; ++e) {
    strain_matrix(e, b, &volume);
    for (int i = 0; i < 6; ++i)
      for (int j = 0; j < 12; ++j) {
        db[i][j] = 0;
        for (int k = 0; k < 6; ++k) db[i][j] += d[i][k] * b[k][j];
      }
    for (int r = 0; r < 12; ++r) {
      int er = equation[tets[4 * e + r / 3]][r % 3];
      if (er < 0) continue;
      for (int c = 0; c < 12; ++c) {
        int ec = equation[tets[4 * e + c / 3]][c % 3];
        if (ec < 0) continue;
        double s = 0;
        for (int k = 0; k < 6; ++k) s += b[k][r] * db[k][c];
        k_body[er * n_eq + ec] += volume * s;
      }
    }
  }
  /* The pressure on the upper top: p A / 3 down at each corner. */
  for (int f = 0; f < N_FACES; ++f) {
    if (tags[f] != TAG_UPPER_TOP) continue;
    double n[3];
    face_normal(&faces[3 * f], n);
    double area = 0.5 * sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    for (int q = 0; q < 3; ++q) {
      int e = equation[faces[3 * f + q]][2];
      if (e >= 0) f_body[e] -= P * area / 3.0;
    }
  }
}

/* Solves a x = rhs (a symmetric positive definite, n x n, overwritten by
 * its Cholesky factor); 0 if a pivot is not positive. */
static int cholesky_solve(double *a, int n, double *x) {
  for (int j = 0; j < n; ++j) {
    double s = a[j * n + j];
    for (int k = 0; k < j; ++k) s -= a[j * n + k] * a[j * n + k];
    if (!(s > 0)) return 0;
    a[j * n + j] = sqrt(s);
    for (int i = j + 1; i < n; ++i) {
      double t = a[i * n + j];
      for (int k = 0; k < j; ++k) t -= a[i * n + k] * a[j * n + k];
      a[i * n + j] = t / a[j * n + j];
    }
  }
  for (int i = 0; i < n; ++i) {
    for (int k = 0; k < i; ++k) x[i] -= a[i * n + k] * x[k];
    x[i] /= a[i * n + i];
  }
  for (int i = n - 1; i >= 0; --i) {
    for (int k = i + 1; k < n; ++k) x[i] -= a[k * n + i] * x[k];
    x[i] /= a[i * n + i];
  }
  return 1;
}

/* ---- The sides as the host gives them. */

typedef struct {
  int nodes[SIDE_NODES];
  double xyz[3 * SIDE_NODES];
  int64_t equations[3 * SIDE_NODES];
  int triangles[3 * SIDE_TRIS];
  int n_nodes, n_triangles;
} side_data;

/* The faces tagged `tag`, turned counter-clockwise seen from outside
 * (outward normal along `out_z`), in host node numbers of index base
 * `base`, with their nodes' coordinates and equations (base - 1: none). */
static void side_of(int tag, double out_z, int base, side_data *s) {
  s->n_nodes = 0;
  s->n_triangles = 0;
  for (int f = 0; f < N_FACES; ++f) {
    if (tags[f] != tag) continue;
    int t[3] = {faces[3 * f], faces[3 * f + 1], faces[3 * f + 2]};
    double n[3];
    face_normal(t, n);
    if (n[2] * out_z < 0) {
      int swap = t[1];
      t[1] = t[2];
      t[2] = swap;
    }
    for (int q = 0; q < 3; ++q) {
      s->triangles[3 * s->n_triangles + q] = t[q] + base;
      int known = 0;
      for (int m = 0; m < s->n_nodes; ++m) known = known || s->nodes[m] == t[q] + base;
      if (known) continue;
      int m = s->n_nodes++;
      s->nodes[m] = t[q] + base;
      for (int c = 0; c < 3; ++c) {
        s->xyz[3 * m + c] = xyz[3 * t[q] + c];
        s->equations[3 * m + c] = equation[t[q]][c] < 0 ? base - 1 : equation[t[q]][c] + base;
      }
    }
    ++s->n_triangles;
  }
}

static side_data lower, upper;

/* A context of index base `base` with the two sides and their pair. */
static tfem_solid_contact *context(int base) {
  tfem_solid_contact *c = tfem_solid_contact_create(base, NULL);
  CHECK(c != NULL);
  side_of(TAG_LOWER_TOP, 1.0, base, &lower);
  side_of(TAG_UPPER_BOTTOM, -1.0, base, &upper);
  CHECK(lower.n_nodes == SIDE_NODES && lower.n_triangles == SIDE_TRIS);
  CHECK(upper.n_nodes == SIDE_NODES && upper.n_triangles == SIDE_TRIS);
  int a = -7, b = -7, pair = -7;
  OK(tfem_solid_contact_add_side(c, TAG_LOWER_TOP, 1, E, lower.n_nodes, lower.nodes, lower.xyz,
                                 lower.equations, lower.n_triangles, lower.triangles, &a));
  OK(tfem_solid_contact_add_side(c, TAG_UPPER_BOTTOM, 2, E, upper.n_nodes, upper.nodes,
                                 upper.xyz, upper.equations, upper.n_triangles, upper.triangles,
                                 &b));
  CHECK(a == base && b == base + 1); /* side numbers in the index base */
  OK(tfem_solid_contact_add_pair(c, a, b, &pair));
  CHECK(pair == base);
  return c;
}

static double kt[MAX_EQ * MAX_EQ], u_host[MAX_EQ];
enum { MAX_ENTRIES = N_CONTACT * 144 };
static int64_t rows[MAX_ENTRIES], cols[MAX_ENTRIES];
static double values[MAX_ENTRIES];

/* The host's loop: its matrix plus B's values, its load less B's residual
 * at u = 0 (the initial gaps' load), its solve, and tfem's verdict, until
 * the set stands. Returns the iterations, 0 on failure. */
static int host_loop(tfem_solid_contact *c, int base) {
  int nn = -1, nt = -1;
  int64_t ne = -1;
  OK(tfem_solid_contact_sizes(c, &nn, &nt, &ne));
  CHECK(nn == 2 * SIDE_NODES && nt == N_CONTACT && ne > 0 && ne <= MAX_ENTRIES);
  if (ne <= 0 || ne > MAX_ENTRIES) return 0;
  size_t entries = (size_t)ne, n_local = 3 * (size_t)nn;
  OK(tfem_solid_contact_pattern(c, rows, cols, entries));
  int in_range = 1;
  for (size_t k = 0; k < entries; ++k)
    in_range = in_range && rows[k] >= base && rows[k] < n_eq + base && cols[k] >= base &&
               cols[k] < n_eq + base;
  CHECK(in_range);
  static double zero[3 * 2 * SIDE_NODES], r0[3 * 2 * SIDE_NODES], local[3 * 2 * SIDE_NODES];
  for (int it = 1; it <= 20; ++it) {
    OK(tfem_solid_contact_evaluate(c, zero, n_local, values, entries, r0, n_local));
    memcpy(kt, k_body, sizeof(double) * (size_t)(n_eq * n_eq));
    for (size_t k = 0; k < entries; ++k)
      kt[(rows[k] - base) * n_eq + (cols[k] - base)] += values[k];
    for (size_t k = 0; k < n_local; ++k) r0[k] = -r0[k];
    memcpy(u_host, f_body, sizeof(double) * (size_t)n_eq);
    OK(tfem_solid_contact_scatter_add(c, r0, n_local, u_host, (size_t)n_eq));
    if (!cholesky_solve(kt, n_eq, u_host)) {
      printf("FAIL: the host's matrix is not positive definite (iteration %d)\n", it);
      ++failed;
      return 0;
    }
    OK(tfem_solid_contact_gather(c, u_host, (size_t)n_eq, local, n_local));
    int changed = -1, on = -1, off = -1;
    OK(tfem_solid_contact_update(c, local, n_local, &changed, &on, &off));
    CHECK(changed == (on + off > 0));
    if (changed == 0) return it;
  }
  printf("FAIL: the host's loop did not settle\n");
  ++failed;
  return 0;
}

/* Every displacement of the host's solution (fixed DOFs 0). */
static void host_displacements(double *u) {
  for (int v = 0; v < N_NODES; ++v)
    for (int c = 0; c < 3; ++c) u[3 * v + c] = equation[v][c] < 0 ? 0.0 : u_host[equation[v][c]];
}

/* The host's stresses: sigma_zz = -p and every other component 0 in every
 * tetrahedron, from its own displacements. */
static void check_stresses(const double *u) {
  double d[6][6], b[6][12], volume, worst = 0;
  elasticity(d);
  for (int e = 0; e < N_TETS; ++e) {
    strain_matrix(e, b, &volume);
    double strain[6] = {0, 0, 0, 0, 0, 0};
    for (int i = 0; i < 6; ++i)
      for (int j = 0; j < 12; ++j) strain[i] += b[i][j] * u[3 * tets[4 * e + j / 3] + j % 3];
    for (int i = 0; i < 6; ++i) {
      double s = 0;
      for (int k = 0; k < 6; ++k) s += d[i][k] * strain[k];
      worst = fmax(worst, fabs(s - (i == 2 ? -P : 0.0)));
    }
  }
  printf("worst stress error %.2e (p = %g)\n", worst, P);
  CHECK(worst <= TOL * P);
}

static double u_base1[3 * N_NODES];

/* The patch test through a context of index base `base`. */
static void patch_test(int base) {
  tfem_solid_contact *c = context(base);
  OK(tfem_solid_contact_setup(c));
  OK(tfem_solid_contact_setup(c)); /* a second call does nothing */
  int iterations = host_loop(c, base);
  CHECK(iterations >= 1);
  printf("index base %d: the host's loop settled in %d iteration(s)\n", base, iterations);
  static double u[3 * N_NODES];
  host_displacements(u);
  check_stresses(u);
  if (base == 1) memcpy(u_base1, u, sizeof u);
  else CHECK(memcmp(u, u_base1, sizeof u) == 0); /* the base changes nothing */

  int active[N_CONTACT];
  OK(tfem_solid_contact_get_active(c, active, N_CONTACT));
  int all = 1;
  for (int k = 0; k < N_CONTACT; ++k) all = all && active[k] == 1;
  CHECK(all);
  double area = -1;
  OK(tfem_solid_contact_area(c, &area));
  CHECK(fabs(area - 1.0) < 1e-12);

  /* The tetrahedra of B join the two sides' nodes, in the host's numbers. */
  int ct[4 * N_CONTACT], nodes[2 * SIDE_NODES];
  OK(tfem_solid_contact_tetrahedra(c, ct, 4 * N_CONTACT));
  OK(tfem_solid_contact_nodes(c, nodes, 2 * SIDE_NODES));
  int on_interface = 1;
  for (int k = 0; k < 4 * N_CONTACT; ++k) {
    int v = ct[k] - base;
    on_interface = on_interface && v >= 0 && v < N_NODES && xyz[3 * v + 2] == 0.0;
  }
  CHECK(on_interface);
  CHECK(nodes[0] == lower.nodes[0] && nodes[SIDE_NODES] == upper.nodes[0]);

  /* The gaps: every tetrahedron pressed by the upper bottom's drop below
   * the lower top (uniform: the penalty's penetration). */
  static double local[3 * 2 * SIDE_NODES], gaps[N_CONTACT];
  OK(tfem_solid_contact_gather(c, u_host, (size_t)n_eq, local, 6 * SIDE_NODES));
  OK(tfem_solid_contact_gaps(c, local, 6 * SIDE_NODES, gaps, N_CONTACT));
  double drop = u[3 * NODES_PER + 2] - u[3 * (NODES_PER - 1) + 2], wg = 0;
  for (int k = 0; k < N_CONTACT; ++k) wg = fmax(wg, fabs(gaps[k] - drop));
  CHECK(drop < 0 && wg <= TOL * P / E);

  /* The element blocks assemble to the pattern's values. */
  static int64_t eq[12 * N_CONTACT];
  static double blocks[144 * N_CONTACT];
  OK(tfem_solid_contact_element_equations(c, eq, 12 * N_CONTACT));
  OK(tfem_solid_contact_element_blocks(c, blocks, 144 * N_CONTACT));
  int64_t ne = 0;
  OK(tfem_solid_contact_sizes(c, NULL, NULL, &ne));
  static double zero[6 * SIDE_NODES];
  OK(tfem_solid_contact_evaluate(c, zero, 6 * SIDE_NODES, values, (size_t)ne, NULL, 0));
  memset(kt, 0, sizeof kt);
  for (int64_t k = 0; k < ne; ++k) kt[(rows[k] - base) * n_eq + (cols[k] - base)] += values[k];
  static double kb[MAX_EQ * MAX_EQ];
  memset(kb, 0, sizeof kb);
  int64_t counted = 0;
  for (int t = 0; t < N_CONTACT; ++t)
    for (int r = 0; r < 12; ++r)
      for (int s = 0; s < 12; ++s) {
        int64_t er = eq[12 * t + r], es = eq[12 * t + s];
        if (er < base || es < base) continue;
        kb[(er - base) * n_eq + (es - base)] += blocks[144 * t + 12 * r + s];
        ++counted;
      }
  CHECK(counted == ne);
  double wk = 0, scale = 0;
  for (int k = 0; k < n_eq * n_eq; ++k) {
    wk = fmax(wk, fabs(kt[k] - kb[k]));
    scale = fmax(scale, fabs(kt[k]));
  }
  CHECK(scale > 0 && wk <= 1e-14 * scale);
  tfem_solid_contact_destroy(c);
}

/* Every value of `a` (n doubles) is still `v`. */
static int all_equal(const double *a, size_t n, double v) {
  for (size_t k = 0; k < n; ++k)
    if (a[k] != v) return 0;
  return 1;
}

/* ---- The refusals: each with its status and message, writing nothing
 * and leaving the context usable. */
static void refusals(void) {
  enum { NL = 6 * SIDE_NODES };
  static double u[NL], out[MAX_ENTRIES], host[MAX_EQ];
  int sentinel = -7;

  /* Creation: a base other than 0 or 1, a law 3D contact has not. */
  CHECK(tfem_solid_contact_create(2, NULL) == NULL);
  EXPECT_ERROR(NULL, TFEM_STATUS_INVALID_ARGUMENT, TFEM_STATUS_INVALID_ARGUMENT,
               "index_base = 2");
  CHECK(tfem_solid_contact_create(-1, NULL) == NULL);
  EXPECT_ERROR(NULL, TFEM_STATUS_INVALID_ARGUMENT, TFEM_STATUS_INVALID_ARGUMENT,
               "index_base = -1");
  tfem_contact_options o;
  OK(tfem_contact_options_default(&o));
  o.law = 1;
  CHECK(tfem_solid_contact_create(1, &o) == NULL);
  EXPECT_ERROR(NULL, TFEM_STATUS_INVALID_ARGUMENT, TFEM_STATUS_INVALID_ARGUMENT,
               "frictionless");
  o.law = 0;
  o.max_iterations = 0;
  CHECK(tfem_solid_contact_create(1, &o) == NULL);
  EXPECT_ERROR(NULL, TFEM_STATUS_INVALID_ARGUMENT, TFEM_STATUS_INVALID_ARGUMENT,
               "max_iterations");

  /* Declaring: no pair yet, a NULL array, a node not in the side, a node
   * below the base, a side out of range or below the base, one body. */
  tfem_solid_contact *c = tfem_solid_contact_create(1, NULL);
  side_of(TAG_LOWER_TOP, 1.0, 1, &lower);
  side_of(TAG_UPPER_BOTTOM, -1.0, 1, &upper);
  EXPECT_ERROR(c, tfem_solid_contact_setup(c), TFEM_STATUS_INVALID_STATE, "no contact pair");
  EXPECT_ERROR(c, tfem_solid_contact_sizes(c, &sentinel, NULL, NULL), TFEM_STATUS_INVALID_STATE,
               "no contact pair");
  CHECK(sentinel == -7);
  CHECK(tfem_solid_contact_last_error_length(c) > 1);
  EXPECT_ERROR(c,
               tfem_solid_contact_add_side(c, TAG_LOWER_TOP, 1, E, lower.n_nodes, NULL, lower.xyz,
                                           lower.equations, lower.n_triangles, lower.triangles,
                                           &sentinel),
               TFEM_STATUS_NULL_POINTER, "`nodes`");
  EXPECT_ERROR(c,
               tfem_solid_contact_add_side(c, TAG_LOWER_TOP, 1, E, lower.n_nodes, lower.nodes,
                                           lower.xyz, lower.equations, -1, lower.triangles,
                                           &sentinel),
               TFEM_STATUS_INVALID_ARGUMENT, "n_triangles = -1");
  side_data bad = lower;
  bad.triangles[4] = 999;
  EXPECT_ERROR(c,
               tfem_solid_contact_add_side(c, TAG_LOWER_TOP, 1, E, bad.n_nodes, bad.nodes, bad.xyz,
                                           bad.equations, bad.n_triangles, bad.triangles,
                                           &sentinel),
               TFEM_STATUS_INVALID_ARGUMENT,
               "side 1 (tag 6): triangle 2 uses node 999, which the side does not give");
  bad = lower;
  bad.nodes[0] = 0;
  EXPECT_ERROR(c,
               tfem_solid_contact_add_side(c, TAG_LOWER_TOP, 1, E, bad.n_nodes, bad.nodes, bad.xyz,
                                           bad.equations, bad.n_triangles, bad.triangles,
                                           &sentinel),
               TFEM_STATUS_INVALID_ARGUMENT, "below the index base 1");
  bad = lower;
  bad.xyz[5] = NAN;
  EXPECT_ERROR(c,
               tfem_solid_contact_add_side(c, TAG_LOWER_TOP, 1, E, bad.n_nodes, bad.nodes, bad.xyz,
                                           bad.equations, bad.n_triangles, bad.triangles,
                                           &sentinel),
               TFEM_STATUS_INVALID_ARGUMENT, "non-finite coordinate");
  EXPECT_ERROR(c,
               tfem_solid_contact_add_side(c, TAG_LOWER_TOP, 1, -1.0, lower.n_nodes, lower.nodes,
                                           lower.xyz, lower.equations, lower.n_triangles,
                                           lower.triangles, &sentinel),
               TFEM_STATUS_INVALID_ARGUMENT, "Young's modulus");
  CHECK(sentinel == -7);
  int nn = -7;
  EXPECT_ERROR(c, tfem_solid_contact_sizes(c, &nn, NULL, NULL), TFEM_STATUS_INVALID_STATE,
               "no contact pair");
  CHECK(nn == -7);
  int a = 0, b = 0;
  OK(tfem_solid_contact_add_side(c, TAG_LOWER_TOP, 1, E, lower.n_nodes, lower.nodes, lower.xyz,
                                 lower.equations, lower.n_triangles, lower.triangles, &a));
  CHECK(tfem_solid_contact_last_error_length(c) == 1);
  EXPECT_ERROR(c, tfem_solid_contact_add_pair(c, a, 3, &sentinel), TFEM_STATUS_INVALID_ARGUMENT,
               "side 3 does not exist (1 sides)");
  EXPECT_ERROR(c, tfem_solid_contact_add_pair(c, 0, a, &sentinel), TFEM_STATUS_INVALID_ARGUMENT,
               "side_a = 0 is below the index base 1");
  EXPECT_ERROR(c, tfem_solid_contact_add_pair(c, a, a, &sentinel), TFEM_STATUS_INVALID_ARGUMENT,
               "self-contact");
  CHECK(sentinel == -7);
  OK(tfem_solid_contact_add_side(c, TAG_UPPER_BOTTOM, 2, E, upper.n_nodes, upper.nodes,
                                 upper.xyz, upper.equations, upper.n_triangles, upper.triangles,
                                 &b));
  CHECK(a == 1 && b == 2);
  OK(tfem_solid_contact_add_pair(c, a, b, NULL));
  OK(tfem_solid_contact_setup(c));
  EXPECT_ERROR(c,
               tfem_solid_contact_add_side(c, 99, 3, E, lower.n_nodes, lower.nodes, lower.xyz,
                                           lower.equations, lower.n_triangles, lower.triangles,
                                           NULL),
               TFEM_STATUS_INVALID_STATE, "the pattern is built");
  EXPECT_ERROR(c, tfem_solid_contact_add_pair(c, a, b, NULL), TFEM_STATUS_INVALID_STATE,
               "the pattern is built");

  /* Evaluating: a NULL u, a wrong length, a NaN, a buffer too short. */
  int64_t ne = 0;
  OK(tfem_solid_contact_sizes(c, NULL, NULL, &ne));
  for (size_t k = 0; k < MAX_ENTRIES; ++k) out[k] = 42.0;
  memset(u, 0, sizeof u);
  EXPECT_ERROR(c, tfem_solid_contact_evaluate(c, NULL, NL, out, (size_t)ne, NULL, 0),
               TFEM_STATUS_NULL_POINTER, "`u`");
  EXPECT_ERROR(c, tfem_solid_contact_evaluate(c, u, NL - 1, out, (size_t)ne, NULL, 0),
               TFEM_STATUS_INVALID_ARGUMENT, "`u` holds 53 values");
  EXPECT_ERROR(c, tfem_solid_contact_evaluate(c, u, NL, out, (size_t)ne - 1, NULL, 0),
               TFEM_STATUS_BUFFER_TOO_SMALL, "`values` holds");
  static double residual[NL];
  for (int k = 0; k < NL; ++k) residual[k] = 42.0;
  EXPECT_ERROR(c, tfem_solid_contact_evaluate(c, u, NL, out, (size_t)ne, residual, NL - 1),
               TFEM_STATUS_BUFFER_TOO_SMALL, "`residual` holds");
  CHECK(all_equal(residual, NL, 42.0));
  u[4] = NAN;
  EXPECT_ERROR(c, tfem_solid_contact_evaluate(c, u, NL, out, (size_t)ne, NULL, 0),
               TFEM_STATUS_INVALID_ARGUMENT, "not finite");
  CHECK(all_equal(out, MAX_ENTRIES, 42.0));

  /* The active set: a NaN in u, a flag other than 0 or 1, a count that is
   * not B's; the flags stay. */
  int changed = -7, flags[N_CONTACT];
  EXPECT_ERROR(c, tfem_solid_contact_update(c, u, NL, &changed, NULL, NULL),
               TFEM_STATUS_INVALID_ARGUMENT, "not finite");
  CHECK(changed == -7);
  for (int k = 0; k < N_CONTACT; ++k) flags[k] = 2;
  EXPECT_ERROR(c, tfem_solid_contact_set_active(c, flags, N_CONTACT),
               TFEM_STATUS_INVALID_ARGUMENT, "active[0] = 2 must be 0 or 1");
  for (int k = 0; k < N_CONTACT; ++k) flags[k] = 0;
  EXPECT_ERROR(c, tfem_solid_contact_set_active(c, flags, N_CONTACT - 1),
               TFEM_STATUS_INVALID_ARGUMENT, "active flags for");
  for (int k = 0; k < N_CONTACT; ++k) flags[k] = -7;
  EXPECT_ERROR(c, tfem_solid_contact_get_active(c, flags, N_CONTACT - 1),
               TFEM_STATUS_BUFFER_TOO_SMALL, "are needed");
  CHECK(flags[0] == -7);
  OK(tfem_solid_contact_get_active(c, flags, N_CONTACT));
  int all = 1;
  for (int k = 0; k < N_CONTACT; ++k) all = all && flags[k] == 1;
  CHECK(all); /* touching at rest: on from the start, and still */

  /* Host vectors: an equation beyond the host's vector, a NaN there, a
   * NaN residual, an Inf in the host's vector; nothing written. */
  u[4] = 0.0;
  for (int k = 0; k < NL; ++k) out[k] = 42.0;
  for (int k = 0; k < MAX_EQ; ++k) host[k] = 1.0;
  EXPECT_ERROR(c, tfem_solid_contact_gather(c, host, 3, out, NL),
               TFEM_STATUS_INVALID_ARGUMENT, "beyond the host's vector");
  int e0 = (int)lower.equations[3 * (lower.n_nodes - 1) + 2] - 1; /* a free z */
  host[e0] = NAN;
  EXPECT_ERROR(c, tfem_solid_contact_gather(c, host, (size_t)n_eq, out, NL),
               TFEM_STATUS_INVALID_ARGUMENT, "is not finite");
  EXPECT_ERROR(c, tfem_solid_contact_gather(c, host, (size_t)n_eq, out, NL - 1),
               TFEM_STATUS_BUFFER_TOO_SMALL, "`u` holds");
  CHECK(all_equal(out, NL, 42.0));
  host[e0] = 1.0;
  u[7] = NAN;
  EXPECT_ERROR(c, tfem_solid_contact_scatter_add(c, u, NL, host, (size_t)n_eq),
               TFEM_STATUS_INVALID_ARGUMENT, "`residual`: the y value of interface node");
  u[7] = 0.0;
  host[e0] = INFINITY;
  EXPECT_ERROR(c, tfem_solid_contact_scatter_add(c, u, NL, host, (size_t)n_eq),
               TFEM_STATUS_INVALID_ARGUMENT, "`host_vector` holds inf at equation");
  host[e0] = 1.0;
  u[3 * (lower.n_nodes - 1) + 2] = 1e308;
  host[e0] = 1e308;
  EXPECT_ERROR(c, tfem_solid_contact_scatter_add(c, u, NL, host, (size_t)n_eq),
               TFEM_STATUS_NUMERICAL_FAILURE, "gives inf");
  CHECK(host[e0] == 1e308);
  host[e0] = 1.0;
  u[3 * (lower.n_nodes - 1) + 2] = 0.0;
  EXPECT_ERROR(c, tfem_solid_contact_scatter_add(c, u, NL - 3, host, (size_t)n_eq),
               TFEM_STATUS_INVALID_ARGUMENT, "`residual` holds 51 values");
  EXPECT_ERROR(c, tfem_solid_contact_scatter_add(c, u, NL, host, 3),
               TFEM_STATUS_INVALID_ARGUMENT, "beyond the host's vector");
  CHECK(all_equal(host, MAX_EQ, 1.0));

  /* Results: buffers too short, NULL outputs. */
  double area = -7.0, gaps[N_CONTACT];
  for (int k = 0; k < N_CONTACT; ++k) gaps[k] = 42.0;
  EXPECT_ERROR(c, tfem_solid_contact_gaps(c, u, NL, gaps, N_CONTACT - 1),
               TFEM_STATUS_BUFFER_TOO_SMALL, "are needed");
  u[0] = INFINITY;
  EXPECT_ERROR(c, tfem_solid_contact_gaps(c, u, NL, gaps, N_CONTACT),
               TFEM_STATUS_INVALID_ARGUMENT, "not finite");
  u[0] = 0.0;
  CHECK(all_equal(gaps, N_CONTACT, 42.0));
  EXPECT_ERROR(c, tfem_solid_contact_area(c, NULL), TFEM_STATUS_NULL_POINTER, "`area`");
  int64_t rw[4] = {-7, -7, -7, -7};
  EXPECT_ERROR(c, tfem_solid_contact_pattern(c, rw, NULL, (size_t)ne), TFEM_STATUS_NULL_POINTER,
               "`cols`");
  EXPECT_ERROR(c, tfem_solid_contact_pattern(c, rw, rw, 4), TFEM_STATUS_BUFFER_TOO_SMALL,
               "are needed");
  CHECK(rw[0] == -7 && rw[3] == -7);
  EXPECT_ERROR(c, tfem_solid_contact_element_blocks(c, out, 144 * N_CONTACT - 1),
               TFEM_STATUS_BUFFER_TOO_SMALL, "are needed");
  OK(tfem_solid_contact_area(c, &area));
  CHECK(fabs(area - 1.0) < 1e-12);

  /* The cap on updates: max_iterations = 1 refuses a second update of one
   * loop; a restart starts a new one. */
  tfem_solid_contact *capped;
  OK(tfem_contact_options_default(&o));
  o.max_iterations = 1;
  capped = tfem_solid_contact_create(1, &o);
  CHECK(capped != NULL);
  OK(tfem_solid_contact_add_side(capped, 6, 1, E, lower.n_nodes, lower.nodes, lower.xyz,
                                 lower.equations, lower.n_triangles, lower.triangles, NULL));
  OK(tfem_solid_contact_add_side(capped, 15, 2, E, upper.n_nodes, upper.nodes, upper.xyz,
                                 upper.equations, upper.n_triangles, upper.triangles, NULL));
  OK(tfem_solid_contact_add_pair(capped, 1, 2, NULL));
  OK(tfem_solid_contact_update(capped, u, NL, &changed, NULL, NULL));
  CHECK(changed == 0);
  changed = -7;
  EXPECT_ERROR(capped, tfem_solid_contact_update(capped, u, NL, &changed, NULL, NULL),
               TFEM_STATUS_NOT_CONVERGED, "did not settle in 1 iterations");
  CHECK(changed == -7);
  OK(tfem_solid_contact_restart(capped));
  OK(tfem_solid_contact_update(capped, u, NL, &changed, NULL, NULL));
  CHECK(changed == 0);
  tfem_solid_contact_destroy(capped);

  /* Sides that do not face each other: the upper side numbered clockwise
   * seen from outside, refused when B is built, naming the pair. */
  tfem_solid_contact *turned = tfem_solid_contact_create(0, NULL);
  side_data lo0, up0;
  side_of(TAG_LOWER_TOP, 1.0, 0, &lo0);
  side_of(TAG_UPPER_BOTTOM, +1.0, 0, &up0);
  OK(tfem_solid_contact_add_side(turned, 6, 1, E, lo0.n_nodes, lo0.nodes, lo0.xyz, lo0.equations,
                                 lo0.n_triangles, lo0.triangles, NULL));
  OK(tfem_solid_contact_add_side(turned, 15, 2, E, up0.n_nodes, up0.nodes, up0.xyz,
                                 up0.equations, up0.n_triangles, up0.triangles, NULL));
  OK(tfem_solid_contact_add_pair(turned, 0, 1, NULL));
  EXPECT_ERROR(turned, tfem_solid_contact_setup(turned), TFEM_STATUS_INVALID_ARGUMENT,
               "contact pair 0 (sides 0 and 1): the sides do not face each other");
  tfem_solid_contact_destroy(turned);

  /* Handles: NULL, a 2D context, a 3D model, the other way round, a
   * destroyed one. Their messages are the thread's. */
  EXPECT_ERROR(NULL, tfem_solid_contact_setup(NULL), TFEM_STATUS_NULL_POINTER, "`context`");
  tfem_contact *two = tfem_contact_create(1);
  tfem_solid_model *model = tfem_solid_create();
  nn = -7;
  EXPECT_ERROR(NULL, tfem_solid_contact_sizes((tfem_solid_contact *)two, &nn, NULL, NULL),
               TFEM_STATUS_INVALID_ARGUMENT,
               "is not a 3D contact context (from tfem_solid_contact_create): it is a contact "
               "context (from tfem_contact_create)");
  EXPECT_ERROR(NULL, tfem_solid_contact_setup((tfem_solid_contact *)model),
               TFEM_STATUS_INVALID_ARGUMENT, "it is a 3D model");
  EXPECT_ERROR(NULL, tfem_contact_sizes((tfem_contact *)c, &nn, NULL, NULL),
               TFEM_STATUS_INVALID_ARGUMENT, "it is a 3D contact context");
  EXPECT_ERROR(NULL, tfem_solid_solve((tfem_solid_model *)c, NULL), TFEM_STATUS_INVALID_ARGUMENT,
               "it is a 3D contact context");
  CHECK(nn == -7);
  char msg[256] = "";
  CHECK(tfem_solid_contact_last_error((tfem_solid_contact *)two, msg, sizeof msg) ==
        TFEM_STATUS_INVALID_ARGUMENT);
  CHECK(strstr(msg, "not a 3D contact context") != NULL);
  CHECK(tfem_solid_contact_last_error_length((tfem_solid_contact *)two) == strlen(msg) + 1);
  CHECK(tfem_solid_contact_last_error(NULL, msg, sizeof msg) == TFEM_STATUS_NULL_POINTER);
  CHECK(tfem_solid_contact_last_error_length(NULL) == 1);
  tfem_solid_contact_destroy((tfem_solid_contact *)two); /* not ours: a no-op */
  OK(tfem_contact_last_error(two, msg, sizeof msg)); /* still live */
  tfem_contact_destroy(two);
  tfem_solid_destroy(model);

  /* The context still works after every refusal. */
  OK(tfem_solid_contact_evaluate(c, u, NL, out, (size_t)ne, NULL, 0));
  CHECK(tfem_solid_contact_last_error_length(c) == 1);

  tfem_solid_contact_destroy(c);
  EXPECT_ERROR(NULL, tfem_solid_contact_setup(c), TFEM_STATUS_INVALID_ARGUMENT, "destroyed");
  CHECK(tfem_solid_contact_last_error(c, msg, sizeof msg) == TFEM_STATUS_INVALID_ARGUMENT);
  CHECK(strstr(msg, "destroyed") != NULL);
  tfem_solid_contact_destroy(c); /* again: a no-op */
}

/* A side's node that faces no node of the other side is named by the
 * host's own number (here index base 1): the lower side's node (1, 1, N)
 * moved off the node above it. */
static void unmatched_node_named_by_host_number(void) {
  tfem_solid_contact *c = tfem_solid_contact_create(1, NULL);
  CHECK(c != NULL);
  side_of(TAG_LOWER_TOP, 1.0, 1, &lower);
  side_of(TAG_UPPER_BOTTOM, -1.0, 1, &upper);
  int host = id(0, 1, 1, N) + 1, found = 0;
  for (int m = 0; m < lower.n_nodes; ++m)
    if (lower.nodes[m] == host) {
      lower.xyz[3 * m] += 0.1 / N;
      found = 1;
    }
  CHECK(found);
  int a = -7, b = -7;
  OK(tfem_solid_contact_add_side(c, TAG_LOWER_TOP, 1, E, lower.n_nodes, lower.nodes, lower.xyz,
                                 lower.equations, lower.n_triangles, lower.triangles, &a));
  OK(tfem_solid_contact_add_side(c, TAG_UPPER_BOTTOM, 2, E, upper.n_nodes, upper.nodes,
                                 upper.xyz, upper.equations, upper.n_triangles, upper.triangles,
                                 &b));
  OK(tfem_solid_contact_add_pair(c, a, b, NULL));
  char needle[64];
  snprintf(needle, sizeof needle, "node %d of surface a faces no node", host);
  EXPECT_ERROR(c, tfem_solid_contact_setup(c), TFEM_STATUS_INVALID_ARGUMENT, needle);
  tfem_solid_contact_destroy(c);
}

int main(void) {
  cube(0, -1.0, 0);
  cube(NODES_PER, 0.0, 10);
  if (n_tets != N_TETS || n_faces != N_FACES) {
    printf("mesh built wrong: %d tetrahedra, %d faces\n", n_tets, n_faces);
    return 1;
  }
  number_equations();
  CHECK(n_eq == 3 * N_NODES - 5 * NP * NP);
  assemble();

  patch_test(1);
  patch_test(0);
  refusals();
  unmatched_node_named_by_host_number();

  printf("solid_host_test: %d passed, %d failed\n", passed, failed);
  return failed == 0 ? 0 : 1;
}
