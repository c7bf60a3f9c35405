/* GENERATED FILE - DO NOT EDIT. C code emitted by CasADi for ground_rows() of
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
  #define CASADI_PREFIX(ID) snakecg_sp1_ground_rows_ ## ID
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
#define casadi_s5 CASADI_PREFIX(s5)
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
CASADI_SYMBOL_EXPORT void snakecg_sp1_ground_rows_casadi_version(int* major, int* minor, int* patch) {
  *major = 3;
  *minor = 8;
  *patch = 2;
}
CASADI_SYMBOL_EXPORT int snakecg_sp1_ground_rows_casadi_int_size(void) { return (int) sizeof(casadi_int); }
CASADI_SYMBOL_EXPORT int snakecg_sp1_ground_rows_casadi_real_size(void) { return (int) sizeof(casadi_real); }

static const casadi_int casadi_s0[3] = {8, 1, 1};
static const casadi_int casadi_s1[3] = {7, 1, 1};
static const casadi_int casadi_s2[3] = {71, 1, 1};
static const casadi_int casadi_s3[3] = {6, 1, 1};
static const casadi_int casadi_s4[3] = {2, 7, 1};
static const casadi_int casadi_s5[3] = {2, 1, 1};

/* snakecg_sp1_ground_rows:(q[8],v[7],K[71],support_points[6])->(A[2x7],adot_v[2],height[2]) */
static int casadi_f0(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem) {
  casadi_real a00, a01, a02, a03, a04, a05, a06, a07, a08, a09, a10, a11;
  casadi_real a12, a13, a14, a15, a16, a17, a18, a19, a20, a21, a22, a23;
  casadi_real a24, a25, a26, a27, a28, a29, a30, a31, a32, a33, a34, a35;
  casadi_real a36, a37, a38, a39, a40, a41, a42, a43, a44, a45;
  a00=-2.;
  a01=arg[0]? arg[0][6] : 0;
  a02=(a00*a01);
  a03=arg[0]? arg[0][4] : 0;
  a04=(a02*a03);
  a05=arg[0]? arg[0][3] : 0;
  a06=(2.*a05);
  a07=arg[0]? arg[0][5] : 0;
  a08=(a06*a07);
  a04=(a04+a08);
  if (res[0]!=0) res[0][0]=a04;
  if (res[0]!=0) res[0][1]=a04;
  a01=(2.*a01);
  a09=(a01*a05);
  a10=(2.*a03);
  a10=(a10*a07);
  a09=(a09+a10);
  if (res[0]!=0) res[0][2]=a09;
  if (res[0]!=0) res[0][3]=a09;
  a11=1.;
  a12=casadi_sq(a05);
  a12=(a00*a12);
  a12=(a11+a12);
  a13=casadi_sq(a03);
  a13=(a00*a13);
  a14=(a12+a13);
  if (res[0]!=0) res[0][4]=a14;
  if (res[0]!=0) res[0][5]=a14;
  a11=(a11+a13);
  a13=casadi_sq(a07);
  a00=(a00*a13);
  a11=(a11+a00);
  a13=(a01*a07);
  a06=(a06*a03);
  a13=(a13+a06);
  a15=arg[3]? arg[3][0] : 0;
  a16=(a13*a15);
  a12=(a12+a00);
  a00=arg[3]? arg[3][1] : 0;
  a17=(a12*a00);
  a16=(a16+a17);
  a05=(a02*a05);
  a05=(a05+a10);
  a10=arg[3]? arg[3][2] : 0;
  a17=(a05*a10);
  a16=(a16+a17);
  a17=(a11*a16);
  a18=(a11*a15);
  a02=(a02*a07);
  a02=(a02+a06);
  a06=(a02*a00);
  a18=(a18+a06);
  a01=(a01*a03);
  a01=(a01+a08);
  a08=(a01*a10);
  a18=(a18+a08);
  a08=(a13*a18);
  a17=(a17-a08);
  if (res[0]!=0) res[0][6]=a17;
  a17=arg[2]? arg[2][47] : 0;
  a08=(a17*a13);
  a03=arg[2]? arg[2][48] : 0;
  a06=(a03*a12);
  a08=(a08+a06);
  a06=arg[2]? arg[2][49] : 0;
  a07=(a06*a05);
  a08=(a08+a07);
  a07=arg[2]? arg[2][38] : 0;
  a19=arg[3]? arg[3][3] : 0;
  a07=(a07*a19);
  a20=arg[2]? arg[2][39] : 0;
  a21=arg[3]? arg[3][4] : 0;
  a20=(a20*a21);
  a07=(a07+a20);
  a20=arg[2]? arg[2][40] : 0;
  a22=arg[3]? arg[3][5] : 0;
  a20=(a20*a22);
  a07=(a07+a20);
  a20=(a08*a07);
  a23=arg[2]? arg[2][41] : 0;
  a24=(a23*a13);
  a25=arg[2]? arg[2][42] : 0;
  a26=(a25*a12);
  a24=(a24+a26);
  a26=arg[2]? arg[2][43] : 0;
  a27=(a26*a05);
  a24=(a24+a27);
  a27=arg[0]? arg[0][7] : 0;
  a28=cos(a27);
  a29=(a24*a28);
  a30=arg[2]? arg[2][44] : 0;
  a31=(a30*a13);
  a32=arg[2]? arg[2][45] : 0;
  a33=(a32*a12);
  a31=(a31+a33);
  a33=arg[2]? arg[2][46] : 0;
  a34=(a33*a05);
  a31=(a31+a34);
  a27=sin(a27);
  a34=(a31*a27);
  a29=(a29+a34);
  a34=arg[2]? arg[2][32] : 0;
  a34=(a34*a19);
  a35=arg[2]? arg[2][33] : 0;
  a35=(a35*a21);
  a34=(a34+a35);
  a35=arg[2]? arg[2][34] : 0;
  a35=(a35*a22);
  a34=(a34+a35);
  a29=(a29*a34);
  a20=(a20+a29);
  a31=(a31*a28);
  a24=(a24*a27);
  a31=(a31-a24);
  a24=arg[2]? arg[2][35] : 0;
  a24=(a24*a19);
  a19=arg[2]? arg[2][36] : 0;
  a19=(a19*a21);
  a24=(a24+a19);
  a19=arg[2]? arg[2][37] : 0;
  a19=(a19*a22);
  a24=(a24+a19);
  a31=(a31*a24);
  a20=(a20+a31);
  a31=arg[2]? arg[2][50] : 0;
  a19=(a13*a31);
  a22=arg[2]? arg[2][51] : 0;
  a21=(a12*a22);
  a19=(a19+a21);
  a21=arg[2]? arg[2][52] : 0;
  a29=(a05*a21);
  a19=(a19+a29);
  a29=arg[0]? arg[0][1] : 0;
  a35=(a19+a29);
  a35=(a20+a35);
  a35=(a35-a29);
  a29=(a11*a35);
  a36=(a17*a11);
  a37=(a03*a02);
  a36=(a36+a37);
  a37=(a06*a01);
  a36=(a36+a37);
  a37=(a36*a07);
  a38=(a23*a11);
  a39=(a25*a02);
  a38=(a38+a39);
  a39=(a26*a01);
  a38=(a38+a39);
  a39=(a38*a28);
  a40=(a30*a11);
  a41=(a32*a02);
  a40=(a40+a41);
  a41=(a33*a01);
  a40=(a40+a41);
  a41=(a40*a27);
  a39=(a39+a41);
  a39=(a39*a34);
  a37=(a37+a39);
  a40=(a40*a28);
  a38=(a38*a27);
  a40=(a40-a38);
  a40=(a40*a24);
  a37=(a37+a40);
  a40=(a11*a31);
  a38=(a02*a22);
  a40=(a40+a38);
  a38=(a01*a21);
  a40=(a40+a38);
  a38=arg[0]? arg[0][0] : 0;
  a39=(a40+a38);
  a39=(a37+a39);
  a39=(a39-a38);
  a38=(a13*a39);
  a29=(a29-a38);
  if (res[0]!=0) res[0][7]=a29;
  a29=(a02*a16);
  a38=(a12*a18);
  a29=(a29-a38);
  if (res[0]!=0) res[0][8]=a29;
  a29=(a02*a35);
  a38=(a12*a39);
  a29=(a29-a38);
  if (res[0]!=0) res[0][9]=a29;
  a29=(a01*a16);
  a38=(a05*a18);
  a29=(a29-a38);
  if (res[0]!=0) res[0][10]=a29;
  a35=(a01*a35);
  a39=(a05*a39);
  a35=(a35-a39);
  if (res[0]!=0) res[0][11]=a35;
  a35=0.;
  if (res[0]!=0) res[0][12]=a35;
  a35=(a36*a20);
  a39=(a08*a37);
  a35=(a35-a39);
  if (res[0]!=0) res[0][13]=a35;
  a35=arg[1]? arg[1][3] : 0;
  a39=(a11*a35);
  a29=arg[1]? arg[1][4] : 0;
  a38=(a02*a29);
  a39=(a39+a38);
  a38=arg[1]? arg[1][5] : 0;
  a41=(a01*a38);
  a39=(a39+a41);
  a41=arg[1]? arg[1][0] : 0;
  a42=(a13*a41);
  a43=arg[1]? arg[1][1] : 0;
  a44=(a12*a43);
  a42=(a42+a44);
  a44=arg[1]? arg[1][2] : 0;
  a45=(a05*a44);
  a42=(a42+a45);
  a42=(a39*a42);
  a13=(a13*a35);
  a12=(a12*a29);
  a13=(a13+a12);
  a05=(a05*a38);
  a13=(a13+a05);
  a11=(a11*a41);
  a02=(a02*a43);
  a11=(a11+a02);
  a01=(a01*a44);
  a11=(a11+a01);
  a11=(a13*a11);
  a42=(a42-a11);
  a35=(a04*a35);
  a29=(a09*a29);
  a35=(a35+a29);
  a38=(a14*a38);
  a35=(a35+a38);
  a18=(a18*a35);
  a15=(a04*a15);
  a00=(a09*a00);
  a15=(a15+a00);
  a10=(a14*a10);
  a15=(a15+a10);
  a10=(a15*a39);
  a18=(a18-a10);
  a18=(a18*a39);
  a18=(a42+a18);
  a10=(a15*a13);
  a16=(a16*a35);
  a10=(a10-a16);
  a10=(a10*a13);
  a18=(a18-a10);
  if (res[1]!=0) res[1][0]=a18;
  a40=(a40*a35);
  a31=(a04*a31);
  a22=(a09*a22);
  a31=(a31+a22);
  a21=(a14*a21);
  a31=(a31+a21);
  a21=(a31*a39);
  a40=(a40-a21);
  a40=(a39*a40);
  a42=(a42+a40);
  a40=(a31*a13);
  a19=(a19*a35);
  a40=(a40-a19);
  a40=(a13*a40);
  a42=(a42-a40);
  a40=arg[1]? arg[1][6] : 0;
  a17=(a17*a04);
  a03=(a03*a09);
  a17=(a17+a03);
  a06=(a06*a14);
  a17=(a17+a06);
  a06=(a17*a13);
  a03=(a08*a35);
  a06=(a06-a03);
  a06=(a40*a06);
  a06=(a06*a20);
  a42=(a42+a06);
  a06=(a17*a40);
  a06=(a35+a06);
  a03=(a37*a06);
  a07=(a17*a07);
  a23=(a23*a04);
  a25=(a25*a09);
  a23=(a23+a25);
  a26=(a26*a14);
  a23=(a23+a26);
  a26=(a23*a28);
  a30=(a30*a04);
  a32=(a32*a09);
  a30=(a30+a32);
  a33=(a33*a14);
  a30=(a30+a33);
  a33=(a30*a27);
  a26=(a26+a33);
  a26=(a26*a34);
  a07=(a07+a26);
  a30=(a30*a28);
  a23=(a23*a27);
  a30=(a30-a23);
  a30=(a30*a24);
  a07=(a07+a30);
  a30=(a36*a40);
  a30=(a39+a30);
  a24=(a07*a30);
  a03=(a03-a24);
  a03=(a03*a30);
  a42=(a42+a03);
  a36=(a36*a35);
  a17=(a17*a39);
  a36=(a36-a17);
  a36=(a40*a36);
  a36=(a36*a37);
  a42=(a42-a36);
  a08=(a08*a40);
  a13=(a13+a08);
  a08=(a07*a13);
  a20=(a20*a06);
  a08=(a08-a20);
  a08=(a08*a13);
  a42=(a42-a08);
  if (res[1]!=0) res[1][1]=a42;
  a42=arg[0]? arg[0][2] : 0;
  a15=(a15+a42);
  if (res[2]!=0) res[2][0]=a15;
  a31=(a31+a42);
  a07=(a07+a31);
  if (res[2]!=0) res[2][1]=a07;
  return 0;
}

