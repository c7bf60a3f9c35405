/* GENERATED FILE - DO NOT EDIT. C code emitted by CasADi for point_bias_acceleration() of
 * generated/spatial/na1/ (see its model.py), plus its batched driver.
 * Regenerate with: python -m snakecg_derive.spatial --checked-in
 * spec sha256: f2554e7caf7b43e45e9fb60d8118a375db06d8dd0e711f01c5b700b16dc8d2be
 * tools: sympy 1.14.0, casadi 3.8.2, jinja2 3.1.6
 */
/* How to prefix internal symbols */
#ifdef CASADI_CODEGEN_PREFIX
  #define CASADI_NAMESPACE_CONCAT(NS, ID) _CASADI_NAMESPACE_CONCAT(NS, ID)
  #define _CASADI_NAMESPACE_CONCAT(NS, ID) NS ## ID
  #define CASADI_PREFIX(ID) CASADI_NAMESPACE_CONCAT(CODEGEN_PREFIX, ID)
#else
  #define CASADI_PREFIX(ID) snakecg_sp1_point_bias_acceleration_ ## ID
#endif

#include <math.h>

#ifndef casadi_real
#define casadi_real double
#endif

#ifndef casadi_int
#define casadi_int long long int
#endif

/* Add prefix to internal symbols */
#define casadi_f0 CASADI_PREFIX(f0)
#define casadi_s0 CASADI_PREFIX(s0)
#define casadi_s1 CASADI_PREFIX(s1)
#define casadi_s2 CASADI_PREFIX(s2)
#define casadi_s3 CASADI_PREFIX(s3)
#define casadi_s4 CASADI_PREFIX(s4)
#define casadi_sq CASADI_PREFIX(sq)

/* Symbol visibility in DLLs */
#ifndef CASADI_SYMBOL_EXPORT
  #if defined(_WIN32) || defined(__WIN32__) || defined(__CYGWIN__)
    #if defined(STATIC_LINKED)
      #define CASADI_SYMBOL_EXPORT
    #else
      #define CASADI_SYMBOL_EXPORT __declspec(dllexport)
    #endif
  #elif defined(__GNUC__) && defined(GCC_HASCLASSVISIBILITY)
    #define CASADI_SYMBOL_EXPORT __attribute__ ((visibility ("default")))
  #else
    #define CASADI_SYMBOL_EXPORT
  #endif
#endif

casadi_real casadi_sq(casadi_real x) { return x*x;}

/* Configuration this file was compiled with */
CASADI_SYMBOL_EXPORT void snakecg_sp1_point_bias_acceleration_casadi_version(int* major, int* minor, int* patch) {
  *major = 3;
  *minor = 8;
  *patch = 2;
}
CASADI_SYMBOL_EXPORT int snakecg_sp1_point_bias_acceleration_casadi_int_size(void) { return (int) sizeof(casadi_int); }
CASADI_SYMBOL_EXPORT int snakecg_sp1_point_bias_acceleration_casadi_real_size(void) { return (int) sizeof(casadi_real); }

static const casadi_int casadi_s0[3] = {8, 1, 1};
static const casadi_int casadi_s1[3] = {7, 1, 1};
static const casadi_int casadi_s2[3] = {71, 1, 1};
static const casadi_int casadi_s3[3] = {2, 1, 1};
static const casadi_int casadi_s4[3] = {3, 1, 1};

