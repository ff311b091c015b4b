/* An external integrator for dlpverify in plain C on the HDF5 C API: explicit midpoint (RK2) on
 * the DLP particle cloud. It knows nothing of dlpverify but the exchange file (docs/exchange.md):
 * it reads the initial state and the problem's description from INPUT, integrates `steps` steps
 * of `dt` from `t0`, and writes the final state to OUTPUT. The right-hand side is written here
 * from docs/model.md §1, independently of dlpverify's own code, as a user's code would be.
 *
 *   dlpverify check --case drag --expect-order 2 --integrator "exec:external_midpoint_c {input} {output}"
 *
 * --slip puts the midpoint stage at the full step (a deliberate bug: order 1, for the test that a
 * check catches it). Exit 0 done, 1 a file could not be read or written, 2 bad arguments. */
#include <hdf5.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

enum { X, Y, Z, VX, VY, VZ, T, M, FIELDS };
static const char* const kNames[FIELDS] = {"x", "y", "z", "vx", "vy", "vz", "T", "m"};

typedef struct {
  double diameter, rho_particle, cs_particle, rho_gas, mu_gas, cp_gas, prandtl, t_gas, cd, gravity, burn_rate;
  int drag, reynolds_law, gravity_on, heat, burning;
} Model;

static void fail(const char* what, const char* name) {
  fprintf(stderr, "midpoint.c: %s %s\n", what, name);
  exit(1);
}

static double number(hid_t at, const char* name) {
  double value = 0.0;
  hid_t a = H5Aopen(at, name, H5P_DEFAULT);
  if (a < 0 || H5Aread(a, H5T_NATIVE_DOUBLE, &value) < 0) fail("cannot read the attribute", name);
  H5Aclose(a);
  return value;
}

/* A variable-length UTF-8 string attribute, compared with `expected`. */
static int text_is(hid_t at, const char* name, const char* expected) {
  char* value = NULL;
  hid_t type = H5Tcopy(H5T_C_S1);
  H5Tset_size(type, H5T_VARIABLE);
  H5Tset_cset(type, H5T_CSET_UTF8); /* the file's strings are UTF-8: HDF5 converts no character sets */
  hid_t a = H5Aopen(at, name, H5P_DEFAULT);
  if (a < 0 || H5Aread(a, type, &value) < 0) fail("cannot read the attribute", name);
  const int same = strcmp(value, expected) == 0;
  H5free_memory(value);
  H5Aclose(a);
  H5Tclose(type);
  return same;
}

static Model read_model(hid_t file) {
  Model m;
  hid_t p = H5Gopen2(file, "parameters", H5P_DEFAULT), t = H5Gopen2(file, "terms", H5P_DEFAULT);
  if (p < 0 || t < 0) fail("no group", "/parameters or /terms");
  m.diameter = number(p, "diameter");
  m.rho_particle = number(p, "rho_particle");
  m.cs_particle = number(p, "cs_particle");
  m.rho_gas = number(p, "rho_gas");
  m.mu_gas = number(p, "mu_gas");
  m.cp_gas = number(p, "cp_gas");
  m.prandtl = number(p, "prandtl");
  m.t_gas = number(p, "t_gas");
  m.cd = number(p, "cd");
  m.gravity = number(p, "gravity");
  m.burn_rate = number(p, "burn_rate");
  m.drag = !text_is(t, "drag", "off");
  m.reynolds_law = text_is(t, "drag", "reynolds");
  m.gravity_on = text_is(t, "gravity", "on");
  m.heat = text_is(t, "heat", "on");
  m.burning = text_is(t, "burning", "on");
  H5Gclose(p);
  H5Gclose(t);
  return m;
}

