/* GENERATED FILE - DO NOT EDIT. C code emitted by CasADi for point_jacobian() of
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
  #define CASADI_PREFIX(ID) snakecg_sp1_point_jacobian_ ## ID
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
CASADI_SYMBOL_EXPORT void snakecg_sp1_point_jacobian_casadi_version(int* major, int* minor, int* patch) {
  *major = 3;
  *minor = 8;
  *patch = 2;
}
CASADI_SYMBOL_EXPORT int snakecg_sp1_point_jacobian_casadi_int_size(void) { return (int) sizeof(casadi_int); }
CASADI_SYMBOL_EXPORT int snakecg_sp1_point_jacobian_casadi_real_size(void) { return (int) sizeof(casadi_real); }

static const casadi_int casadi_s0[3] = {8, 1, 1};
static const casadi_int casadi_s1[3] = {71, 1, 1};
static const casadi_int casadi_s2[3] = {2, 1, 1};
static const casadi_int casadi_s3[3] = {3, 1, 1};
static const casadi_int casadi_s4[3] = {3, 7, 1};

/* snakecg_sp1_point_jacobian:(q[8],K[71],link[2],point[3])->(position[3],J[3x7]) */
static int casadi_f0(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem) {
  casadi_real a00, a01, a02, a03, a04, a05, a06, a07, a08, a09, a10, a11;
  casadi_real a12, a13, a14, a15, a16, a17, a18, a19, a20, a21, a22, a23;
  casadi_real a24, a25, a26, a27, a28, a29, a30, a31, a32, a33, a34, a35;
  casadi_real a36, a37, a38, a39, a40, a41, a42;
  a00=arg[1]? arg[1][41] : 0;
  a01=1.;
  a02=-2.;
  a03=arg[0]? arg[0][4] : 0;
  a04=casadi_sq(a03);
  a04=(a02*a04);
  a05=(a01+a04);
  a06=arg[0]? arg[0][5] : 0;
  a07=casadi_sq(a06);
  a07=(a02*a07);
  a05=(a05+a07);
  a08=(a00*a05);
  a09=arg[1]? arg[1][42] : 0;
  a10=arg[0]? arg[0][6] : 0;
  a11=(a02*a10);
  a12=(a11*a06);
  a13=arg[0]? arg[0][3] : 0;
  a14=(2.*a13);
  a15=(a14*a03);
  a12=(a12+a15);
  a16=(a09*a12);
  a08=(a08+a16);
  a16=arg[1]? arg[1][43] : 0;
  a10=(2.*a10);
  a17=(a10*a03);
  a14=(a14*a06);
  a17=(a17+a14);
  a18=(a16*a17);
  a08=(a08+a18);
  a18=arg[0]? arg[0][7] : 0;
  a19=cos(a18);
  a20=(a08*a19);
  a21=arg[1]? arg[1][44] : 0;
  a22=(a21*a05);
  a23=arg[1]? arg[1][45] : 0;
  a24=(a23*a12);
  a22=(a22+a24);
  a24=arg[1]? arg[1][46] : 0;
  a25=(a24*a17);
  a22=(a22+a25);
  a18=sin(a18);
  a25=(a22*a18);
  a20=(a20+a25);
  a25=arg[2]? arg[2][1] : 0;
  a20=(a20*a25);
  a26=arg[2]? arg[2][0] : 0;
  a27=(a05*a26);
  a20=(a20+a27);
  a27=arg[1]? arg[1][32] : 0;
  a27=(a27*a25);
  a27=(a26+a27);
  a28=arg[3]? arg[3][0] : 0;
  a27=(a27*a28);
  a29=arg[1]? arg[1][33] : 0;
  a29=(a29*a25);
  a30=arg[3]? arg[3][1] : 0;
  a29=(a29*a30);
  a27=(a27+a29);
  a29=arg[1]? arg[1][34] : 0;
  a29=(a29*a25);
  a31=arg[3]? arg[3][2] : 0;
  a29=(a29*a31);
  a27=(a27+a29);
  a20=(a20*a27);
  a22=(a22*a19);
  a08=(a08*a18);
  a22=(a22-a08);
  a22=(a22*a25);
  a08=(a12*a26);
  a22=(a22+a08);
  a08=arg[1]? arg[1][35] : 0;
  a08=(a08*a25);
  a08=(a08*a28);
  a29=arg[1]? arg[1][36] : 0;
  a29=(a29*a25);
  a29=(a26+a29);
  a29=(a29*a30);
  a08=(a08+a29);
  a29=arg[1]? arg[1][37] : 0;
  a29=(a29*a25);
  a29=(a29*a31);
  a08=(a08+a29);
  a22=(a22*a08);
  a20=(a20+a22);
  a22=arg[1]? arg[1][47] : 0;
  a29=(a22*a05);
  a32=arg[1]? arg[1][48] : 0;
  a33=(a32*a12);
  a29=(a29+a33);
  a33=arg[1]? arg[1][49] : 0;
  a34=(a33*a17);
  a29=(a29+a34);
  a34=(a29*a25);
  a35=(a17*a26);
  a34=(a34+a35);
  a35=arg[1]? arg[1][38] : 0;
  a35=(a35*a25);
  a35=(a35*a28);
  a28=arg[1]? arg[1][39] : 0;
  a28=(a28*a25);
  a28=(a28*a30);
  a35=(a35+a28);
  a28=arg[1]? arg[1][40] : 0;
  a28=(a28*a25);
  a28=(a26+a28);
  a28=(a28*a31);
  a35=(a35+a28);
  a34=(a34*a35);
  a20=(a20+a34);
  a34=arg[1]? arg[1][50] : 0;
  a28=(a05*a34);
  a31=arg[1]? arg[1][51] : 0;
  a30=(a12*a31);
  a28=(a28+a30);
  a30=arg[1]? arg[1][52] : 0;
  a36=(a17*a30);
  a28=(a28+a36);
  a36=arg[0]? arg[0][0] : 0;
  a28=(a28+a36);
  a37=(a28*a25);
  a38=(a26*a36);
  a37=(a37+a38);
  a20=(a20+a37);
  if (res[0]!=0) res[0][0]=a20;
  a37=(a10*a06);
  a37=(a37+a15);
  a15=(a00*a37);
  a38=casadi_sq(a13);
  a02=(a02*a38);
  a01=(a01+a02);
  a07=(a01+a07);
  a02=(a09*a07);
  a15=(a15+a02);
  a02=(a11*a13);
  a38=(2.*a03);
  a38=(a38*a06);
  a02=(a02+a38);
  a06=(a16*a02);
  a15=(a15+a06);
  a06=(a15*a19);
  a39=(a21*a37);
  a40=(a23*a07);
  a39=(a39+a40);
  a40=(a24*a02);
  a39=(a39+a40);
  a40=(a39*a18);
  a06=(a06+a40);
  a06=(a06*a25);
  a40=(a37*a26);
  a06=(a06+a40);
  a06=(a06*a27);
  a39=(a39*a19);
  a15=(a15*a18);
  a39=(a39-a15);
  a39=(a39*a25);
  a15=(a07*a26);
  a39=(a39+a15);
  a39=(a39*a08);
  a06=(a06+a39);
  a39=(a22*a37);
  a15=(a32*a07);
  a39=(a39+a15);
  a15=(a33*a02);
  a39=(a39+a15);
  a15=(a39*a25);
  a40=(a02*a26);
  a15=(a15+a40);
  a15=(a15*a35);
  a06=(a06+a15);
  a15=(a37*a34);
  a40=(a07*a31);
  a15=(a15+a40);
  a40=(a02*a30);
  a15=(a15+a40);
  a40=arg[0]? arg[0][1] : 0;
  a15=(a15+a40);
  a41=(a15*a25);
  a42=(a26*a40);
  a41=(a41+a42);
  a06=(a06+a41);
  if (res[0]!=0) res[0][1]=a06;
  a11=(a11*a03);
  a11=(a11+a14);
  a00=(a00*a11);
  a10=(a10*a13);
  a10=(a10+a38);
  a09=(a09*a10);
  a00=(a00+a09);
  a01=(a01+a04);
  a16=(a16*a01);
  a00=(a00+a16);
  a16=(a00*a19);
  a21=(a21*a11);
  a23=(a23*a10);
  a21=(a21+a23);
  a24=(a24*a01);
  a21=(a21+a24);
  a24=(a21*a18);
  a16=(a16+a24);
  a16=(a16*a25);
  a24=(a11*a26);
  a16=(a16+a24);
  a16=(a16*a27);
  a21=(a21*a19);
  a00=(a00*a18);
  a21=(a21-a00);
  a21=(a21*a25);
  a00=(a10*a26);
  a21=(a21+a00);
  a21=(a21*a08);
  a16=(a16+a21);
  a22=(a22*a11);
  a32=(a32*a10);
  a22=(a22+a32);
  a33=(a33*a01);
  a22=(a22+a33);
  a33=(a22*a25);
  a32=(a01*a26);
  a33=(a33+a32);
  a33=(a33*a35);
  a16=(a16+a33);
  a34=(a11*a34);
  a31=(a10*a31);
  a34=(a34+a31);
  a30=(a01*a30);
  a34=(a34+a30);
  a30=arg[0]? arg[0][2] : 0;
  a34=(a34+a30);
  a31=(a34*a25);
  a26=(a26*a30);
  a31=(a31+a26);
  a16=(a16+a31);
  if (res[0]!=0) res[0][2]=a16;
  if (res[1]!=0) res[1][0]=a05;
  if (res[1]!=0) res[1][1]=a37;
  if (res[1]!=0) res[1][2]=a11;
  if (res[1]!=0) res[1][3]=a12;
  if (res[1]!=0) res[1][4]=a07;
  if (res[1]!=0) res[1][5]=a10;
  if (res[1]!=0) res[1][6]=a17;
  if (res[1]!=0) res[1][7]=a02;
  if (res[1]!=0) res[1][8]=a01;
  a30=(a16-a30);
  a31=(a37*a30);
  a40=(a06-a40);
  a26=(a11*a40);
  a31=(a31-a26);
  if (res[1]!=0) res[1][9]=a31;
  a36=(a20-a36);
  a11=(a11*a36);
  a31=(a05*a30);
  a11=(a11-a31);
  if (res[1]!=0) res[1][10]=a11;
  a05=(a05*a40);
  a37=(a37*a36);
  a05=(a05-a37);
  if (res[1]!=0) res[1][11]=a05;
  a05=(a07*a30);
  a37=(a10*a40);
  a05=(a05-a37);
  if (res[1]!=0) res[1][12]=a05;
  a10=(a10*a36);
  a05=(a12*a30);
  a10=(a10-a05);
  if (res[1]!=0) res[1][13]=a10;
  a12=(a12*a40);
  a07=(a07*a36);
  a12=(a12-a07);
  if (res[1]!=0) res[1][14]=a12;
  a12=(a02*a30);
  a07=(a01*a40);
  a12=(a12-a07);
  if (res[1]!=0) res[1][15]=a12;
  a01=(a01*a36);
  a30=(a17*a30);
  a01=(a01-a30);
  if (res[1]!=0) res[1][16]=a01;
  a17=(a17*a40);
  a02=(a02*a36);
  a17=(a17-a02);
  if (res[1]!=0) res[1][17]=a17;
  a16=(a16-a34);
  a34=(a39*a16);
  a06=(a06-a15);
  a15=(a22*a06);
  a34=(a34-a15);
  a34=(a25*a34);
  if (res[1]!=0) res[1][18]=a34;
  a20=(a20-a28);
  a22=(a22*a20);
  a16=(a29*a16);
  a22=(a22-a16);
  a22=(a25*a22);
  if (res[1]!=0) res[1][19]=a22;
  a29=(a29*a06);
  a39=(a39*a20);
  a29=(a29-a39);
  a25=(a25*a29);
  if (res[1]!=0) res[1][20]=a25;
  return 0;
}

