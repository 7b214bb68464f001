/* The seed scene through the C ABI. Reads a scene file (mesh, constraints,
 * load, materials, contact pair and probe nodes, 0-based; written by the
 * Rust test `two_blocks_through_the_c_abi_matches_rust`), solves the contact
 * problem with the default options and prints the outputs with 17
 * significant digits, one "name value" per line. */

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "tfem.h"

static void fail(tfem_model *m, const char *what, tfem_status s) {
  char msg[1024];
  tfem_last_error(m, msg, sizeof msg);
  fprintf(stderr, "%s failed with status %d: %s\n", what, (int)s, msg);
  exit(1);
}

#define CALL(m, expr)                          \
  do {                                         \
    tfem_status s_ = (expr);                   \
    if (s_ != TFEM_STATUS_OK) fail(m, #expr, s_); \
  } while (0)

static int expect(FILE *f, const char *word) {
  char buf[64];
  int n = 0;
  if (fscanf(f, "%63s %d", buf, &n) != 2 || strcmp(buf, word) != 0) {
    fprintf(stderr, "scene file: expected section '%s'\n", word);
    exit(2);
  }
  return n;
}

int main(int argc, char **argv) {
  if (argc != 2) {
    fprintf(stderr, "usage: %s scene.txt\n", argv[0]);
    return 2;
  }
  FILE *f = fopen(argv[1], "r");
  if (!f) {
    perror(argv[1]);
    return 2;
  }
  tfem_model *m = tfem_create();
  int nn = expect(f, "nodes");
  double *xy = malloc(sizeof(double) * 2 * nn);
  for (int i = 0; i < 2 * nn; ++i)
    if (fscanf(f, "%lf", &xy[i]) != 1) return 2;
  int nt = expect(f, "triangles");
  int *conn = malloc(sizeof(int) * 3 * nt), *body = malloc(sizeof(int) * nt);
  for (int t = 0; t < nt; ++t)
    if (fscanf(f, "%d %d %d %d", &conn[3 * t], &conn[3 * t + 1], &conn[3 * t + 2], &body[t]) != 4) return 2;
  CALL(m, tfem_set_mesh(m, nn, xy, nt, conn, body, 0));
  int ne = expect(f, "edges");
  int *edges = malloc(sizeof(int) * 2 * ne), *tags = malloc(sizeof(int) * ne);
  for (int e = 0; e < ne; ++e)
    if (fscanf(f, "%d %d %d", &edges[2 * e], &edges[2 * e + 1], &tags[e]) != 3) return 2;
  CALL(m, tfem_set_boundary_edges(m, ne, edges, tags));
  int nm = expect(f, "materials");
  for (int k = 0; k < nm; ++k) {
    int b, plane;
    double E, nu;
    if (fscanf(f, "%d %lf %lf %d", &b, &E, &nu, &plane) != 4) return 2;
    CALL(m, tfem_set_material(m, b, E, nu, plane));
  }
  int nf = expect(f, "fixed");
  for (int k = 0; k < nf; ++k) {
    int node, comp;
    double value;
    if (fscanf(f, "%d %d %lf", &node, &comp, &value) != 3) return 2;
    CALL(m, tfem_fix(m, node, comp, value));
  }
  int np = expect(f, "pressures");
  for (int k = 0; k < np; ++k) {
    int tag;
    double p;
    if (fscanf(f, "%d %lf", &tag, &p) != 2) return 2;
    CALL(m, tfem_add_pressure(m, tag, p));
  }
  int ta, tb, corner_lower, corner_upper, top_center;
  expect(f, "contact");
  if (fscanf(f, "%d %d", &ta, &tb) != 2) return 2;
  CALL(m, tfem_add_contact_pair(m, ta, tb, NULL));
  expect(f, "probes");
  if (fscanf(f, "%d %d %d", &corner_lower, &corner_upper, &top_center) != 3) return 2;
  fclose(f);

  tfem_contact_options opts;
  CALL(m, tfem_contact_options_default(&opts));
  tfem_contact_report rep;
  CALL(m, tfem_solve_contact(m, &opts, &rep));
  double *u = malloc(sizeof(double) * 2 * nn);
  CALL(m, tfem_get_displacements(m, u, 2 * (size_t)nn));
  int nn2, nt2, nc;
  CALL(m, tfem_get_sizes(m, &nn2, &nt2, &nc));
  int *active = malloc(sizeof(int) * nc);
  double *pressure = malloc(sizeof(double) * nc);
  CALL(m, tfem_get_contact_active(m, active, (size_t)nc));
  CALL(m, tfem_get_contact_pressure(m, pressure, (size_t)nc));
  int n_active = 0;
  for (int k = 0; k < nc; ++k) n_active += active[k];

  printf("lc %.17g\n", rep.contact_length);
  printf("gap_edge %.17g\n", u[2 * corner_upper + 1] - u[2 * corner_lower + 1]);
  printf("v_top %.17g\n", u[2 * top_center + 1]);
  printf("max_penetration %.17g\n", rep.max_penetration);
  printf("iterations %d\n", rep.iterations);
  printf("active %d\n", n_active);
  printf("unknowns %lld\n", (long long)rep.info.unknowns);
  tfem_destroy(m);
  free(xy);
  free(conn);
  free(body);
  free(edges);
  free(tags);
  free(u);
  free(active);
  free(pressure);
  return 0;
}
