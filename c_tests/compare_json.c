/* Regression check: compares the numbers of a JSON object (one line, as
 * printed by `two_blocks --json`) with a baseline file of lines
 *   key  value  relative_tolerance
 * and prints a readable table; exits 1 when a number moved beyond its
 * tolerance or is missing. With --bless, rewrites the baseline's values
 * from the JSON (keeping its keys and tolerances). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static char *slurp(const char *path) {
  FILE *f = fopen(path, "rb");
  if (!f) return NULL;
  fseek(f, 0, SEEK_END);
  long n = ftell(f);
  fseek(f, 0, SEEK_SET);
  char *s = malloc((size_t)n + 1);
  size_t got = fread(s, 1, (size_t)n, f);
  s[got] = 0;
  fclose(f);
  return s;
}

static int lookup(const char *json, const char *key, double *value) {
  char pattern[128];
  snprintf(pattern, sizeof pattern, "\"%s\":", key);
  const char *p = strstr(json, pattern);
  if (!p) return 0;
  char *end;
  *value = strtod(p + strlen(pattern), &end);
  return end != p + strlen(pattern);
}

int main(int argc, char **argv) {
  int bless = argc == 4 && strcmp(argv[1], "--bless") == 0;
  if (argc != 3 && !bless) {
    fprintf(stderr, "usage: %s [--bless] baseline.txt output.json\n", argv[0]);
    return 2;
  }
  const char *base_path = argv[argc - 2], *json_path = argv[argc - 1];
  char *json = slurp(json_path), *base = slurp(base_path);
  if (!json || !base) {
    fprintf(stderr, "cannot read %s or %s\n", base_path, json_path);
    return 2;
  }
  char key[64];
  double expected, tol, got;
  int n = 0, bad = 0, off = 0;
  FILE *out = bless ? fopen(base_path, "w") : NULL;
  printf("%-20s %24s %24s %10s %10s\n", "quantity", "baseline", "now", "rel.diff", "tolerance");
  while (sscanf(base + off, "%63s %lf %lf%n", key, &expected, &tol, &n) == 3) {
    off += n;
    if (!lookup(json, key, &got)) {
      printf("%-20s %24.16e %24s  MISSING\n", key, expected, "-");
      ++bad;
      continue;
    }
    if (out) fprintf(out, "%s %.17g %g\n", key, got, tol);
    double rel = fabs(got - expected) / fmax(fabs(expected), 1e-300);
    int fail = !(rel <= tol);
    printf("%-20s %24.16e %24.16e %10.2e %10.1e%s\n", key, expected, got, rel, tol, fail ? "  CHANGED" : "");
    bad += fail;
  }
  if (out) {
    fclose(out);
    printf("blessed %s\n", base_path);
    return 0;
  }
  printf("%d passed, %d failed\n", bad == 0 ? 1 : 0, bad == 0 ? 0 : 1);
  return bad == 0 ? 0 : 1;
}