CASADI_SYMBOL_EXPORT int snakecg_sp1_point_jacobian(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem){
  return casadi_f0(arg, res, iw, w, mem);
}

CASADI_SYMBOL_EXPORT int snakecg_sp1_point_jacobian_checkout(void) {
  return 0;
}

CASADI_SYMBOL_EXPORT void snakecg_sp1_point_jacobian_release(int mem) {
}

CASADI_SYMBOL_EXPORT void snakecg_sp1_point_jacobian_incref(void) {
}

CASADI_SYMBOL_EXPORT void snakecg_sp1_point_jacobian_decref(void) {
}

CASADI_SYMBOL_EXPORT casadi_int snakecg_sp1_point_jacobian_n_in(void) { return 4;}

CASADI_SYMBOL_EXPORT casadi_int snakecg_sp1_point_jacobian_n_out(void) { return 2;}

CASADI_SYMBOL_EXPORT casadi_real snakecg_sp1_point_jacobian_default_in(casadi_int i) {
  switch (i) {
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const char* snakecg_sp1_point_jacobian_name_in(casadi_int i) {
  switch (i) {
    case 0: return "q";
    case 1: return "K";
    case 2: return "link";
    case 3: return "point";
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const char* snakecg_sp1_point_jacobian_name_out(casadi_int i) {
  switch (i) {
    case 0: return "position";
    case 1: return "J";
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const casadi_int* snakecg_sp1_point_jacobian_sparsity_in(casadi_int i) {
  switch (i) {
    case 0: return casadi_s0;
    case 1: return casadi_s1;
    case 2: return casadi_s2;
    case 3: return casadi_s3;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const casadi_int* snakecg_sp1_point_jacobian_sparsity_out(casadi_int i) {
  switch (i) {
    case 0: return casadi_s3;
    case 1: return casadi_s4;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT int snakecg_sp1_point_jacobian_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w) {
  if (sz_arg) *sz_arg = 4;
  if (sz_res) *sz_res = 2;
  if (sz_iw) *sz_iw = 0;
  if (sz_w) *sz_w = 0;
  return 0;
}

CASADI_SYMBOL_EXPORT int snakecg_sp1_point_jacobian_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w) {
  if (sz_arg) *sz_arg = 4*sizeof(const casadi_real*);
  if (sz_res) *sz_res = 2*sizeof(casadi_real*);
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

/* snakecg_sp1_point_jacobian_sincos: 298 CasADi instructions, printed one per line */
static void snakecg_sp1_point_jacobian_sincos(
    const casadi_real* restrict arg0,
    const casadi_real* restrict arg1,
    const casadi_real* restrict arg2,
    const casadi_real* restrict arg3,
    const casadi_real* restrict arg4,
    const casadi_real* restrict arg5,
    casadi_real* restrict res0,
    casadi_real* restrict res1) {
  casadi_real w0, w1, w2, w3, w4, w5, w6, w7, w8, w9;
  casadi_real w10, w11, w12, w13, w14, w15, w16, w17, w18, w19;
  casadi_real w20, w21, w22, w23, w24, w25, w26, w27, w28, w29;
  casadi_real w30, w31, w32, w33, w34, w35, w36, w37, w38, w39;
  casadi_real w40, w41, w42;
  w0 = arg1[41];
  w1 = 1.0;
  w2 = (-2.0);
  w3 = arg0[4];
  w4 = w3 * w3;
  w4 = w2 * w4;
  w5 = w1 + w4;
  w6 = arg0[5];
  w7 = w6 * w6;
  w7 = w2 * w7;
  w5 = w5 + w7;
  w8 = w0 * w5;
  w9 = arg1[42];
  w10 = arg0[6];
  w11 = w2 * w10;
  w12 = w11 * w6;
  w13 = arg0[3];
  w14 = w13 + w13;
  w15 = w14 * w3;
  w12 = w12 + w15;
  w16 = w9 * w12;
  w8 = w8 + w16;
  w16 = arg1[43];
  w10 = w10 + w10;
  w17 = w10 * w3;
  w14 = w14 * w6;
  w17 = w17 + w14;
  w18 = w16 * w17;
  w8 = w8 + w18;
  w18 = arg4[0];
  w19 = w8 * w18;
  w20 = arg1[44];
  w21 = w20 * w5;
  w22 = arg1[45];
  w23 = w22 * w12;
  w21 = w21 + w23;
  w23 = arg1[46];
  w24 = w23 * w17;
  w21 = w21 + w24;
  w24 = arg5[0];
  w25 = w21 * w24;
  w19 = w19 + w25;
  w25 = arg2[1];
  w19 = w19 * w25;
  w26 = arg2[0];
  w27 = w5 * w26;
  w19 = w19 + w27;
  w27 = arg1[32];
  w27 = w27 * w25;
  w27 = w26 + w27;
  w28 = arg3[0];
  w27 = w27 * w28;
  w29 = arg1[33];
  w29 = w29 * w25;
  w30 = arg3[1];
  w29 = w29 * w30;
  w27 = w27 + w29;
  w29 = arg1[34];
  w29 = w29 * w25;
  w31 = arg3[2];
  w29 = w29 * w31;
  w27 = w27 + w29;
  w19 = w19 * w27;
  w21 = w21 * w18;
  w8 = w8 * w24;
  w21 = w21 - w8;
  w21 = w21 * w25;
  w8 = w12 * w26;
  w21 = w21 + w8;
  w8 = arg1[35];
  w8 = w8 * w25;
  w8 = w8 * w28;
  w29 = arg1[36];
  w29 = w29 * w25;
  w29 = w26 + w29;
  w29 = w29 * w30;
  w8 = w8 + w29;
  w29 = arg1[37];
  w29 = w29 * w25;
  w29 = w29 * w31;
  w8 = w8 + w29;
  w21 = w21 * w8;
  w19 = w19 + w21;
  w21 = arg1[47];
  w29 = w21 * w5;
  w32 = arg1[48];
  w33 = w32 * w12;
  w29 = w29 + w33;
  w33 = arg1[49];
  w34 = w33 * w17;
  w29 = w29 + w34;
  w34 = w29 * w25;
  w35 = w17 * w26;
  w34 = w34 + w35;
  w35 = arg1[38];
  w35 = w35 * w25;
  w35 = w35 * w28;
  w28 = arg1[39];
  w28 = w28 * w25;
  w28 = w28 * w30;
  w35 = w35 + w28;
  w28 = arg1[40];
  w28 = w28 * w25;
  w28 = w26 + w28;
  w28 = w28 * w31;
  w35 = w35 + w28;
  w34 = w34 * w35;
  w19 = w19 + w34;
  w34 = arg1[50];
  w28 = w5 * w34;
  w31 = arg1[51];
  w30 = w12 * w31;
  w28 = w28 + w30;
  w30 = arg1[52];
  w36 = w17 * w30;
  w28 = w28 + w36;
  w36 = arg0[0];
  w28 = w28 + w36;
  w37 = w28 * w25;
  w38 = w26 * w36;
  w37 = w37 + w38;
  w19 = w19 + w37;
  res0[0] = w19;
  w37 = w10 * w6;
  w37 = w37 + w15;
  w15 = w0 * w37;
  w38 = w13 * w13;
  w2 = w2 * w38;
  w1 = w1 + w2;
  w7 = w1 + w7;
  w2 = w9 * w7;
  w15 = w15 + w2;
  w2 = w11 * w13;
  w38 = w3 + w3;
  w38 = w38 * w6;
  w2 = w2 + w38;
  w6 = w16 * w2;
  w15 = w15 + w6;
  w6 = w15 * w18;
  w39 = w20 * w37;
  w40 = w22 * w7;
  w39 = w39 + w40;
  w40 = w23 * w2;
  w39 = w39 + w40;
  w40 = w39 * w24;
  w6 = w6 + w40;
  w6 = w6 * w25;
  w40 = w37 * w26;
  w6 = w6 + w40;
  w6 = w6 * w27;
  w39 = w39 * w18;
  w15 = w15 * w24;
  w39 = w39 - w15;
  w39 = w39 * w25;
  w15 = w7 * w26;
  w39 = w39 + w15;
  w39 = w39 * w8;
  w6 = w6 + w39;
  w39 = w21 * w37;
  w15 = w32 * w7;
  w39 = w39 + w15;
  w15 = w33 * w2;
  w39 = w39 + w15;
  w15 = w39 * w25;
  w40 = w2 * w26;
  w15 = w15 + w40;
  w15 = w15 * w35;
  w6 = w6 + w15;
  w15 = w37 * w34;
  w40 = w7 * w31;
  w15 = w15 + w40;
  w40 = w2 * w30;
  w15 = w15 + w40;
  w40 = arg0[1];
  w15 = w15 + w40;
  w41 = w15 * w25;
  w42 = w26 * w40;
  w41 = w41 + w42;
  w6 = w6 + w41;
  res0[1] = w6;
  w11 = w11 * w3;
  w11 = w11 + w14;
  w0 = w0 * w11;
  w10 = w10 * w13;
  w10 = w10 + w38;
  w9 = w9 * w10;
  w0 = w0 + w9;
  w1 = w1 + w4;
  w16 = w16 * w1;
  w0 = w0 + w16;
  w16 = w0 * w18;
  w20 = w20 * w11;
  w22 = w22 * w10;
  w20 = w20 + w22;
  w23 = w23 * w1;
  w20 = w20 + w23;
  w23 = w20 * w24;
  w16 = w16 + w23;
  w16 = w16 * w25;
  w23 = w11 * w26;
  w16 = w16 + w23;
  w16 = w16 * w27;
  w20 = w20 * w18;
  w0 = w0 * w24;
  w20 = w20 - w0;
  w20 = w20 * w25;
  w0 = w10 * w26;
  w20 = w20 + w0;
  w20 = w20 * w8;
  w16 = w16 + w20;
  w21 = w21 * w11;
  w32 = w32 * w10;
  w21 = w21 + w32;
  w33 = w33 * w1;
  w21 = w21 + w33;
  w33 = w21 * w25;
  w32 = w1 * w26;
  w33 = w33 + w32;
  w33 = w33 * w35;
  w16 = w16 + w33;
  w34 = w11 * w34;
  w31 = w10 * w31;
  w34 = w34 + w31;
  w30 = w1 * w30;
  w34 = w34 + w30;
  w30 = arg0[2];
  w34 = w34 + w30;
  w31 = w34 * w25;
  w26 = w26 * w30;
  w31 = w31 + w26;
  w16 = w16 + w31;
  res0[2] = w16;
  res1[0] = w5;
  res1[1] = w37;
  res1[2] = w11;
  res1[3] = w12;
  res1[4] = w7;
  res1[5] = w10;
  res1[6] = w17;
  res1[7] = w2;
  res1[8] = w1;
  w30 = w16 - w30;
  w31 = w37 * w30;
  w40 = w6 - w40;
  w26 = w11 * w40;
  w31 = w31 - w26;
  res1[9] = w31;
  w36 = w19 - w36;
  w11 = w11 * w36;
  w31 = w5 * w30;
  w11 = w11 - w31;
  res1[10] = w11;
  w5 = w5 * w40;
  w37 = w37 * w36;
  w5 = w5 - w37;
  res1[11] = w5;
  w5 = w7 * w30;
  w37 = w10 * w40;
  w5 = w5 - w37;
  res1[12] = w5;
  w10 = w10 * w36;
  w5 = w12 * w30;
  w10 = w10 - w5;
  res1[13] = w10;
  w12 = w12 * w40;
  w7 = w7 * w36;
  w12 = w12 - w7;
  res1[14] = w12;
  w12 = w2 * w30;
  w7 = w1 * w40;
  w12 = w12 - w7;
  res1[15] = w12;
  w1 = w1 * w36;
  w30 = w17 * w30;
  w1 = w1 - w30;
  res1[16] = w1;
  w17 = w17 * w40;
  w2 = w2 * w36;
  w17 = w17 - w2;
  res1[17] = w17;
  w16 = w16 - w34;
  w34 = w39 * w16;
  w6 = w6 - w15;
  w15 = w21 * w6;
  w34 = w34 - w15;
  w34 = w25 * w34;
  res1[18] = w34;
  w19 = w19 - w28;
  w21 = w21 * w19;
  w16 = w29 * w16;
  w21 = w21 - w16;
  w21 = w25 * w21;
  res1[19] = w21;
  w29 = w29 * w6;
  w39 = w39 * w19;
  w29 = w29 - w39;
  w25 = w25 * w29;
  res1[20] = w25;
}


CASADI_SYMBOL_EXPORT int snakecg_sp1_batch_point_jacobian(casadi_int n, const casadi_real** arg,
    const casadi_int* stride, casadi_real** res) {
  const casadi_real* a[4];
  casadi_real* r[2];
  casadi_int* iw = (casadi_int*) malloc(sizeof(casadi_int) * 1);
  casadi_real* w = (casadi_real*) malloc(sizeof(casadi_real) * 44);
  casadi_int i, k;
  int status = 0;
  if (!iw || !w) { free(iw); free(w); return -1; }
  for (k = 0; k < 4; ++k) a[k] = 0;
  for (k = 0; k < 2; ++k) r[k] = 0;
  if (arg[0] && arg[1] && arg[2] && arg[3] && res[0] && res[1]) {
    /* cos and sin of q[7..7] of 16 samples at a time, then snakecg_sp1_point_jacobian_sincos
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
        snakecg_sp1_point_jacobian_sincos(arg[0] + (i0 + i) * stride[0], arg[1] + (i0 + i) * stride[1], arg[2] + (i0 + i) * stride[2], arg[3] + (i0 + i) * stride[3], ca + i * na, sa + i * na, res[0] + (i0 + i) * 3, res[1] + (i0 + i) * 21);
      }
    }
  } else {
    /* a null input or output (CasADi's convention: zeros in, nothing out): per sample */
    for (i = 0; i < n; ++i) {
      a[0] = arg[0] + i * stride[0];
      a[1] = arg[1] + i * stride[1];
      a[2] = arg[2] + i * stride[2];
      a[3] = arg[3] + i * stride[3];
      r[0] = res[0] + i * 3;
      r[1] = res[1] + i * 21;
      if (snakecg_sp1_point_jacobian(a, r, iw, w, 0)) { status = (int) (i + 1); break; }
    }
  }
  free(iw);
  free(w);
  return status;
}