/* snakecg_sp1_point_bias_acceleration:(q[8],v[7],K[71],link[2],point[3])->(bias[3]) */
static int casadi_f0(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem) {
  casadi_real a00, a01, a02, a03, a04, a05, a06, a07, a08, a09, a10, a11;
  casadi_real a12, a13, a14, a15, a16, a17, a18, a19, a20, a21, a22, a23;
  casadi_real a24, a25, a26, a27, a28, a29, a30, a31, a32, a33, a34, a35;
  casadi_real a36, a37, a38, a39, a40, a41, a42, a43, a44, a45;
  a00=arg[0]? arg[0][6] : 0;
  a01=(2.*a00);
  a02=arg[0]? arg[0][5] : 0;
  a03=(a01*a02);
  a04=arg[0]? arg[0][3] : 0;
  a05=(2.*a04);
  a06=arg[0]? arg[0][4] : 0;
  a07=(a05*a06);
  a03=(a03+a07);
  a08=arg[1]? arg[1][3] : 0;
  a09=(a03*a08);
  a10=1.;
  a11=-2.;
  a12=casadi_sq(a04);
  a12=(a11*a12);
  a12=(a10+a12);
  a13=casadi_sq(a02);
  a13=(a11*a13);
  a14=(a12+a13);
  a15=arg[1]? arg[1][4] : 0;
  a16=(a14*a15);
  a09=(a09+a16);
  a00=(a11*a00);
  a16=(a00*a04);
  a17=(2.*a06);
  a17=(a17*a02);
  a16=(a16+a17);
  a18=arg[1]? arg[1][5] : 0;
  a19=(a16*a18);
  a09=(a09+a19);
  a19=(a00*a06);
  a05=(a05*a02);
  a19=(a19+a05);
  a20=arg[1]? arg[1][0] : 0;
  a21=(a19*a20);
  a04=(a01*a04);
  a04=(a04+a17);
  a17=arg[1]? arg[1][1] : 0;
  a22=(a04*a17);
  a21=(a21+a22);
  a22=casadi_sq(a06);
  a11=(a11*a22);
  a12=(a12+a11);
  a22=arg[1]? arg[1][2] : 0;
  a23=(a12*a22);
  a21=(a21+a23);
  a23=(a09*a21);
  a24=(a19*a08);
  a25=(a04*a15);
  a24=(a24+a25);
  a25=(a12*a18);
  a24=(a24+a25);
  a25=(a03*a20);
  a26=(a14*a17);
  a25=(a25+a26);
  a26=(a16*a22);
  a25=(a25+a26);
  a26=(a24*a25);
  a23=(a23-a26);
  a26=arg[3]? arg[3][0] : 0;
  a27=(a23*a26);
  a28=arg[2]? arg[2][50] : 0;
  a29=(a03*a28);
  a30=arg[2]? arg[2][51] : 0;
  a31=(a14*a30);
  a29=(a29+a31);
  a31=arg[2]? arg[2][52] : 0;
  a32=(a16*a31);
  a29=(a29+a32);
  a10=(a10+a11);
  a10=(a10+a13);
  a08=(a10*a08);
  a00=(a00*a02);
  a00=(a00+a07);
  a15=(a00*a15);
  a08=(a08+a15);
  a01=(a01*a06);
  a01=(a01+a05);
  a18=(a01*a18);
  a08=(a08+a18);
  a18=(a29*a08);
  a05=(a10*a28);
  a06=(a00*a30);
  a05=(a05+a06);
  a06=(a01*a31);
  a05=(a05+a06);
  a06=(a05*a09);
  a18=(a18-a06);
  a06=(a09*a18);
  a23=(a23+a06);
  a05=(a05*a24);
  a28=(a19*a28);
  a30=(a04*a30);
  a28=(a28+a30);
  a31=(a12*a31);
  a28=(a28+a31);
  a31=(a28*a08);
  a05=(a05-a31);
  a31=(a24*a05);
  a23=(a23-a31);
  a31=arg[3]? arg[3][1] : 0;
  a23=(a23*a31);
  a27=(a27+a23);
  a23=arg[1]? arg[1][6] : 0;
  a30=arg[2]? arg[2][47] : 0;
  a06=(a30*a10);
  a15=arg[2]? arg[2][48] : 0;
  a07=(a15*a00);
  a06=(a06+a07);
  a07=arg[2]? arg[2][49] : 0;
  a02=(a07*a01);
  a06=(a06+a02);
  a02=(a06*a24);
  a13=(a30*a19);
  a11=(a15*a04);
  a13=(a13+a11);
  a11=(a07*a12);
  a13=(a13+a11);
  a11=(a13*a08);
  a02=(a02-a11);
  a02=(a23*a02);
  a02=(a02*a31);
  a11=arg[2]? arg[2][41] : 0;
  a32=(a11*a19);
  a33=arg[2]? arg[2][42] : 0;
  a34=(a33*a04);
  a32=(a32+a34);
  a34=arg[2]? arg[2][43] : 0;
  a35=(a34*a12);
  a32=(a32+a35);
  a35=arg[0]? arg[0][7] : 0;
  a36=cos(a35);
  a37=(a32*a36);
  a38=arg[2]? arg[2][44] : 0;
  a39=(a38*a19);
  a40=arg[2]? arg[2][45] : 0;
  a41=(a40*a04);
  a39=(a39+a41);
  a41=arg[2]? arg[2][46] : 0;
  a42=(a41*a12);
  a39=(a39+a42);
  a35=sin(a35);
  a42=(a39*a35);
  a37=(a37+a42);
  a37=(a37*a31);
  a19=(a19*a26);
  a37=(a37+a19);
  a19=arg[2]? arg[2][32] : 0;
  a19=(a19*a31);
  a19=(a26+a19);
  a42=arg[4]? arg[4][0] : 0;
  a19=(a19*a42);
  a43=arg[2]? arg[2][33] : 0;
  a43=(a43*a31);
  a44=arg[4]? arg[4][1] : 0;
  a43=(a43*a44);
  a19=(a19+a43);
  a43=arg[2]? arg[2][34] : 0;
  a43=(a43*a31);
  a45=arg[4]? arg[4][2] : 0;
  a43=(a43*a45);
  a19=(a19+a43);
  a37=(a37*a19);
  a39=(a39*a36);
  a32=(a32*a35);
  a39=(a39-a32);
  a39=(a39*a31);
  a04=(a04*a26);
  a39=(a39+a04);
  a04=arg[2]? arg[2][35] : 0;
  a04=(a04*a31);
  a04=(a04*a42);
  a32=arg[2]? arg[2][36] : 0;
  a32=(a32*a31);
  a32=(a26+a32);
  a32=(a32*a44);
  a04=(a04+a32);
  a32=arg[2]? arg[2][37] : 0;
  a32=(a32*a31);
  a32=(a32*a45);
  a04=(a04+a32);
  a39=(a39*a04);
  a37=(a37+a39);
  a39=(a13*a31);
  a12=(a12*a26);
  a39=(a39+a12);
  a12=arg[2]? arg[2][38] : 0;
  a12=(a12*a31);
  a12=(a12*a42);
  a42=arg[2]? arg[2][39] : 0;
  a42=(a42*a31);
  a42=(a42*a44);
  a12=(a12+a42);
  a42=arg[2]? arg[2][40] : 0;
  a42=(a42*a31);
  a42=(a26+a42);
  a42=(a42*a45);
  a12=(a12+a42);
  a39=(a39*a12);
  a37=(a37+a39);
  a39=(a02*a37);
  a27=(a27+a39);
  a39=(a09*a26);
  a30=(a30*a03);
  a15=(a15*a14);
  a30=(a30+a15);
  a07=(a07*a16);
  a30=(a30+a07);
  a07=(a30*a23);
  a07=(a09+a07);
  a07=(a07*a31);
  a39=(a39+a07);
  a07=(a11*a03);
  a15=(a33*a14);
  a07=(a07+a15);
  a15=(a34*a16);
  a07=(a07+a15);
  a15=(a07*a36);
  a42=(a38*a03);
  a45=(a40*a14);
  a42=(a42+a45);
  a45=(a41*a16);
  a42=(a42+a45);
  a45=(a42*a35);
  a15=(a15+a45);
  a15=(a15*a31);
  a03=(a03*a26);
  a15=(a15+a03);
  a15=(a15*a19);
  a42=(a42*a36);
  a07=(a07*a35);
  a42=(a42-a07);
  a42=(a42*a31);
  a14=(a14*a26);
  a42=(a42+a14);
  a42=(a42*a04);
  a15=(a15+a42);
  a42=(a30*a31);
  a16=(a16*a26);
  a42=(a42+a16);
  a42=(a42*a12);
  a15=(a15+a42);
  a42=(a08*a26);
  a16=(a06*a23);
  a16=(a08+a16);
  a16=(a16*a31);
  a42=(a42+a16);
  a16=(a15*a42);
  a11=(a11*a10);
  a33=(a33*a00);
  a11=(a11+a33);
  a34=(a34*a01);
  a11=(a11+a34);
  a34=(a11*a36);
  a38=(a38*a10);
  a40=(a40*a00);
  a38=(a38+a40);
  a41=(a41*a01);
  a38=(a38+a41);
  a41=(a38*a35);
  a34=(a34+a41);
  a34=(a34*a31);
  a41=(a10*a26);
  a34=(a34+a41);
  a34=(a34*a19);
  a38=(a38*a36);
  a11=(a11*a35);
  a38=(a38-a11);
  a38=(a38*a31);
  a11=(a00*a26);
  a38=(a38+a11);
  a38=(a38*a04);
  a34=(a34+a38);
  a38=(a06*a31);
  a04=(a01*a26);
  a38=(a38+a04);
  a38=(a38*a12);
  a34=(a34+a38);
  a38=(a34*a39);
  a16=(a16-a38);
  a38=(a39*a16);
  a27=(a27+a38);
  a38=(a30*a08);
  a06=(a06*a09);
  a38=(a38-a06);
  a38=(a23*a38);
  a38=(a38*a31);
  a06=(a38*a15);
  a27=(a27-a06);
  a06=(a24*a26);
  a12=(a13*a23);
  a12=(a24+a12);
  a12=(a12*a31);
  a06=(a06+a12);
  a12=(a34*a06);
  a04=(a37*a42);
  a12=(a12-a04);
  a04=(a06*a12);
  a27=(a27-a04);
  if (res[0]!=0) res[0][0]=a27;
  a10=(a10*a20);
  a00=(a00*a17);
  a10=(a10+a00);
  a01=(a01*a22);
  a10=(a10+a01);
  a01=(a24*a10);
  a21=(a08*a21);
  a01=(a01-a21);
  a21=(a01*a26);
  a28=(a28*a09);
  a29=(a29*a24);
  a28=(a28-a29);
  a29=(a24*a28);
  a01=(a01+a29);
  a18=(a08*a18);
  a01=(a01-a18);
  a01=(a01*a31);
  a21=(a21+a01);
  a38=(a38*a34);
  a21=(a21+a38);
  a38=(a37*a39);
  a01=(a15*a06);
  a38=(a38-a01);
  a06=(a06*a38);
  a21=(a21+a06);
  a13=(a13*a09);
  a30=(a30*a24);
  a13=(a13-a30);
  a23=(a23*a13);
  a23=(a23*a31);
  a37=(a23*a37);
  a21=(a21-a37);
  a16=(a42*a16);
  a21=(a21-a16);
  if (res[0]!=0) res[0][1]=a21;
  a25=(a08*a25);
  a10=(a09*a10);
  a25=(a25-a10);
  a26=(a25*a26);
  a08=(a08*a05);
  a25=(a25+a08);
  a09=(a09*a28);
  a25=(a25-a09);
  a25=(a25*a31);
  a26=(a26+a25);
  a23=(a23*a15);
  a26=(a26+a23);
  a42=(a42*a12);
  a26=(a26+a42);
  a02=(a02*a34);
  a26=(a26-a02);
  a39=(a39*a38);
  a26=(a26-a39);
  if (res[0]!=0) res[0][2]=a26;
  return 0;
}