CASADI_SYMBOL_EXPORT int snakecg_sp1_ground_rows(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem){
  return casadi_f0(arg, res, iw, w, mem);
}

CASADI_SYMBOL_EXPORT int snakecg_sp1_ground_rows_checkout(void) {
  return 0;
}

CASADI_SYMBOL_EXPORT void snakecg_sp1_ground_rows_release(int mem) {
}

CASADI_SYMBOL_EXPORT void snakecg_sp1_ground_rows_incref(void) {
}

CASADI_SYMBOL_EXPORT void snakecg_sp1_ground_rows_decref(void) {
}

CASADI_SYMBOL_EXPORT casadi_int snakecg_sp1_ground_rows_n_in(void) { return 4;}

CASADI_SYMBOL_EXPORT casadi_int snakecg_sp1_ground_rows_n_out(void) { return 3;}

CASADI_SYMBOL_EXPORT casadi_real snakecg_sp1_ground_rows_default_in(casadi_int i) {
  switch (i) {
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const char* snakecg_sp1_ground_rows_name_in(casadi_int i) {
  switch (i) {
    case 0: return "q";
    case 1: return "v";
    case 2: return "K";
    case 3: return "support_points";
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const char* snakecg_sp1_ground_rows_name_out(casadi_int i) {
  switch (i) {
    case 0: return "A";
    case 1: return "adot_v";
    case 2: return "height";
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const casadi_int* snakecg_sp1_ground_rows_sparsity_in(casadi_int i) {
  switch (i) {
    case 0: return casadi_s0;
    case 1: return casadi_s1;
    case 2: return casadi_s2;
    case 3: return casadi_s3;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const casadi_int* snakecg_sp1_ground_rows_sparsity_out(casadi_int i) {
  switch (i) {
    case 0: return casadi_s4;
    case 1: return casadi_s5;
    case 2: return casadi_s5;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT int snakecg_sp1_ground_rows_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w) {
  if (sz_arg) *sz_arg = 4;
  if (sz_res) *sz_res = 3;
  if (sz_iw) *sz_iw = 0;
  if (sz_w) *sz_w = 0;
  return 0;
}

CASADI_SYMBOL_EXPORT int snakecg_sp1_ground_rows_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w) {
  if (sz_arg) *sz_arg = 4*sizeof(const casadi_real*);
  if (sz_res) *sz_res = 3*sizeof(casadi_real*);
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

/* snakecg_sp1_ground_rows_sincos: 323 CasADi instructions, printed one per line */
static void snakecg_sp1_ground_rows_sincos(
    const casadi_real* restrict arg0,
    const casadi_real* restrict arg1,
    const casadi_real* restrict arg2,
    const casadi_real* restrict arg3,
    const casadi_real* restrict arg4,
    const casadi_real* restrict arg5,
    casadi_real* restrict res0,
    casadi_real* restrict res1,
    casadi_real* restrict res2) {
  casadi_real w0, w1, w2, w3, w4, w5, w6, w7, w8, w9;
  casadi_real w10, w11, w12, w13, w14, w15, w16, w17, w18, w19;
  casadi_real w20, w21, w22, w23, w24, w25, w26, w27, w28, w29;
  casadi_real w30, w31, w32, w33, w34, w35, w36, w37, w38, w39;
  casadi_real w40, w41, w42, w43, w44, w45;
  w0 = (-2.0);
  w1 = arg0[6];
  w2 = w0 * w1;
  w3 = arg0[4];
  w4 = w2 * w3;
  w5 = arg0[3];
  w6 = w5 + w5;
  w7 = arg0[5];
  w8 = w6 * w7;
  w4 = w4 + w8;
  res0[0] = w4;
  res0[1] = w4;
  w1 = w1 + w1;
  w9 = w1 * w5;
  w10 = w3 + w3;
  w10 = w10 * w7;
  w9 = w9 + w10;
  res0[2] = w9;
  res0[3] = w9;
  w11 = 1.0;
  w12 = w5 * w5;
  w12 = w0 * w12;
  w12 = w11 + w12;
  w13 = w3 * w3;
  w13 = w0 * w13;
  w14 = w12 + w13;
  res0[4] = w14;
  res0[5] = w14;
  w11 = w11 + w13;
  w13 = w7 * w7;
  w0 = w0 * w13;
  w11 = w11 + w0;
  w13 = w1 * w7;
  w6 = w6 * w3;
  w13 = w13 + w6;
  w15 = arg3[0];
  w16 = w13 * w15;
  w12 = w12 + w0;
  w0 = arg3[1];
  w17 = w12 * w0;
  w16 = w16 + w17;
  w5 = w2 * w5;
  w5 = w5 + w10;
  w10 = arg3[2];
  w17 = w5 * w10;
  w16 = w16 + w17;
  w17 = w11 * w16;
  w18 = w11 * w15;
  w2 = w2 * w7;
  w2 = w2 + w6;
  w6 = w2 * w0;
  w18 = w18 + w6;
  w1 = w1 * w3;
  w1 = w1 + w8;
  w8 = w1 * w10;
  w18 = w18 + w8;
  w8 = w13 * w18;
  w17 = w17 - w8;
  res0[6] = w17;
  w17 = arg2[47];
  w8 = w17 * w13;
  w3 = arg2[48];
  w6 = w3 * w12;
  w8 = w8 + w6;
  w6 = arg2[49];
  w7 = w6 * w5;
  w8 = w8 + w7;
  w7 = arg2[38];
  w19 = arg3[3];
  w7 = w7 * w19;
  w20 = arg2[39];
  w21 = arg3[4];
  w20 = w20 * w21;
  w7 = w7 + w20;
  w20 = arg2[40];
  w22 = arg3[5];
  w20 = w20 * w22;
  w7 = w7 + w20;
  w20 = w8 * w7;
  w23 = arg2[41];
  w24 = w23 * w13;
  w25 = arg2[42];
  w26 = w25 * w12;
  w24 = w24 + w26;
  w26 = arg2[43];
  w27 = w26 * w5;
  w24 = w24 + w27;
  w27 = arg4[0];
  w28 = w24 * w27;
  w29 = arg2[44];
  w30 = w29 * w13;
  w31 = arg2[45];
  w32 = w31 * w12;
  w30 = w30 + w32;
  w32 = arg2[46];
  w33 = w32 * w5;
  w30 = w30 + w33;
  w33 = arg5[0];
  w34 = w30 * w33;
  w28 = w28 + w34;
  w34 = arg2[32];
  w34 = w34 * w19;
  w35 = arg2[33];
  w35 = w35 * w21;
  w34 = w34 + w35;
  w35 = arg2[34];
  w35 = w35 * w22;
  w34 = w34 + w35;
  w28 = w28 * w34;
  w20 = w20 + w28;
  w30 = w30 * w27;
  w24 = w24 * w33;
  w30 = w30 - w24;
  w24 = arg2[35];
  w24 = w24 * w19;
  w19 = arg2[36];
  w19 = w19 * w21;
  w24 = w24 + w19;
  w19 = arg2[37];
  w19 = w19 * w22;
  w24 = w24 + w19;
  w30 = w30 * w24;
  w20 = w20 + w30;
  w30 = arg2[50];
  w19 = w13 * w30;
  w22 = arg2[51];
  w21 = w12 * w22;
  w19 = w19 + w21;
  w21 = arg2[52];
  w28 = w5 * w21;
  w19 = w19 + w28;
  w28 = arg0[1];
  w35 = w19 + w28;
  w35 = w20 + w35;
  w35 = w35 - w28;
  w28 = w11 * w35;
  w36 = w17 * w11;
  w37 = w3 * w2;
  w36 = w36 + w37;
  w37 = w6 * w1;
  w36 = w36 + w37;
  w37 = w36 * w7;
  w38 = w23 * w11;
  w39 = w25 * w2;
  w38 = w38 + w39;
  w39 = w26 * w1;
  w38 = w38 + w39;
  w39 = w38 * w27;
  w40 = w29 * w11;
  w41 = w31 * w2;
  w40 = w40 + w41;
  w41 = w32 * w1;
  w40 = w40 + w41;
  w41 = w40 * w33;
  w39 = w39 + w41;
  w39 = w39 * w34;
  w37 = w37 + w39;
  w40 = w40 * w27;
  w38 = w38 * w33;
  w40 = w40 - w38;
  w40 = w40 * w24;
  w37 = w37 + w40;
  w40 = w11 * w30;
  w38 = w2 * w22;
  w40 = w40 + w38;
  w38 = w1 * w21;
  w40 = w40 + w38;
  w38 = arg0[0];
  w39 = w40 + w38;
  w39 = w37 + w39;
  w39 = w39 - w38;
  w38 = w13 * w39;
  w28 = w28 - w38;
  res0[7] = w28;
  w28 = w2 * w16;
  w38 = w12 * w18;
  w28 = w28 - w38;
  res0[8] = w28;
  w28 = w2 * w35;
  w38 = w12 * w39;
  w28 = w28 - w38;
  res0[9] = w28;
  w28 = w1 * w16;
  w38 = w5 * w18;
  w28 = w28 - w38;
  res0[10] = w28;
  w35 = w1 * w35;
  w39 = w5 * w39;
  w35 = w35 - w39;
  res0[11] = w35;
  w35 = 0.0;
  res0[12] = w35;
  w35 = w36 * w20;
  w39 = w8 * w37;
  w35 = w35 - w39;
  res0[13] = w35;
  w35 = arg1[3];
  w39 = w11 * w35;
  w28 = arg1[4];
  w38 = w2 * w28;
  w39 = w39 + w38;
  w38 = arg1[5];
  w41 = w1 * w38;
  w39 = w39 + w41;
  w41 = arg1[0];
  w42 = w13 * w41;
  w43 = arg1[1];
  w44 = w12 * w43;
  w42 = w42 + w44;
  w44 = arg1[2];
  w45 = w5 * w44;
  w42 = w42 + w45;
  w42 = w39 * w42;
  w13 = w13 * w35;
  w12 = w12 * w28;
  w13 = w13 + w12;
  w5 = w5 * w38;
  w13 = w13 + w5;
  w11 = w11 * w41;
  w2 = w2 * w43;
  w11 = w11 + w2;
  w1 = w1 * w44;
  w11 = w11 + w1;
  w11 = w13 * w11;
  w42 = w42 - w11;
  w35 = w4 * w35;
  w28 = w9 * w28;
  w35 = w35 + w28;
  w38 = w14 * w38;
  w35 = w35 + w38;
  w18 = w18 * w35;
  w15 = w4 * w15;
  w0 = w9 * w0;
  w15 = w15 + w0;
  w10 = w14 * w10;
  w15 = w15 + w10;
  w10 = w15 * w39;
  w18 = w18 - w10;
  w18 = w18 * w39;
  w18 = w42 + w18;
  w10 = w15 * w13;
  w16 = w16 * w35;
  w10 = w10 - w16;
  w10 = w10 * w13;
  w18 = w18 - w10;
  res1[0] = w18;
  w40 = w40 * w35;
  w30 = w4 * w30;
  w22 = w9 * w22;
  w30 = w30 + w22;
  w21 = w14 * w21;
  w30 = w30 + w21;
  w21 = w30 * w39;
  w40 = w40 - w21;
  w40 = w39 * w40;
  w42 = w42 + w40;
  w40 = w30 * w13;
  w19 = w19 * w35;
  w40 = w40 - w19;
  w40 = w13 * w40;
  w42 = w42 - w40;
  w40 = arg1[6];
  w17 = w17 * w4;
  w3 = w3 * w9;
  w17 = w17 + w3;
  w6 = w6 * w14;
  w17 = w17 + w6;
  w6 = w17 * w13;
  w3 = w8 * w35;
  w6 = w6 - w3;
  w6 = w40 * w6;
  w6 = w6 * w20;
  w42 = w42 + w6;
  w6 = w17 * w40;
  w6 = w35 + w6;
  w3 = w37 * w6;
  w7 = w17 * w7;
  w23 = w23 * w4;
  w25 = w25 * w9;
  w23 = w23 + w25;
  w26 = w26 * w14;
  w23 = w23 + w26;
  w26 = w23 * w27;
  w29 = w29 * w4;
  w31 = w31 * w9;
  w29 = w29 + w31;
  w32 = w32 * w14;
  w29 = w29 + w32;
  w32 = w29 * w33;
  w26 = w26 + w32;
  w26 = w26 * w34;
  w7 = w7 + w26;
  w29 = w29 * w27;
  w23 = w23 * w33;
  w29 = w29 - w23;
  w29 = w29 * w24;
  w7 = w7 + w29;
  w29 = w36 * w40;
  w29 = w39 + w29;
  w24 = w7 * w29;
  w3 = w3 - w24;
  w3 = w3 * w29;
  w42 = w42 + w3;
  w36 = w36 * w35;
  w17 = w17 * w39;
  w36 = w36 - w17;
  w36 = w40 * w36;
  w36 = w36 * w37;
  w42 = w42 - w36;
  w8 = w8 * w40;
  w13 = w13 + w8;
  w8 = w7 * w13;
  w20 = w20 * w6;
  w8 = w8 - w20;
  w8 = w8 * w13;
  w42 = w42 - w8;
  res1[1] = w42;
  w42 = arg0[2];
  w15 = w15 + w42;
  res2[0] = w15;
  w30 = w30 + w42;
  w7 = w7 + w30;
  res2[1] = w7;
}


CASADI_SYMBOL_EXPORT int snakecg_sp1_batch_ground_rows(casadi_int n, const casadi_real** arg,
    const casadi_int* stride, casadi_real** res) {
  const casadi_real* a[4];
  casadi_real* r[3];
  casadi_int* iw = (casadi_int*) malloc(sizeof(casadi_int) * 1);
  casadi_real* w = (casadi_real*) malloc(sizeof(casadi_real) * 47);
  casadi_int i, k;
  int status = 0;
  if (!iw || !w) { free(iw); free(w); return -1; }
  for (k = 0; k < 4; ++k) a[k] = 0;
  for (k = 0; k < 3; ++k) r[k] = 0;
  if (arg[0] && arg[1] && arg[2] && arg[3] && res[0] && res[1] && res[2]) {
    /* cos and sin of q[7..7] of 16 samples at a time, then snakecg_sp1_ground_rows_sincos
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
        snakecg_sp1_ground_rows_sincos(arg[0] + (i0 + i) * stride[0], arg[1] + (i0 + i) * stride[1], arg[2] + (i0 + i) * stride[2], arg[3] + (i0 + i) * stride[3], ca + i * na, sa + i * na, res[0] + (i0 + i) * 14, res[1] + (i0 + i) * 2, res[2] + (i0 + i) * 2);
      }
    }
  } else {
    /* a null input or output (CasADi's convention: zeros in, nothing out): per sample */
    for (i = 0; i < n; ++i) {
      a[0] = arg[0] + i * stride[0];
      a[1] = arg[1] + i * stride[1];
      a[2] = arg[2] + i * stride[2];
      a[3] = arg[3] + i * stride[3];
      r[0] = res[0] + i * 14;
      r[1] = res[1] + i * 2;
      r[2] = res[2] + i * 2;
      if (snakecg_sp1_ground_rows(a, r, iw, w, 0)) { status = (int) (i + 1); break; }
    }
  }
  free(iw);
  free(w);
  return status;
}
