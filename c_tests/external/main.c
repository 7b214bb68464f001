/* A user program built against the installed tfem package: a clamped
 * square pulled on one side, prints the version and the tip displacement. */
#include <math.h>
#include <stdio.h>

#include "tfem.h"

int main(void) {
  tfem_model *m = tfem_create();
  double xy[] = {0, 0, 1, 0, 1, 1, 0, 1};
  int tri[] = {0, 1, 2, 0, 2, 3}, body[] = {1, 1}, edges[] = {1, 2}, tags[] = {10};
  double u[8];
  int ok = tfem_set_mesh(m, 4, xy, 2, tri, body, 0) == TFEM_STATUS_OK &&
           tfem_set_boundary_edges(m, 1, edges, tags) == TFEM_STATUS_OK &&
           tfem_set_material(m, 1, 1000.0, 0.0, TFEM_PLANE_MODE_STRESS) == TFEM_STATUS_OK &&
           tfem_set_tempering(m, TFEM_TEMPERING_MODE_LAMBDA, 1e6) == TFEM_STATUS_OK &&
           tfem_fix(m, 0, TFEM_COMPONENT_X, 0.0) == TFEM_STATUS_OK &&
           tfem_fix(m, 0, TFEM_COMPONENT_Y, 0.0) == TFEM_STATUS_OK &&
           tfem_fix(m, 3, TFEM_COMPONENT_X, 0.0) == TFEM_STATUS_OK &&
           tfem_add_traction(m, 10, 1.0, 0.0) == TFEM_STATUS_OK &&
           tfem_solve(m, NULL) == TFEM_STATUS_OK && tfem_get_displacements(m, u, 8) == TFEM_STATUS_OK;
  tfem_destroy(m);
  if (!ok || fabs(u[2] - 1e-3) > 1e-15) {
    printf("tfem_user: FAILED\n");
    return 1;
  }
  printf("tfem_user: tfem %s, u_x at the pulled side = %.6e (exact 1e-3)\n", tfem_version(), u[2]);
  return 0;
}