/* dy/dt of docs/model.md §1 for members [0, n), quiescent gas (w = -v). */
static void rhs(const Model* c, double* const y[FIELDS], double* const f[FIELDS], long n) {
  const double pi = 3.14159265358979323846, k_gas = c->mu_gas * c->cp_gas / c->prandtl;
  for (long i = 0; i < n; ++i) {
    const double vx = y[VX][i], vy = y[VY][i], vz = y[VZ][i];
    const double d = c->burning ? cbrt(6.0 * y[M][i] / (pi * c->rho_particle)) : c->diameter;
    const double s = sqrt(vx * vx + vy * vy + vz * vz); /* slip speed |w| = |v| */
    double k = 0.0;
    if (c->drag) {
      /* C_D |w|, the law's form finite at |w| = 0: 0.48 |w| + 28 (rho_a d / mu)^-0.85 |w|^0.15 */
      const double cd_s = c->reynolds_law ? 0.48 * s + 28.0 * pow(c->rho_gas * d / c->mu_gas, -0.85) * pow(s, 0.15)
                                          : c->cd * s;
      k = -3.0 * c->rho_gas / (4.0 * c->rho_particle * d) * cd_s;
    }
    f[X][i] = vx;
    f[Y][i] = vy;
    f[Z][i] = vz;
    f[VX][i] = k * vx;
    f[VY][i] = k * vy;
    f[VZ][i] = k * vz - (c->gravity_on ? c->gravity : 0.0); /* g = (0, 0, -|g|) */
    f[T][i] = 0.0;
    if (c->heat) {
      const double nusselt = 2.0 + 0.6 * cbrt(c->prandtl) * sqrt(c->rho_gas * s * d / c->mu_gas);
      f[T][i] = pi * d * k_gas * nusselt * (c->t_gas - y[T][i]) / (y[M][i] * c->cs_particle);
    }
    f[M][i] = c->burning ? -c->burn_rate * d * d : 0.0;
  }
}

static double** columns(long n) {
  double** c = malloc(FIELDS * sizeof *c);
  for (int f = 0; f < FIELDS; ++f)
    if (!(c[f] = malloc((size_t)n * sizeof **c))) fail("out of memory for", "the state");
  return c;
}

static void free_columns(double** c) {
  for (int f = 0; f < FIELDS; ++f) free(c[f]);
  free(c);
}

/* Explicit midpoint: y_half = y + (dt/2) f(y); y += dt f(y_half). With `slip`, y + dt f(y). */
static void midpoint(const Model* c, double** y, long n, double dt, long steps, int slip) {
  double **k1 = columns(n), **half = columns(n), **k2 = columns(n);
  const double stage = slip ? dt : 0.5 * dt;
  for (long step = 0; step < steps; ++step) {
    rhs(c, y, k1, n);
    for (int f = 0; f < FIELDS; ++f)
      for (long i = 0; i < n; ++i) half[f][i] = y[f][i] + stage * k1[f][i];
    rhs(c, half, k2, n);
    for (int f = 0; f < FIELDS; ++f)
      for (long i = 0; i < n; ++i) y[f][i] += dt * k2[f][i];
  }
  free_columns(k1);
  free_columns(half);
  free_columns(k2);
}

int main(int argc, char** argv) {
  if (argc < 3 || argc > 4 || (argc == 4 && strcmp(argv[3], "--slip") != 0)) {
    fprintf(stderr, "usage: %s INPUT OUTPUT [--slip]\n", argv[0]);
    return 2;
  }
  hid_t in = H5Fopen(argv[1], H5F_ACC_RDONLY, H5P_DEFAULT);
  if (in < 0) fail("cannot open", argv[1]);
  if (number(in, "dlpverify_exchange_version") != 1.0) fail("unknown exchange version in", argv[1]);
  if (!text_is(in, "problem", "dlp")) fail("this example implements the DLP cloud only, not the problem of", argv[1]);
  const Model model = read_model(in);
  const double dt = number(in, "dt");
  const long steps = (long)number(in, "steps"), n = (long)number(in, "members");
  double** y = columns(n);
  for (int f = 0; f < FIELDS; ++f) {
    char path[32];
    snprintf(path, sizeof path, "/fields/%s", kNames[f]);
    hid_t set = H5Dopen2(in, path, H5P_DEFAULT);
    if (set < 0 || H5Dread(set, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, y[f]) < 0) fail("cannot read", path);
    H5Dclose(set);
  }
  H5Fclose(in);

  midpoint(&model, y, n, dt, steps, argc == 4);

  hid_t out = H5Fcreate(argv[2], H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT);
  hid_t group = out < 0 ? -1 : H5Gcreate2(out, "fields", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
  if (group < 0) fail("cannot create", argv[2]);
  const hsize_t length = (hsize_t)n;
  hid_t space = H5Screate_simple(1, &length, NULL);
  for (int f = 0; f < FIELDS; ++f) {
    hid_t set = H5Dcreate2(group, kNames[f], H5T_IEEE_F64LE, space, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
    if (set < 0 || H5Dwrite(set, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, y[f]) < 0) fail("cannot write", argv[2]);
    H5Dclose(set);
  }
  H5Sclose(space);
  H5Gclose(group);
  free_columns(y);
  return H5Fclose(out) < 0;
}
