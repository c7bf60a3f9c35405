/* GENERATED FILE - DO NOT EDIT. C code emitted by CasADi for mass_matrix() of
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
  #define CASADI_PREFIX(ID) snakecg_sp1_mass_matrix_ ## ID
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

/* Configuration this file was compiled with */
CASADI_SYMBOL_EXPORT void snakecg_sp1_mass_matrix_casadi_version(int* major, int* minor, int* patch) {
  *major = 3;
  *minor = 8;
  *patch = 2;
}
CASADI_SYMBOL_EXPORT int snakecg_sp1_mass_matrix_casadi_int_size(void) { return (int) sizeof(casadi_int); }
CASADI_SYMBOL_EXPORT int snakecg_sp1_mass_matrix_casadi_real_size(void) { return (int) sizeof(casadi_real); }

static const casadi_int casadi_s0[3] = {8, 1, 1};
static const casadi_int casadi_s1[3] = {71, 1, 1};
static const casadi_int casadi_s2[3] = {7, 7, 1};

/* snakecg_sp1_mass_matrix:(q[8],K[71])->(M[7x7]) */
static int casadi_f0(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem) {
  casadi_real a00, a01, a02, a03, a04, a05, a06, a07, a08, a09, a10, a11;
  casadi_real a12, a13, a14, a15, a16, a17, a18, a19, a20, a21, a22, a23;
  casadi_real a24, a25, a26, a27, a28, a29, a30, a31, a32, a33, a34, a35;
  casadi_real a36, a37, a38, a39, a40, a41, a42;
  a00=arg[1]? arg[1][0] : 0;
  a01=arg[1]? arg[1][1] : 0;
  a02=(a00+a01);
  if (res[0]!=0) res[0][0]=a02;
  a03=0.;
  if (res[0]!=0) res[0][1]=a03;
  if (res[0]!=0) res[0][2]=a03;
  if (res[0]!=0) res[0][3]=a03;
  a04=arg[1]? arg[1][55] : 0;
  a05=(a04*a00);
  a06=arg[1]? arg[1][49] : 0;
  a07=arg[1]? arg[1][58] : 0;
  a08=(a06*a07);
  a09=arg[1]? arg[1][43] : 0;
  a10=arg[0]? arg[0][7] : 0;
  a11=cos(a10);
  a12=(a09*a11);
  a13=arg[1]? arg[1][46] : 0;
  a10=sin(a10);
  a14=(a13*a10);
  a12=(a12+a14);
  a14=arg[1]? arg[1][56] : 0;
  a15=(a12*a14);
  a08=(a08+a15);
  a13=(a13*a11);
  a09=(a09*a10);
  a13=(a13-a09);
  a09=arg[1]? arg[1][57] : 0;
  a15=(a13*a09);
  a08=(a08+a15);
  a15=arg[1]? arg[1][52] : 0;
  a08=(a08+a15);
  a16=(a08*a01);
  a17=(a05+a16);
  if (res[0]!=0) res[0][4]=a17;
  a18=arg[1]? arg[1][54] : 0;
  a19=(a18*a00);
  a20=arg[1]? arg[1][48] : 0;
  a21=(a20*a07);
  a22=arg[1]? arg[1][42] : 0;
  a23=(a22*a11);
  a24=arg[1]? arg[1][45] : 0;
  a25=(a24*a10);
  a23=(a23+a25);
  a25=(a23*a14);
  a21=(a21+a25);
  a24=(a24*a11);
  a22=(a22*a10);
  a24=(a24-a22);
  a22=(a24*a09);
  a21=(a21+a22);
  a22=arg[1]? arg[1][51] : 0;
  a21=(a21+a22);
  a25=(a21*a01);
  a26=(a19+a25);
  a27=(-a26);
  if (res[0]!=0) res[0][5]=a27;
  a28=(a20*a16);
  a29=(a06*a22);
  a30=(a20*a15);
  a29=(a29-a30);
  a30=(a29*a01);
  a28=(a28+a30);
  a30=(a06*a25);
  a28=(a28-a30);
  if (res[0]!=0) res[0][6]=a28;
  if (res[0]!=0) res[0][7]=a03;
  if (res[0]!=0) res[0][8]=a02;
  if (res[0]!=0) res[0][9]=a03;
  a30=(-a17);
  if (res[0]!=0) res[0][10]=a30;
  if (res[0]!=0) res[0][11]=a03;
  a31=arg[1]? arg[1][53] : 0;
  a00=(a31*a00);
  a32=arg[1]? arg[1][47] : 0;
  a07=(a32*a07);
  a33=arg[1]? arg[1][41] : 0;
  a34=(a33*a11);
  a35=arg[1]? arg[1][44] : 0;
  a36=(a35*a10);
  a34=(a34+a36);
  a14=(a34*a14);
  a07=(a07+a14);
  a35=(a35*a11);
  a33=(a33*a10);
  a35=(a35-a33);
  a09=(a35*a09);
  a07=(a07+a09);
  a09=arg[1]? arg[1][50] : 0;
  a07=(a07+a09);
  a33=(a07*a01);
  a10=(a00+a33);
  if (res[0]!=0) res[0][12]=a10;
  a11=(a06*a33);
  a15=(a32*a15);
  a14=(a06*a09);
  a15=(a15-a14);
  a14=(a15*a01);
  a11=(a11+a14);
  a14=(a32*a16);
  a11=(a11-a14);
  if (res[0]!=0) res[0][13]=a11;
  if (res[0]!=0) res[0][14]=a03;
  if (res[0]!=0) res[0][15]=a03;
  if (res[0]!=0) res[0][16]=a02;
  if (res[0]!=0) res[0][17]=a26;
  a02=(-a10);
  if (res[0]!=0) res[0][18]=a02;
  if (res[0]!=0) res[0][19]=a03;
  a14=(a32*a25);
  a09=(a20*a09);
  a22=(a32*a22);
  a09=(a09-a22);
  a01=(a09*a01);
  a14=(a14+a01);
  a01=(a20*a33);
  a14=(a14-a01);
  if (res[0]!=0) res[0][20]=a14;
  if (res[0]!=0) res[0][21]=a03;
  if (res[0]!=0) res[0][22]=a30;
  if (res[0]!=0) res[0][23]=a26;
  a26=arg[1]? arg[1][65] : 0;
  a30=arg[1]? arg[1][66] : 0;
  a30=(a30-a26);
  a01=(a35*a30);
  a22=(a01*a35);
  a22=(a26+a22);
  a36=arg[1]? arg[1][69] : 0;
  a34=(a36*a34);
  a37=arg[1]? arg[1][70] : 0;
  a35=(a37*a35);
  a34=(a34+a35);
  a35=5.0000000000000000e-01;
  a38=arg[1]? arg[1][67] : 0;
  a35=(a35*a38);
  a38=-5.0000000000000000e-01;
  a38=(a38*a26);
  a35=(a35+a38);
  a38=(a35*a32);
  a34=(a34+a38);
  a38=(2.*a34);
  a38=(a38*a32);
  a22=(a22+a38);
  a07=(a07*a33);
  a38=(a21*a25);
  a39=(a07+a38);
  a40=(a08*a16);
  a39=(a39+a40);
  a22=(a22+a39);
  a22=(a22-a07);
  a07=arg[1]? arg[1][59] : 0;
  a07=(a22+a07);
  a31=(a31*a00);
  a41=(a18*a19);
  a42=(a31+a41);
  a05=(a04*a05);
  a42=(a42+a05);
  a07=(a07+a42);
  a07=(a07-a31);
  if (res[0]!=0) res[0][24]=a07;
  a07=(a34*a20);
  a23=(a36*a23);
  a31=(a37*a24);
  a23=(a23+a31);
  a31=(a35*a20);
  a23=(a23+a31);
  a31=(a23*a32);
  a07=(a07+a31);
  a31=(a01*a24);
  a07=(a07+a31);
  a21=(a21*a33);
  a07=(a07-a21);
  a21=arg[1]? arg[1][62] : 0;
  a21=(a07+a21);
  a18=(a18*a00);
  a21=(a21-a18);
  if (res[0]!=0) res[0][25]=a21;
  a34=(a34*a06);
  a36=(a36*a12);
  a37=(a37*a13);
  a36=(a36+a37);
  a35=(a35*a06);
  a36=(a36+a35);
  a35=(a36*a32);
  a34=(a34+a35);
  a01=(a01*a13);
  a34=(a34+a01);
  a01=(a08*a33);
  a34=(a34-a01);
  a01=arg[1]? arg[1][63] : 0;
  a01=(a34+a01);
  a00=(a04*a00);
  a01=(a01-a00);
  if (res[0]!=0) res[0][26]=a01;
  a22=(a22*a32);
  a00=(a07*a20);
  a22=(a22+a00);
  a00=(a34*a06);
  a22=(a22+a00);
  a00=(a25*a09);
  a22=(a22+a00);
  a00=(a16*a15);
  a22=(a22-a00);
  if (res[0]!=0) res[0][27]=a22;
  if (res[0]!=0) res[0][28]=a17;
  if (res[0]!=0) res[0][29]=a03;
  if (res[0]!=0) res[0][30]=a02;
  if (res[0]!=0) res[0][31]=a21;
  a21=(a24*a30);
  a24=(a21*a24);
  a24=(a26+a24);
  a02=(2.*a23);
  a02=(a02*a20);
  a24=(a24+a02);
  a24=(a24+a39);
  a24=(a24-a38);
  a38=arg[1]? arg[1][60] : 0;
  a38=(a24+a38);
  a38=(a38+a42);
  a38=(a38-a41);
  if (res[0]!=0) res[0][32]=a38;
  a23=(a23*a06);
  a38=(a36*a20);
  a23=(a23+a38);
  a21=(a21*a13);
  a23=(a23+a21);
  a08=(a08*a25);
  a23=(a23-a08);
  a08=arg[1]? arg[1][64] : 0;
  a08=(a23+a08);
  a04=(a04*a19);
  a08=(a08-a04);
  if (res[0]!=0) res[0][33]=a08;
  a24=(a24*a20);
  a07=(a07*a32);
  a24=(a24+a07);
  a07=(a23*a06);
  a24=(a24+a07);
  a16=(a16*a29);
  a24=(a24+a16);
  a16=(a33*a09);
  a24=(a24-a16);
  if (res[0]!=0) res[0][34]=a24;
  if (res[0]!=0) res[0][35]=a27;
  if (res[0]!=0) res[0][36]=a10;
  if (res[0]!=0) res[0][37]=a03;
  if (res[0]!=0) res[0][38]=a01;
  if (res[0]!=0) res[0][39]=a08;
  a30=(a13*a30);
  a30=(a30*a13);
  a26=(a26+a30);
  a36=(2.*a36);
  a36=(a36*a06);
  a26=(a26+a36);
  a26=(a26+a39);
  a26=(a26-a40);
  a40=arg[1]? arg[1][61] : 0;
  a40=(a26+a40);
  a40=(a40+a42);
  a40=(a40-a05);
  if (res[0]!=0) res[0][40]=a40;
  a26=(a26*a06);
  a34=(a34*a32);
  a26=(a26+a34);
  a23=(a23*a20);
  a26=(a26+a23);
  a33=(a33*a15);
  a26=(a26+a33);
  a25=(a25*a29);
  a26=(a26-a25);
  if (res[0]!=0) res[0][41]=a26;
  if (res[0]!=0) res[0][42]=a28;
  if (res[0]!=0) res[0][43]=a11;
  if (res[0]!=0) res[0][44]=a14;
  if (res[0]!=0) res[0][45]=a22;
  if (res[0]!=0) res[0][46]=a24;
  if (res[0]!=0) res[0][47]=a26;
  a22=(a22*a32);
  a24=(a24*a20);
  a22=(a22+a24);
  a26=(a26*a06);
  a22=(a22+a26);
  a28=(a28*a29);
  a22=(a22+a28);
  a11=(a11*a15);
  a22=(a22+a11);
  a14=(a14*a09);
  a22=(a22+a14);
  if (res[0]!=0) res[0][48]=a22;
  return 0;
}