CASADI_SYMBOL_EXPORT int snakecg_sp1_point_bias_acceleration(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem){
  return casadi_f0(arg, res, iw, w, mem);
}

CASADI_SYMBOL_EXPORT int snakecg_sp1_point_bias_acceleration_checkout(void) {
  return 0;
}

CASADI_SYMBOL_EXPORT void snakecg_sp1_point_bias_acceleration_release(int mem) {
}

CASADI_SYMBOL_EXPORT void snakecg_sp1_point_bias_acceleration_incref(void) {
}

CASADI_SYMBOL_EXPORT void snakecg_sp1_point_bias_acceleration_decref(void) {
}

CASADI_SYMBOL_EXPORT casadi_int snakecg_sp1_point_bias_acceleration_n_in(void) { return 5;}

CASADI_SYMBOL_EXPORT casadi_int snakecg_sp1_point_bias_acceleration_n_out(void) { return 1;}

CASADI_SYMBOL_EXPORT casadi_real snakecg_sp1_point_bias_acceleration_default_in(casadi_int i) {
  switch (i) {
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const char* snakecg_sp1_point_bias_acceleration_name_in(casadi_int i) {
  switch (i) {
    case 0: return "q";
    case 1: return "v";
    case 2: return "K";
    case 3: return "link";
    case 4: return "point";
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const char* snakecg_sp1_point_bias_acceleration_name_out(casadi_int i) {
  switch (i) {
    case 0: return "bias";
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const casadi_int* snakecg_sp1_point_bias_acceleration_sparsity_in(casadi_int i) {
  switch (i) {
    case 0: return casadi_s0;
    case 1: return casadi_s1;
    case 2: return casadi_s2;
    case 3: return casadi_s3;
    case 4: return casadi_s4;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const casadi_int* snakecg_sp1_point_bias_acceleration_sparsity_out(casadi_int i) {
  switch (i) {
    case 0: return casadi_s4;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT int snakecg_sp1_point_bias_acceleration_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w) {
  if (sz_arg) *sz_arg = 5;
  if (sz_res) *sz_res = 1;
  if (sz_iw) *sz_iw = 0;
  if (sz_w) *sz_w = 0;
  return 0;
}

CASADI_SYMBOL_EXPORT int snakecg_sp1_point_bias_acceleration_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w) {
  if (sz_arg) *sz_arg = 5*sizeof(const casadi_real*);
  if (sz_res) *sz_res = 1*sizeof(casadi_real*);
  if (sz_iw) *sz_iw = 0*sizeof(casadi_int);
  if (sz_w) *sz_w = 0*sizeof(casadi_real);
  return 0;
}



/* ------------------------------------------------------------------------------------------
 * GENERATED FILE - DO NOT EDIT. Batched drivers rendered from derive/templates/batch.c.j2.
 * snakecg's counterpart of CasADi's Function.map(n, "serial"): one loop in C over n samples,
 * reading inputs in place (input k of sample i at arg[k] + i * stride[k]; stride 0 broadcasts)
 * and writing dense column-major outputs contiguously (output k of sample i at
 * res[k] + i * nnz_out(k)). Returns 0 on success, the failing sample + 1 otherwise, -1 when out of memory.
 * ---------------------------------------------------------------------------------------- */
#include <stdlib.h>

/* Cosines and sines of a block of angles in one loop without calls or branches, which the
 * compiler turns into vector instructions (16 angles per call): the sines and cosines of
 * the angles of 16 samples are computed at once, then the function without its own calls
 * runs per sample.
 * Reduction by pi/2 in three parts (Cody and Waite, exact products for |x| < 2^20 pi/2) and
 * fdlibm's polynomials of sin and cos on [-pi/4, pi/4] (errors below one unit in the last
 * place there); the quadrant turns the pair by n pi/2 with factors 0, +1, -1 (exact). An
 * angle with |x| above SNAKECG_SINCOS_MAX, or not a number, is left to the C library
 * (snakecg_sincos_large). */
#define SNAKECG_SINCOS_BLOCK 16
#define SNAKECG_SINCOS_MAX 8.0e5

#if defined(__GNUC__) && !defined(__clang__) && __GNUC__ >= 6 && defined(__x86_64__) \
    && defined(__linux__)
/* a second copy for processors with AVX2 (four angles per instruction), chosen at load time */
__attribute__((target_clones("avx2", "default")))
#endif
static void snakecg_sincos_block(const casadi_real* restrict x, casadi_real* restrict c,
                                 casadi_real* restrict s) {
  const casadi_real round = 6755399441055744.0; /* 1.5 * 2^52: adding it rounds to integers */
  const casadi_real two_over_pi = 6.36619772367581382433e-01;
  const casadi_real pio2_1 = 1.57079632673412561417e+00; /* pi/2: first 33 bits */
  const casadi_real pio2_2 = 6.07710050630396597660e-11; /* next 33 bits */
  const casadi_real pio2_3 = 2.02226624871116645580e-21; /* the rest */
  const casadi_real S1 = -1.66666666666666324348e-01, S2 = 8.33333333332248946124e-03,
      S3 = -1.98412698298579493134e-04, S4 = 2.75573137070700676789e-06,
      S5 = -2.50507602534068634195e-08, S6 = 1.58969099521155010221e-10;
  const casadi_real C1 = 4.16666666666666019037e-02, C2 = -1.38888888888741095749e-03,
      C3 = 2.48015872894767294178e-05, C4 = -2.75573143513906633035e-07,
      C5 = 2.08757232129817482790e-09, C6 = -1.13596475577881948265e-11;
  int i;
  for (i = 0; i < SNAKECG_SINCOS_BLOCK; ++i) {
    casadi_real n = (x[i] * two_over_pi + round) - round;  /* nearest multiple of pi/2 */
    casadi_real m = n - 4.0 * ((0.25 * n + round) - round); /* n mod 4 in -2..2 */
    casadi_real am = fabs(m);
    casadi_real cq = 1.0 - am, sq = m * (2.0 - am);          /* cos, sin of n pi/2 */
    casadi_real y = ((x[i] - n * pio2_1) - n * pio2_2) - n * pio2_3;
    casadi_real z = y * y;
    casadi_real sy = y + z * y * (S1 + z * (S2 + z * (S3 + z * (S4 + z * (S5 + z * S6)))));
    casadi_real hz = 0.5 * z, w = 1.0 - hz;
    casadi_real cy = w + (((1.0 - w) - hz)
                          + z * z * (C1 + z * (C2 + z * (C3 + z * (C4 + z * (C5 + z * C6))))));
    c[i] = cy * cq - sy * sq;
    s[i] = sy * cq + cy * sq;
  }
}

/* the C library's cos and sin where |x| > SNAKECG_SINCOS_MAX or x is not a number (the
 * driver calls this only when it met such an angle while gathering them) */
static void snakecg_sincos_large(const casadi_real* x, casadi_real* c, casadi_real* s,
                                 casadi_int n) {
  casadi_int i;
  for (i = 0; i < n; ++i) {
    if (!(fabs(x[i]) <= SNAKECG_SINCOS_MAX)) {
      c[i] = cos(x[i]);
      s[i] = sin(x[i]);
    }
  }
}

/* snakecg_sp1_point_bias_acceleration_sincos: 353 CasADi instructions, printed one per line */
static void snakecg_sp1_point_bias_acceleration_sincos(
    const casadi_real* restrict arg0,
    const casadi_real* restrict arg1,
    const casadi_real* restrict arg2,
    const casadi_real* restrict arg3,
    const casadi_real* restrict arg4,
    const casadi_real* restrict arg5,
    const casadi_real* restrict arg6,
    casadi_real* restrict res0) {
  casadi_real w0, w1, w2, w3, w4, w5, w6, w7, w8, w9;
  casadi_real w10, w11, w12, w13, w14, w15, w16, w17, w18, w19;
  casadi_real w20, w21, w22, w23, w24, w25, w26, w27, w28, w29;
  casadi_real w30, w31, w32, w33, w34, w35, w36, w37, w38, w39;
  casadi_real w40, w41, w42, w43, w44, w45;
  w0 = arg0[6];
  w1 = w0 + w0;
  w2 = arg0[5];
  w3 = w1 * w2;
  w4 = arg0[3];
  w5 = w4 + w4;
  w6 = arg0[4];
  w7 = w5 * w6;
  w3 = w3 + w7;
  w8 = arg1[3];
  w9 = w3 * w8;
  w10 = 1.0;
  w11 = (-2.0);
  w12 = w4 * w4;
  w12 = w11 * w12;
  w12 = w10 + w12;
  w13 = w2 * w2;
  w13 = w11 * w13;
  w14 = w12 + w13;
  w15 = arg1[4];
  w16 = w14 * w15;
  w9 = w9 + w16;
  w0 = w11 * w0;
  w16 = w0 * w4;
  w17 = w6 + w6;
  w17 = w17 * w2;
  w16 = w16 + w17;
  w18 = arg1[5];
  w19 = w16 * w18;
  w9 = w9 + w19;
  w19 = w0 * w6;
  w5 = w5 * w2;
  w19 = w19 + w5;
  w20 = arg1[0];
  w21 = w19 * w20;
  w4 = w1 * w4;
  w4 = w4 + w17;
  w17 = arg1[1];
  w22 = w4 * w17;
  w21 = w21 + w22;
  w22 = w6 * w6;
  w11 = w11 * w22;
  w12 = w12 + w11;
  w22 = arg1[2];
  w23 = w12 * w22;
  w21 = w21 + w23;
  w23 = w9 * w21;
  w24 = w19 * w8;
  w25 = w4 * w15;
  w24 = w24 + w25;
  w25 = w12 * w18;
  w24 = w24 + w25;
  w25 = w3 * w20;
  w26 = w14 * w17;
  w25 = w25 + w26;
  w26 = w16 * w22;
  w25 = w25 + w26;
  w26 = w24 * w25;
  w23 = w23 - w26;
  w26 = arg3[0];
  w27 = w23 * w26;
  w28 = arg2[50];
  w29 = w3 * w28;
  w30 = arg2[51];
  w31 = w14 * w30;
  w29 = w29 + w31;
  w31 = arg2[52];
  w32 = w16 * w31;
  w29 = w29 + w32;
  w10 = w10 + w11;
  w10 = w10 + w13;
  w8 = w10 * w8;
  w0 = w0 * w2;
  w0 = w0 + w7;
  w15 = w0 * w15;
  w8 = w8 + w15;
  w1 = w1 * w6;
  w1 = w1 + w5;
  w18 = w1 * w18;
  w8 = w8 + w18;
  w18 = w29 * w8;
  w5 = w10 * w28;
  w6 = w0 * w30;
  w5 = w5 + w6;
  w6 = w1 * w31;
  w5 = w5 + w6;
  w6 = w5 * w9;
  w18 = w18 - w6;
  w6 = w9 * w18;
  w23 = w23 + w6;
  w5 = w5 * w24;
  w28 = w19 * w28;
  w30 = w4 * w30;
  w28 = w28 + w30;
  w31 = w12 * w31;
  w28 = w28 + w31;
  w31 = w28 * w8;
  w5 = w5 - w31;
  w31 = w24 * w5;
  w23 = w23 - w31;
  w31 = arg3[1];
  w23 = w23 * w31;
  w27 = w27 + w23;
  w23 = arg1[6];
  w30 = arg2[47];
  w6 = w30 * w10;
  w15 = arg2[48];
  w7 = w15 * w0;
  w6 = w6 + w7;
  w7 = arg2[49];
  w2 = w7 * w1;
  w6 = w6 + w2;
  w2 = w6 * w24;
  w13 = w30 * w19;
  w11 = w15 * w4;
  w13 = w13 + w11;
  w11 = w7 * w12;
  w13 = w13 + w11;
  w11 = w13 * w8;
  w2 = w2 - w11;
  w2 = w23 * w2;
  w2 = w2 * w31;
  w11 = arg2[41];
  w32 = w11 * w19;
  w33 = arg2[42];
  w34 = w33 * w4;
  w32 = w32 + w34;
  w34 = arg2[43];
  w35 = w34 * w12;
  w32 = w32 + w35;
  w35 = arg5[0];
  w36 = w32 * w35;
  w37 = arg2[44];
  w38 = w37 * w19;
  w39 = arg2[45];
  w40 = w39 * w4;
  w38 = w38 + w40;
  w40 = arg2[46];
  w41 = w40 * w12;
  w38 = w38 + w41;
  w41 = arg6[0];
  w42 = w38 * w41;
  w36 = w36 + w42;
  w36 = w36 * w31;
  w19 = w19 * w26;
  w36 = w36 + w19;
  w19 = arg2[32];
  w19 = w19 * w31;
  w19 = w26 + w19;
  w42 = arg4[0];
  w19 = w19 * w42;
  w43 = arg2[33];
  w43 = w43 * w31;
  w44 = arg4[1];
  w43 = w43 * w44;
  w19 = w19 + w43;
  w43 = arg2[34];
  w43 = w43 * w31;
  w45 = arg4[2];
  w43 = w43 * w45;
  w19 = w19 + w43;
  w36 = w36 * w19;
  w38 = w38 * w35;
  w32 = w32 * w41;
  w38 = w38 - w32;
  w38 = w38 * w31;
  w4 = w4 * w26;
  w38 = w38 + w4;
  w4 = arg2[35];
  w4 = w4 * w31;
  w4 = w4 * w42;
  w32 = arg2[36];
  w32 = w32 * w31;
  w32 = w26 + w32;
  w32 = w32 * w44;
  w4 = w4 + w32;
  w32 = arg2[37];
  w32 = w32 * w31;
  w32 = w32 * w45;
  w4 = w4 + w32;
  w38 = w38 * w4;
  w36 = w36 + w38;
  w38 = w13 * w31;
  w12 = w12 * w26;
  w38 = w38 + w12;
  w12 = arg2[38];
  w12 = w12 * w31;
  w12 = w12 * w42;
  w42 = arg2[39];
  w42 = w42 * w31;
  w42 = w42 * w44;
  w12 = w12 + w42;
  w42 = arg2[40];
  w42 = w42 * w31;
  w42 = w26 + w42;
  w42 = w42 * w45;
  w12 = w12 + w42;
  w38 = w38 * w12;
  w36 = w36 + w38;
  w38 = w2 * w36;
  w27 = w27 + w38;
  w38 = w9 * w26;
  w30 = w30 * w3;
  w15 = w15 * w14;
  w30 = w30 + w15;
  w7 = w7 * w16;
  w30 = w30 + w7;
  w7 = w30 * w23;
  w7 = w9 + w7;
  w7 = w7 * w31;
  w38 = w38 + w7;
  w7 = w11 * w3;
  w15 = w33 * w14;
  w7 = w7 + w15;
  w15 = w34 * w16;
  w7 = w7 + w15;
  w15 = w7 * w35;
  w42 = w37 * w3;
  w45 = w39 * w14;
  w42 = w42 + w45;
  w45 = w40 * w16;
  w42 = w42 + w45;
  w45 = w42 * w41;
  w15 = w15 + w45;
  w15 = w15 * w31;
  w3 = w3 * w26;
  w15 = w15 + w3;
  w15 = w15 * w19;
  w42 = w42 * w35;
  w7 = w7 * w41;
  w42 = w42 - w7;
  w42 = w42 * w31;
  w14 = w14 * w26;
  w42 = w42 + w14;
  w42 = w42 * w4;
  w15 = w15 + w42;
  w42 = w30 * w31;
  w16 = w16 * w26;
  w42 = w42 + w16;
  w42 = w42 * w12;
  w15 = w15 + w42;
  w42 = w8 * w26;
  w16 = w6 * w23;
  w16 = w8 + w16;
  w16 = w16 * w31;
  w42 = w42 + w16;
  w16 = w15 * w42;
  w11 = w11 * w10;
  w33 = w33 * w0;
  w11 = w11 + w33;
  w34 = w34 * w1;
  w11 = w11 + w34;
  w34 = w11 * w35;
  w37 = w37 * w10;
  w39 = w39 * w0;
  w37 = w37 + w39;
  w40 = w40 * w1;
  w37 = w37 + w40;
  w40 = w37 * w41;
  w34 = w34 + w40;
  w34 = w34 * w31;
  w40 = w10 * w26;
  w34 = w34 + w40;
  w34 = w34 * w19;
  w37 = w37 * w35;
  w11 = w11 * w41;
  w37 = w37 - w11;
  w37 = w37 * w31;
  w11 = w0 * w26;
  w37 = w37 + w11;
  w37 = w37 * w4;
  w34 = w34 + w37;
  w37 = w6 * w31;
  w4 = w1 * w26;
  w37 = w37 + w4;
  w37 = w37 * w12;
  w34 = w34 + w37;
  w37 = w34 * w38;
  w16 = w16 - w37;
  w37 = w38 * w16;
  w27 = w27 + w37;
  w37 = w30 * w8;
  w6 = w6 * w9;
  w37 = w37 - w6;
  w37 = w23 * w37;
  w37 = w37 * w31;
  w6 = w37 * w15;
  w27 = w27 - w6;
  w6 = w24 * w26;
  w12 = w13 * w23;
  w12 = w24 + w12;
  w12 = w12 * w31;
  w6 = w6 + w12;
  w12 = w34 * w6;
  w4 = w36 * w42;
  w12 = w12 - w4;
  w4 = w6 * w12;
  w27 = w27 - w4;
  res0[0] = w27;
  w10 = w10 * w20;
  w0 = w0 * w17;
  w10 = w10 + w0;
  w1 = w1 * w22;
  w10 = w10 + w1;
  w1 = w24 * w10;
  w21 = w8 * w21;
  w1 = w1 - w21;
  w21 = w1 * w26;
  w28 = w28 * w9;
  w29 = w29 * w24;
  w28 = w28 - w29;
  w29 = w24 * w28;
  w1 = w1 + w29;
  w18 = w8 * w18;
  w1 = w1 - w18;
  w1 = w1 * w31;
  w21 = w21 + w1;
  w37 = w37 * w34;
  w21 = w21 + w37;
  w37 = w36 * w38;
  w1 = w15 * w6;
  w37 = w37 - w1;
  w6 = w6 * w37;
  w21 = w21 + w6;
  w13 = w13 * w9;
  w30 = w30 * w24;
  w13 = w13 - w30;
  w23 = w23 * w13;
  w23 = w23 * w31;
  w36 = w23 * w36;
  w21 = w21 - w36;
  w16 = w42 * w16;
  w21 = w21 - w16;
  res0[1] = w21;
  w25 = w8 * w25;
  w10 = w9 * w10;
  w25 = w25 - w10;
  w26 = w25 * w26;
  w8 = w8 * w5;
  w25 = w25 + w8;
  w9 = w9 * w28;
  w25 = w25 - w9;
  w25 = w25 * w31;
  w26 = w26 + w25;
  w23 = w23 * w15;
  w26 = w26 + w23;
  w42 = w42 * w12;
  w26 = w26 + w42;
  w2 = w2 * w34;
  w26 = w26 - w2;
  w38 = w38 * w37;
  w26 = w26 - w38;
  res0[2] = w26;
}


CASADI_SYMBOL_EXPORT int snakecg_sp1_batch_point_bias_acceleration(casadi_int n, const casadi_real** arg,
    const casadi_int* stride, casadi_real** res) {
  const casadi_real* a[5];
  casadi_real* r[1];
  casadi_int* iw = (casadi_int*) malloc(sizeof(casadi_int) * 1);
  casadi_real* w = (casadi_real*) malloc(sizeof(casadi_real) * 47);
  casadi_int i, k;
  int status = 0;
  if (!iw || !w) { free(iw); free(w); return -1; }
  for (k = 0; k < 5; ++k) a[k] = 0;
  for (k = 0; k < 1; ++k) r[k] = 0;
  if (arg[0] && arg[1] && arg[2] && arg[3] && arg[4] && res[0]) {
    /* cos and sin of q[7..7] of 16 samples at a time, then snakecg_sp1_point_bias_acceleration_sincos
     * per sample (a batch of one too, so that a batch equals its samples one by one) */
    const casadi_int na = 1, per = 16;
    casadi_real ang[16], ca[16], sa[16];
    casadi_int i0, m;
    int large;
    for (k = 0; k < 16; ++k) ang[k] = 0;
    for (i0 = 0; i0 < n; i0 += per) {
      m = n - i0 < per ? n - i0 : per;
      large = 0;
      for (i = 0; i < m; ++i) {
        const casadi_real* q = arg[0] + (i0 + i) * stride[0] + 7;
        for (k = 0; k < na; ++k) {
          ang[i * na + k] = q[k];
          large |= !(fabs(q[k]) <= SNAKECG_SINCOS_MAX);
        }
      }
      for (k = 0; k < m * na; k += SNAKECG_SINCOS_BLOCK) {
        snakecg_sincos_block(ang + k, ca + k, sa + k);
      }
      if (large) snakecg_sincos_large(ang, ca, sa, m * na);
      for (i = 0; i < m; ++i) {
        snakecg_sp1_point_bias_acceleration_sincos(arg[0] + (i0 + i) * stride[0], arg[1] + (i0 + i) * stride[1], arg[2] + (i0 + i) * stride[2], arg[3] + (i0 + i) * stride[3], arg[4] + (i0 + i) * stride[4], ca + i * na, sa + i * na, res[0] + (i0 + i) * 3);
      }
    }
  } else {
    /* a null input or output (CasADi's convention: zeros in, nothing out): per sample */
    for (i = 0; i < n; ++i) {
      a[0] = arg[0] + i * stride[0];
      a[1] = arg[1] + i * stride[1];
      a[2] = arg[2] + i * stride[2];
      a[3] = arg[3] + i * stride[3];
      a[4] = arg[4] + i * stride[4];
      r[0] = res[0] + i * 3;
      if (snakecg_sp1_point_bias_acceleration(a, r, iw, w, 0)) { status = (int) (i + 1); break; }
    }
  }
  free(iw);
  free(w);
  return status;
}