CASADI_SYMBOL_EXPORT int snakecg_sp1_mass_matrix(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem){
  return casadi_f0(arg, res, iw, w, mem);
}

CASADI_SYMBOL_EXPORT int snakecg_sp1_mass_matrix_checkout(void) {
  return 0;
}

CASADI_SYMBOL_EXPORT void snakecg_sp1_mass_matrix_release(int mem) {
}

CASADI_SYMBOL_EXPORT void snakecg_sp1_mass_matrix_incref(void) {
}

CASADI_SYMBOL_EXPORT void snakecg_sp1_mass_matrix_decref(void) {
}

CASADI_SYMBOL_EXPORT casadi_int snakecg_sp1_mass_matrix_n_in(void) { return 2;}

CASADI_SYMBOL_EXPORT casadi_int snakecg_sp1_mass_matrix_n_out(void) { return 1;}

CASADI_SYMBOL_EXPORT casadi_real snakecg_sp1_mass_matrix_default_in(casadi_int i) {
  switch (i) {
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const char* snakecg_sp1_mass_matrix_name_in(casadi_int i) {
  switch (i) {
    case 0: return "q";
    case 1: return "K";
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const char* snakecg_sp1_mass_matrix_name_out(casadi_int i) {
  switch (i) {
    case 0: return "M";
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const casadi_int* snakecg_sp1_mass_matrix_sparsity_in(casadi_int i) {
  switch (i) {
    case 0: return casadi_s0;
    case 1: return casadi_s1;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const casadi_int* snakecg_sp1_mass_matrix_sparsity_out(casadi_int i) {
  switch (i) {
    case 0: return casadi_s2;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT int snakecg_sp1_mass_matrix_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w) {
  if (sz_arg) *sz_arg = 2;
  if (sz_res) *sz_res = 1;
  if (sz_iw) *sz_iw = 0;
  if (sz_w) *sz_w = 0;
  return 0;
}

CASADI_SYMBOL_EXPORT int snakecg_sp1_mass_matrix_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w) {
  if (sz_arg) *sz_arg = 2*sizeof(const casadi_real*);
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

#if defined(__GNUC__) && !defined(__clang__) && __GNUC__ >= 11 && defined(__x86_64__) \
    && defined(__linux__)
/* a second copy for processors with AVX2 (four angles per instruction), chosen at load time */
__attribute__((target_clones("arch=x86-64-v3", "default")))
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

/* snakecg_sp1_mass_matrix_sincos: 288 CasADi instructions, printed one per line */
static void snakecg_sp1_mass_matrix_sincos(
    const casadi_real* restrict arg0,
    const casadi_real* restrict arg1,
    const casadi_real* restrict arg2,
    const casadi_real* restrict arg3,
    casadi_real* restrict res0) {
  casadi_real w0, w1, w2, w3, w4, w5, w6, w7, w8, w9;
  casadi_real w10, w11, w12, w13, w14, w15, w16, w17, w18, w19;
  casadi_real w20, w21, w22, w23, w24, w25, w26, w27, w28, w29;
  casadi_real w30, w31, w32, w33, w34, w35, w36, w37, w38, w39;
  casadi_real w40, w41, w42;
  w0 = arg1[0];
  w1 = arg1[1];
  w2 = w0 + w1;
  res0[0] = w2;
  w3 = 0.0;
  res0[1] = w3;
  res0[2] = w3;
  res0[3] = w3;
  w4 = arg1[55];
  w5 = w4 * w0;
  w6 = arg1[49];
  w7 = arg1[58];
  w8 = w6 * w7;
  w9 = arg1[43];
  w10 = arg2[0];
  w11 = w9 * w10;
  w12 = arg1[46];
  w13 = arg3[0];
  w14 = w12 * w13;
  w11 = w11 + w14;
  w14 = arg1[56];
  w15 = w11 * w14;
  w8 = w8 + w15;
  w12 = w12 * w10;
  w9 = w9 * w13;
  w12 = w12 - w9;
  w9 = arg1[57];
  w15 = w12 * w9;
  w8 = w8 + w15;
  w15 = arg1[52];
  w8 = w8 + w15;
  w16 = w8 * w1;
  w17 = w5 + w16;
  res0[4] = w17;
  w18 = arg1[54];
  w19 = w18 * w0;
  w20 = arg1[48];
  w21 = w20 * w7;
  w22 = arg1[42];
  w23 = w22 * w10;
  w24 = arg1[45];
  w25 = w24 * w13;
  w23 = w23 + w25;
  w25 = w23 * w14;
  w21 = w21 + w25;
  w24 = w24 * w10;
  w22 = w22 * w13;
  w24 = w24 - w22;
  w22 = w24 * w9;
  w21 = w21 + w22;
  w22 = arg1[51];
  w21 = w21 + w22;
  w25 = w21 * w1;
  w26 = w19 + w25;
  w27 = -w26;
  res0[5] = w27;
  w28 = w20 * w16;
  w29 = w6 * w22;
  w30 = w20 * w15;
  w29 = w29 - w30;
  w30 = w29 * w1;
  w28 = w28 + w30;
  w30 = w6 * w25;
  w28 = w28 - w30;
  res0[6] = w28;
  res0[7] = w3;
  res0[8] = w2;
  res0[9] = w3;
  w30 = -w17;
  res0[10] = w30;
  res0[11] = w3;
  w31 = arg1[53];
  w0 = w31 * w0;
  w32 = arg1[47];
  w7 = w32 * w7;
  w33 = arg1[41];
  w34 = w33 * w10;
  w35 = arg1[44];
  w36 = w35 * w13;
  w34 = w34 + w36;
  w14 = w34 * w14;
  w7 = w7 + w14;
  w35 = w35 * w10;
  w33 = w33 * w13;
  w35 = w35 - w33;
  w9 = w35 * w9;
  w7 = w7 + w9;
  w9 = arg1[50];
  w7 = w7 + w9;
  w33 = w7 * w1;
  w13 = w0 + w33;
  res0[12] = w13;
  w10 = w6 * w33;
  w15 = w32 * w15;
  w14 = w6 * w9;
  w15 = w15 - w14;
  w14 = w15 * w1;
  w10 = w10 + w14;
  w14 = w32 * w16;
  w10 = w10 - w14;
  res0[13] = w10;
  res0[14] = w3;
  res0[15] = w3;
  res0[16] = w2;
  res0[17] = w26;
  w2 = -w13;
  res0[18] = w2;
  res0[19] = w3;
  w14 = w32 * w25;
  w9 = w20 * w9;
  w22 = w32 * w22;
  w9 = w9 - w22;
  w1 = w9 * w1;
  w14 = w14 + w1;
  w1 = w20 * w33;
  w14 = w14 - w1;
  res0[20] = w14;
  res0[21] = w3;
  res0[22] = w30;
  res0[23] = w26;
  w26 = arg1[65];
  w30 = arg1[66];
  w30 = w30 - w26;
  w1 = w35 * w30;
  w22 = w1 * w35;
  w22 = w26 + w22;
  w36 = arg1[69];
  w34 = w36 * w34;
  w37 = arg1[70];
  w35 = w37 * w35;
  w34 = w34 + w35;
  w35 = 0.5;
  w38 = arg1[67];
  w35 = w35 * w38;
  w38 = (-0.5);
  w38 = w38 * w26;
  w35 = w35 + w38;
  w38 = w35 * w32;
  w34 = w34 + w38;
  w38 = w34 + w34;
  w38 = w38 * w32;
  w22 = w22 + w38;
  w7 = w7 * w33;
  w38 = w21 * w25;
  w39 = w7 + w38;
  w40 = w8 * w16;
  w39 = w39 + w40;
  w22 = w22 + w39;
  w22 = w22 - w7;
  w7 = arg1[59];
  w7 = w22 + w7;
  w31 = w31 * w0;
  w41 = w18 * w19;
  w42 = w31 + w41;
  w5 = w4 * w5;
  w42 = w42 + w5;
  w7 = w7 + w42;
  w7 = w7 - w31;
  res0[24] = w7;
  w7 = w34 * w20;
  w23 = w36 * w23;
  w31 = w37 * w24;
  w23 = w23 + w31;
  w31 = w35 * w20;
  w23 = w23 + w31;
  w31 = w23 * w32;
  w7 = w7 + w31;
  w31 = w1 * w24;
  w7 = w7 + w31;
  w21 = w21 * w33;
  w7 = w7 - w21;
  w21 = arg1[62];
  w21 = w7 + w21;
  w18 = w18 * w0;
  w21 = w21 - w18;
  res0[25] = w21;
  w34 = w34 * w6;
  w36 = w36 * w11;
  w37 = w37 * w12;
  w36 = w36 + w37;
  w35 = w35 * w6;
  w36 = w36 + w35;
  w35 = w36 * w32;
  w34 = w34 + w35;
  w1 = w1 * w12;
  w34 = w34 + w1;
  w1 = w8 * w33;
  w34 = w34 - w1;
  w1 = arg1[63];
  w1 = w34 + w1;
  w0 = w4 * w0;
  w1 = w1 - w0;
  res0[26] = w1;
  w22 = w22 * w32;
  w0 = w7 * w20;
  w22 = w22 + w0;
  w0 = w34 * w6;
  w22 = w22 + w0;
  w0 = w25 * w9;
  w22 = w22 + w0;
  w0 = w16 * w15;
  w22 = w22 - w0;
  res0[27] = w22;
  res0[28] = w17;
  res0[29] = w3;
  res0[30] = w2;
  res0[31] = w21;
  w21 = w24 * w30;
  w24 = w21 * w24;
  w24 = w26 + w24;
  w2 = w23 + w23;
  w2 = w2 * w20;
  w24 = w24 + w2;
  w24 = w24 + w39;
  w24 = w24 - w38;
  w38 = arg1[60];
  w38 = w24 + w38;
  w38 = w38 + w42;
  w38 = w38 - w41;
  res0[32] = w38;
  w23 = w23 * w6;
  w38 = w36 * w20;
  w23 = w23 + w38;
  w21 = w21 * w12;
  w23 = w23 + w21;
  w8 = w8 * w25;
  w23 = w23 - w8;
  w8 = arg1[64];
  w8 = w23 + w8;
  w4 = w4 * w19;
  w8 = w8 - w4;
  res0[33] = w8;
  w24 = w24 * w20;
  w7 = w7 * w32;
  w24 = w24 + w7;
  w7 = w23 * w6;
  w24 = w24 + w7;
  w16 = w16 * w29;
  w24 = w24 + w16;
  w16 = w33 * w9;
  w24 = w24 - w16;
  res0[34] = w24;
  res0[35] = w27;
  res0[36] = w13;
  res0[37] = w3;
  res0[38] = w1;
  res0[39] = w8;
  w30 = w12 * w30;
  w30 = w30 * w12;
  w26 = w26 + w30;
  w36 = w36 + w36;
  w36 = w36 * w6;
  w26 = w26 + w36;
  w26 = w26 + w39;
  w26 = w26 - w40;
  w40 = arg1[61];
  w40 = w26 + w40;
  w40 = w40 + w42;
  w40 = w40 - w5;
  res0[40] = w40;
  w26 = w26 * w6;
  w34 = w34 * w32;
  w26 = w26 + w34;
  w23 = w23 * w20;
  w26 = w26 + w23;
  w33 = w33 * w15;
  w26 = w26 + w33;
  w25 = w25 * w29;
  w26 = w26 - w25;
  res0[41] = w26;
  res0[42] = w28;
  res0[43] = w10;
  res0[44] = w14;
  res0[45] = w22;
  res0[46] = w24;
  res0[47] = w26;
  w22 = w22 * w32;
  w24 = w24 * w20;
  w22 = w22 + w24;
  w26 = w26 * w6;
  w22 = w22 + w26;
  w28 = w28 * w29;
  w22 = w22 + w28;
  w10 = w10 * w15;
  w22 = w22 + w10;
  w14 = w14 * w9;
  w22 = w22 + w14;
  res0[48] = w22;
}


CASADI_SYMBOL_EXPORT int snakecg_sp1_sample_batch_mass_matrix(casadi_int n, const casadi_real** arg,
    const casadi_int* stride, casadi_real** res) {
  const casadi_real* a[2];
  casadi_real* r[1];
  casadi_int* iw = (casadi_int*) malloc(sizeof(casadi_int) * 1);
  casadi_real* w = (casadi_real*) malloc(sizeof(casadi_real) * 44);
  casadi_int i, k;
  int status = 0;
  if (!iw || !w) { free(iw); free(w); return -1; }
  for (k = 0; k < 2; ++k) a[k] = 0;
  for (k = 0; k < 1; ++k) r[k] = 0;
  if (arg[0] && arg[1] && res[0]) {
    /* cos and sin of q[7..7] of 16 samples at a time, then snakecg_sp1_mass_matrix_sincos
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
        snakecg_sp1_mass_matrix_sincos(arg[0] + (i0 + i) * stride[0], arg[1] + (i0 + i) * stride[1], ca + i * na, sa + i * na, res[0] + (i0 + i) * 49);
      }
    }
  } else {
    /* a null input or output (CasADi's convention: zeros in, nothing out): per sample */
    for (i = 0; i < n; ++i) {
      a[0] = arg[0] + i * stride[0];
      a[1] = arg[1] + i * stride[1];
      r[0] = res[0] + i * 49;
      if (snakecg_sp1_mass_matrix(a, r, iw, w, 0)) { status = (int) (i + 1); break; }
    }
  }
  free(iw);
  free(w);
  return status;
}

/* ------------------------------------------------------------------------------------------
 * GENERATED FILE - DO NOT EDIT. Block driver rendered from derive/spatial/templates/block.c.j2.
 * snakecg_sp1_batch_mass_matrix evaluates 16 samples at a time with snakecg_sp1_mass_matrix_sincos_block (vectorized across
 * the samples): the inputs of a block are gathered sample-innermost, the cosines and sines of
 * the joint angles q[7..7] computed 16 at a time, and the outputs scattered back to
 * the batch layout. When an input or output is null or K varies per sample, the
 * per-sample driver snakecg_sp1_sample_batch_mass_matrix above answers instead. Same return codes.
 * ---------------------------------------------------------------------------------------- */

/* snakecg_sp1_mass_matrix_sincos over 16 samples: 267 CasADi instructions, one per line, in a loop the compiler vectorizes across the samples */
#if defined(__GNUC__) && !defined(__clang__) && __GNUC__ >= 11 && defined(__x86_64__) \
    && defined(__linux__)
/* a second copy for processors with AVX2 and FMA, chosen at load time */
__attribute__((target_clones("arch=x86-64-v3", "default")))
#endif
static void snakecg_sp1_mass_matrix_sincos_block(
    const casadi_real* restrict arg0,
    const casadi_real* restrict arg1,
    const casadi_real* restrict arg2,
    const casadi_real* restrict arg3,
    casadi_real* restrict res0) {
  int s;
  for (s = 0; s < 16; ++s) {
    casadi_real w0 = arg1[0];
    casadi_real w1 = arg1[1];
    casadi_real w2 = w0 + w1;
    res0[0 + s] = w2;
    casadi_real w3 = 0.0;
    res0[16 + s] = w3;
    res0[32 + s] = w2;
    res0[48 + s] = w3;
    res0[64 + s] = w3;
    res0[80 + s] = w2;
    res0[96 + s] = w3;
    w2 = arg1[55];
    casadi_real w4 = w2 * w0;
    casadi_real w5 = arg1[49];
    casadi_real w6 = arg1[58];
    casadi_real w7 = w5 * w6;
    casadi_real w8 = arg1[43];
    casadi_real w9 = arg2[0 + s];
    casadi_real w10 = w8 * w9;
    casadi_real w11 = arg1[46];
    casadi_real w12 = arg3[0 + s];
    casadi_real w13 = w11 * w12;
    w10 = w10 + w13;
    w13 = arg1[56];
    casadi_real w14 = w10 * w13;
    w7 = w7 + w14;
    w11 = w11 * w9;
    w8 = w8 * w12;
    w11 = w11 - w8;
    w8 = arg1[57];
    w14 = w11 * w8;
    w7 = w7 + w14;
    w14 = arg1[52];
    w7 = w7 + w14;
    casadi_real w15 = w7 * w1;
    casadi_real w16 = w4 + w15;
    casadi_real w17 = -w16;
    res0[112 + s] = w17;
    w17 = arg1[54];
    casadi_real w18 = w17 * w0;
    casadi_real w19 = arg1[48];
    casadi_real w20 = w19 * w6;
    casadi_real w21 = arg1[42];
    casadi_real w22 = w21 * w9;
    casadi_real w23 = arg1[45];
    casadi_real w24 = w23 * w12;
    w22 = w22 + w24;
    w24 = w22 * w13;
    w20 = w20 + w24;
    w23 = w23 * w9;
    w21 = w21 * w12;
    w23 = w23 - w21;
    w21 = w23 * w8;
    w20 = w20 + w21;
    w21 = arg1[51];
    w20 = w20 + w21;
    w24 = w20 * w1;
    casadi_real w25 = w18 + w24;
    res0[128 + s] = w25;
    casadi_real w26 = arg1[65];
    casadi_real w27 = arg1[44];
    casadi_real w28 = w27 * w9;
    casadi_real w29 = arg1[41];
    casadi_real w30 = w29 * w12;
    w28 = w28 - w30;
    w30 = arg1[66];
    w30 = w30 - w26;
    casadi_real w31 = w28 * w30;
    casadi_real w32 = w31 * w28;
    w32 = w26 + w32;
    casadi_real w33 = arg1[69];
    w29 = w29 * w9;
    w27 = w27 * w12;
    w29 = w29 + w27;
    w27 = w33 * w29;
    w12 = arg1[70];
    w9 = w12 * w28;
    w27 = w27 + w9;
    w9 = 0.5;
    casadi_real w34 = arg1[67];
    w9 = w9 * w34;
    w34 = (-0.5);
    w34 = w34 * w26;
    w9 = w9 + w34;
    w34 = arg1[47];
    casadi_real w35 = w9 * w34;
    w27 = w27 + w35;
    w35 = w27 + w27;
    w35 = w35 * w34;
    w32 = w32 + w35;
    w6 = w34 * w6;
    w29 = w29 * w13;
    w6 = w6 + w29;
    w28 = w28 * w8;
    w6 = w6 + w28;
    w28 = arg1[50];
    w6 = w6 + w28;
    w8 = w6 * w1;
    w6 = w6 * w8;
    w29 = w20 * w24;
    w13 = w6 + w29;
    w35 = w7 * w15;
    w13 = w13 + w35;
    w32 = w32 + w13;
    w32 = w32 - w6;
    w6 = arg1[59];
    w6 = w32 + w6;
    casadi_real w36 = arg1[53];
    w0 = w36 * w0;
    w36 = w36 * w0;
    casadi_real w37 = w17 * w18;
    casadi_real w38 = w36 + w37;
    w4 = w2 * w4;
    w38 = w38 + w4;
    w6 = w6 + w38;
    w6 = w6 - w36;
    res0[144 + s] = w6;
    res0[160 + s] = w16;
    res0[176 + s] = w3;
    w16 = w0 + w8;
    w6 = -w16;
    res0[192 + s] = w6;
    w6 = w27 * w19;
    w22 = w33 * w22;
    w36 = w12 * w23;
    w22 = w22 + w36;
    w36 = w9 * w19;
    w22 = w22 + w36;
    w36 = w22 * w34;
    w6 = w6 + w36;
    w36 = w31 * w23;
    w6 = w6 + w36;
    w20 = w20 * w8;
    w6 = w6 - w20;
    w20 = arg1[62];
    w20 = w6 + w20;
    w17 = w17 * w0;
    w20 = w20 - w17;
    res0[208 + s] = w20;
    w20 = w23 * w30;
    w23 = w20 * w23;
    w23 = w26 + w23;
    w17 = w22 + w22;
    w17 = w17 * w19;
    w23 = w23 + w17;
    w23 = w23 + w13;
    w23 = w23 - w29;
    w29 = arg1[60];
    w29 = w23 + w29;
    w29 = w29 + w38;
    w29 = w29 - w37;
    res0[224 + s] = w29;
    w25 = -w25;
    res0[240 + s] = w25;
    res0[256 + s] = w16;
    res0[272 + s] = w3;
    w27 = w27 * w5;
    w33 = w33 * w10;
    w12 = w12 * w11;
    w33 = w33 + w12;
    w9 = w9 * w5;
    w33 = w33 + w9;
    w9 = w33 * w34;
    w27 = w27 + w9;
    w31 = w31 * w11;
    w27 = w27 + w31;
    w31 = w7 * w8;
    w27 = w27 - w31;
    w31 = arg1[63];
    w31 = w27 + w31;
    w0 = w2 * w0;
    w31 = w31 - w0;
    res0[288 + s] = w31;
    w22 = w22 * w5;
    w31 = w33 * w19;
    w22 = w22 + w31;
    w20 = w20 * w11;
    w22 = w22 + w20;
    w7 = w7 * w24;
    w22 = w22 - w7;
    w7 = arg1[64];
    w7 = w22 + w7;
    w2 = w2 * w18;
    w7 = w7 - w2;
    res0[304 + s] = w7;
    w30 = w11 * w30;
    w30 = w30 * w11;
    w26 = w26 + w30;
    w33 = w33 + w33;
    w33 = w33 * w5;
    w26 = w26 + w33;
    w26 = w26 + w13;
    w26 = w26 - w35;
    w35 = arg1[61];
    w35 = w26 + w35;
    w35 = w35 + w38;
    w35 = w35 - w4;
    res0[320 + s] = w35;
    w35 = w19 * w15;
    w4 = w5 * w21;
    w38 = w19 * w14;
    w4 = w4 - w38;
    w38 = w4 * w1;
    w35 = w35 + w38;
    w38 = w5 * w24;
    w35 = w35 - w38;
    res0[336 + s] = w35;
    w38 = w5 * w8;
    w14 = w34 * w14;
    w13 = w5 * w28;
    w14 = w14 - w13;
    w13 = w14 * w1;
    w38 = w38 + w13;
    w13 = w34 * w15;
    w38 = w38 - w13;
    res0[352 + s] = w38;
    w13 = w34 * w24;
    w28 = w19 * w28;
    w21 = w34 * w21;
    w28 = w28 - w21;
    w1 = w28 * w1;
    w13 = w13 + w1;
    w1 = w19 * w8;
    w13 = w13 - w1;
    res0[368 + s] = w13;
    w32 = w32 * w34;
    w1 = w6 * w19;
    w32 = w32 + w1;
    w1 = w27 * w5;
    w32 = w32 + w1;
    w1 = w24 * w28;
    w32 = w32 + w1;
    w1 = w15 * w14;
    w32 = w32 - w1;
    res0[384 + s] = w32;
    w23 = w23 * w19;
    w6 = w6 * w34;
    w23 = w23 + w6;
    w6 = w22 * w5;
    w23 = w23 + w6;
    w15 = w15 * w4;
    w23 = w23 + w15;
    w15 = w8 * w28;
    w23 = w23 - w15;
    res0[400 + s] = w23;
    w26 = w26 * w5;
    w27 = w27 * w34;
    w26 = w26 + w27;
    w22 = w22 * w19;
    w26 = w26 + w22;
    w8 = w8 * w14;
    w26 = w26 + w8;
    w24 = w24 * w4;
    w26 = w26 - w24;
    res0[416 + s] = w26;
    w32 = w32 * w34;
    w23 = w23 * w19;
    w32 = w32 + w23;
    w26 = w26 * w5;
    w32 = w32 + w26;
    w35 = w35 * w4;
    w32 = w32 + w35;
    w38 = w38 * w14;
    w32 = w32 + w38;
    w13 = w13 * w28;
    w32 = w32 + w13;
    res0[432 + s] = w32;
  }
}

static const short snakecg_sp1_mass_matrix_sincos_block_entry[49] = {
    0, 1, 3, 6, 10, 15, 21, 1, 2, 4, 7, 11, 16, 22, 3, 4,
    5, 8, 12, 17, 23, 6, 7, 8, 9, 13, 18, 24, 10, 11, 12, 13,
    14, 19, 25, 15, 16, 17, 18, 19, 20, 26, 21, 22, 23, 24, 25, 26,
    27
};
/* The scatter of one output of a block to the batch layout: entry e of sample i, at
 * x[src[e] * 16 + i] in the block (src null: at x[e * 16 + i]), to y[i * nnz + e], m samples.
 * A full block goes 4 entries by 4 samples at a time, transposed in vector registers and
 * stored 4 entries at once (an AVX2 copy chosen at load time), the rest one by one. */
#include <string.h>
#if defined(__GNUC__) && !defined(__clang__) && __GNUC__ >= 11 && defined(__x86_64__) \
    && defined(__linux__)
typedef casadi_real snakecg_sp1_mass_matrix_sincos_block_v4 __attribute__((vector_size(32)));
typedef long long snakecg_sp1_mass_matrix_sincos_block_i4 __attribute__((vector_size(32)));
__attribute__((target_clones("arch=x86-64-v3", "default")))
static void snakecg_sp1_mass_matrix_sincos_block_scatter(const casadi_real* x, const short* src, casadi_int nnz,
    casadi_real* y, casadi_int m) {
  casadi_int e = 0, i;
  const snakecg_sp1_mass_matrix_sincos_block_i4 lo = {0, 4, 2, 6}, hi = {1, 5, 3, 7};
  const snakecg_sp1_mass_matrix_sincos_block_i4 first = {0, 1, 4, 5}, second = {2, 3, 6, 7};
  if (m == 16) {
    for (; e + 4 <= nnz; e += 4) {
      const casadi_real* x0 = x + (src ? src[e] : e) * 16;
      const casadi_real* x1 = x + (src ? src[e + 1] : e + 1) * 16;
      const casadi_real* x2 = x + (src ? src[e + 2] : e + 2) * 16;
      const casadi_real* x3 = x + (src ? src[e + 3] : e + 3) * 16;
      for (i = 0; i < 16; i += 4) {
        snakecg_sp1_mass_matrix_sincos_block_v4 a, b, c, d, t0, t1, t2, t3, r;
        memcpy(&a, x0 + i, sizeof a);
        memcpy(&b, x1 + i, sizeof b);
        memcpy(&c, x2 + i, sizeof c);
        memcpy(&d, x3 + i, sizeof d);
        t0 = __builtin_shuffle(a, b, lo); /* (a0 b0 a2 b2) */
        t1 = __builtin_shuffle(a, b, hi); /* (a1 b1 a3 b3) */
        t2 = __builtin_shuffle(c, d, lo);
        t3 = __builtin_shuffle(c, d, hi);
        r = __builtin_shuffle(t0, t2, first); /* sample i: (a0 b0 c0 d0) */
        memcpy(y + i * nnz + e, &r, sizeof r);
        r = __builtin_shuffle(t1, t3, first);
        memcpy(y + (i + 1) * nnz + e, &r, sizeof r);
        r = __builtin_shuffle(t0, t2, second);
        memcpy(y + (i + 2) * nnz + e, &r, sizeof r);
        r = __builtin_shuffle(t1, t3, second);
        memcpy(y + (i + 3) * nnz + e, &r, sizeof r);
      }
    }
  }
  for (; e < nnz; ++e) {
    const casadi_real* x0 = x + (src ? src[e] : e) * 16;
    for (i = 0; i < m; ++i) y[i * nnz + e] = x0[i];
  }
}
#else
static void snakecg_sp1_mass_matrix_sincos_block_scatter(const casadi_real* x, const short* src, casadi_int nnz,
    casadi_real* y, casadi_int m) {
  casadi_int e, i;
  for (e = 0; e < nnz; ++e) {
    const casadi_real* x0 = x + (src ? src[e] : e) * 16;
    for (i = 0; i < m; ++i) y[i * nnz + e] = x0[i];
  }
}
#endif

CASADI_SYMBOL_EXPORT int snakecg_sp1_batch_mass_matrix(casadi_int n, const casadi_real** arg,
    const casadi_int* stride, casadi_real** res) {
  casadi_real *work, *cq, *sq;
  casadi_real* in0;
  casadi_real* out0;
  casadi_int i, i0, m, e, src;
  int large;
  if (!(arg[0] && arg[1] && res[0] && stride[1] == 0)) {
    return snakecg_sp1_sample_batch_mass_matrix(n, arg, stride, res);
  }
  work = (casadi_real*) malloc(sizeof(casadi_real) * 608);
  if (!work) return -1;
  cq = work;
  sq = cq + 16;
  in0 = sq + 16;
  out0 = in0 + 128;
  for (i0 = 0; i0 < n; i0 += 16) {
    m = n - i0 < 16 ? n - i0 : 16;
    /* gather the entries the kernel and the sines and cosines read (the last sample repeated
     * into the unused slots of a partial block) */
    for (i = 0; i < 16; ++i) {
      src = i0 + (i < m ? i : m - 1);
      for (e = 7; e < 8; ++e) in0[e * 16 + i] = arg[0][src * stride[0] + e];
    }
    for (e = 0; e < 1; ++e) {
      const casadi_real* x = in0 + (7 + e) * 16;
      large = 0;
      for (i = 0; i < 16; ++i) large |= !(fabs(x[i]) <= SNAKECG_SINCOS_MAX);
      snakecg_sincos_block(x, cq + e * 16, sq + e * 16);
      if (large) snakecg_sincos_large(x, cq + e * 16, sq + e * 16, 16);
    }
    snakecg_sp1_mass_matrix_sincos_block(in0, arg[1], cq, sq, out0);
    /* scatter: the block's outputs to the batch layout; the kernel gives the
     * upper triangle of the symmetric output M, the table snakecg_sp1_mass_matrix_sincos_block_entry maps
     * each entry to its place in the triangle */
    snakecg_sp1_mass_matrix_sincos_block_scatter(out0, snakecg_sp1_mass_matrix_sincos_block_entry, 49, res[0] + i0 * 49, m);
  }
  free(work);
  return 0;
}
