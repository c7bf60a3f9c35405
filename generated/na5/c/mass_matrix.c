/* GENERATED FILE - DO NOT EDIT. C code emitted by CasADi for mass_matrix() of
 * generated/na5/ (see its model.py), plus its batched driver.
 * Regenerate with: python -m snakecg_derive --checked-in
 * spec sha256: a2d11c24d4176a7337125b71c8295163762d302b9468a78a7f172d9e0a64cce1
 * tools: sympy 1.14.0, casadi 3.8.2, jinja2 3.1.6
 */
/* How to prefix internal symbols */
#ifdef CASADI_CODEGEN_PREFIX
  #define CASADI_NAMESPACE_CONCAT(NS, ID) _CASADI_NAMESPACE_CONCAT(NS, ID)
  #define _CASADI_NAMESPACE_CONCAT(NS, ID) NS ## ID
  #define CASADI_PREFIX(ID) CASADI_NAMESPACE_CONCAT(CODEGEN_PREFIX, ID)
#else
  #define CASADI_PREFIX(ID) snakecg_na5_mass_matrix_ ## ID
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
CASADI_SYMBOL_EXPORT void snakecg_na5_mass_matrix_casadi_version(int* major, int* minor, int* patch) {
  *major = 3;
  *minor = 8;
  *patch = 2;
}
CASADI_SYMBOL_EXPORT int snakecg_na5_mass_matrix_casadi_int_size(void) { return (int) sizeof(casadi_int); }
CASADI_SYMBOL_EXPORT int snakecg_na5_mass_matrix_casadi_real_size(void) { return (int) sizeof(casadi_real); }

static const casadi_int casadi_s0[3] = {8, 1, 1};
static const casadi_int casadi_s1[3] = {58, 1, 1};
static const casadi_int casadi_s2[3] = {8, 8, 1};

/* snakecg_na5_mass_matrix:(q[8],K[58])->(M[8x8]) */
static int casadi_f0(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem) {
  casadi_real a00, a01, a02, a03, a04, a05, a06, a07, a08, a09, a10, a11;
  casadi_real a12, a13, a14, a15, a16, a17, a18, a19, a20, a21, a22, a23;
  casadi_real a24, a25, a26, a27, a28, a29, a30, a31, a32, a33, a34, a35;
  a00=arg[1]? arg[1][24] : 0;
  if (res[0]!=0) res[0][0]=a00;
  a01=0.;
  if (res[0]!=0) res[0][1]=a01;
  a02=arg[1]? arg[1][30] : 0;
  a03=arg[0]? arg[0][2] : 0;
  a04=cos(a03);
  a05=arg[0]? arg[0][3] : 0;
  a06=cos(a05);
  a07=(a04*a06);
  a03=sin(a03);
  a05=sin(a05);
  a08=(a03*a05);
  a07=(a07-a08);
  a08=arg[0]? arg[0][4] : 0;
  a09=cos(a08);
  a10=(a07*a09);
  a05=(a04*a05);
  a06=(a06*a03);
  a05=(a05+a06);
  a08=sin(a08);
  a06=(a05*a08);
  a10=(a10-a06);
  a06=arg[0]? arg[0][5] : 0;
  a11=cos(a06);
  a12=(a10*a11);
  a08=(a07*a08);
  a09=(a09*a05);
  a08=(a08+a09);
  a06=sin(a06);
  a09=(a08*a06);
  a12=(a12-a09);
  a09=arg[0]? arg[0][6] : 0;
  a13=cos(a09);
  a14=(a12*a13);
  a06=(a10*a06);
  a11=(a11*a08);
  a06=(a06+a11);
  a09=sin(a09);
  a11=(a06*a09);
  a14=(a14-a11);
  a11=arg[0]? arg[0][7] : 0;
  a15=sin(a11);
  a16=(a14*a15);
  a11=cos(a11);
  a09=(a12*a09);
  a13=(a13*a06);
  a09=(a09+a13);
  a13=(a11*a09);
  a16=(a16+a13);
  a16=(a02*a16);
  a13=arg[1]? arg[1][29] : 0;
  a17=(a13*a09);
  a17=(a16+a17);
  a18=arg[1]? arg[1][28] : 0;
  a19=(a18*a06);
  a19=(a17+a19);
  a20=arg[1]? arg[1][27] : 0;
  a21=(a20*a08);
  a21=(a19+a21);
  a22=arg[1]? arg[1][26] : 0;
  a23=(a22*a05);
  a23=(a21+a23);
  a24=arg[1]? arg[1][25] : 0;
  a25=(a24*a03);
  a25=(a23+a25);
  a25=(-a25);
  if (res[0]!=0) res[0][2]=a25;
  a26=(-a23);
  if (res[0]!=0) res[0][3]=a26;
  a27=(-a21);
  if (res[0]!=0) res[0][4]=a27;
  a28=(-a19);
  if (res[0]!=0) res[0][5]=a28;
  a29=(-a17);
  if (res[0]!=0) res[0][6]=a29;
  a30=(-a16);
  if (res[0]!=0) res[0][7]=a30;
  if (res[0]!=0) res[0][8]=a01;
  if (res[0]!=0) res[0][9]=a00;
  a11=(a14*a11);
  a15=(a09*a15);
  a11=(a11-a15);
  a02=(a02*a11);
  a13=(a13*a14);
  a13=(a02+a13);
  a18=(a18*a12);
  a18=(a13+a18);
  a20=(a20*a10);
  a20=(a18+a20);
  a22=(a22*a07);
  a22=(a20+a22);
  a24=(a24*a04);
  a24=(a22+a24);
  if (res[0]!=0) res[0][10]=a24;
  if (res[0]!=0) res[0][11]=a22;
  if (res[0]!=0) res[0][12]=a20;
  if (res[0]!=0) res[0][13]=a18;
  if (res[0]!=0) res[0][14]=a13;
  if (res[0]!=0) res[0][15]=a02;
  if (res[0]!=0) res[0][16]=a25;
  if (res[0]!=0) res[0][17]=a24;
  a24=arg[1]? arg[1][10] : 0;
  a14=(a14*a24);
  a14=(a02*a14);
  a09=(a09*a24);
  a09=(a16*a09);
  a14=(a14+a09);
  a09=arg[1]? arg[1][57] : 0;
  a24=(a14+a09);
  a14=(a24+a14);
  a25=arg[1]? arg[1][56] : 0;
  a14=(a14+a25);
  a25=arg[1]? arg[1][9] : 0;
  a12=(a12*a25);
  a11=(a13*a12);
  a06=(a06*a25);
  a25=(a17*a06);
  a11=(a11+a25);
  a25=(a14+a11);
  a11=(a25+a11);
  a15=arg[1]? arg[1][55] : 0;
  a11=(a11+a15);
  a15=arg[1]? arg[1][8] : 0;
  a10=(a10*a15);
  a00=(a18*a10);
  a08=(a08*a15);
  a15=(a19*a08);
  a00=(a00+a15);
  a15=(a11+a00);
  a00=(a15+a00);
  a01=arg[1]? arg[1][54] : 0;
  a00=(a00+a01);
  a01=arg[1]? arg[1][7] : 0;
  a07=(a07*a01);
  a31=(a20*a07);
  a05=(a05*a01);
  a01=(a21*a05);
  a31=(a31+a01);
  a01=(a00+a31);
  a31=(a01+a31);
  a32=arg[1]? arg[1][53] : 0;
  a31=(a31+a32);
  a32=arg[1]? arg[1][6] : 0;
  a33=arg[1]? arg[1][18] : 0;
  a32=(a32-a33);
  a04=(a04*a32);
  a33=(a22*a04);
  a32=(a32*a03);
  a23=(a23*a32);
  a33=(a33+a23);
  a23=(a31+a33);
  a33=(a23+a33);
  a03=arg[1]? arg[1][52] : 0;
  a33=(a33+a03);
  if (res[0]!=0) res[0][18]=a33;
  if (res[0]!=0) res[0][19]=a23;
  a33=(a20*a04);
  a21=(a21*a32);
  a33=(a33+a21);
  a33=(a01+a33);
  if (res[0]!=0) res[0][20]=a33;
  a21=(a18*a07);
  a03=(a19*a05);
  a21=(a21+a03);
  a21=(a15+a21);
  a03=(a18*a04);
  a19=(a19*a32);
  a03=(a03+a19);
  a03=(a21+a03);
  if (res[0]!=0) res[0][21]=a03;
  a19=(a13*a10);
  a34=(a17*a08);
  a19=(a19+a34);
  a19=(a25+a19);
  a34=(a13*a07);
  a35=(a17*a05);
  a34=(a34+a35);
  a34=(a19+a34);
  a35=(a13*a04);
  a17=(a17*a32);
  a35=(a35+a17);
  a35=(a34+a35);
  if (res[0]!=0) res[0][22]=a35;
  a12=(a02*a12);
  a06=(a16*a06);
  a12=(a12+a06);
  a12=(a24+a12);
  a10=(a02*a10);
  a08=(a16*a08);
  a10=(a10+a08);
  a10=(a12+a10);
  a07=(a02*a07);
  a05=(a16*a05);
  a07=(a07+a05);
  a07=(a10+a07);
  a04=(a02*a04);
  a16=(a16*a32);
  a04=(a04+a16);
  a04=(a07+a04);
  if (res[0]!=0) res[0][23]=a04;
  if (res[0]!=0) res[0][24]=a26;
  if (res[0]!=0) res[0][25]=a22;
  if (res[0]!=0) res[0][26]=a23;
  if (res[0]!=0) res[0][27]=a31;
  if (res[0]!=0) res[0][28]=a01;
  if (res[0]!=0) res[0][29]=a21;
  if (res[0]!=0) res[0][30]=a34;
  if (res[0]!=0) res[0][31]=a07;
  if (res[0]!=0) res[0][32]=a27;
  if (res[0]!=0) res[0][33]=a20;
  if (res[0]!=0) res[0][34]=a33;
  if (res[0]!=0) res[0][35]=a01;
  if (res[0]!=0) res[0][36]=a00;
  if (res[0]!=0) res[0][37]=a15;
  if (res[0]!=0) res[0][38]=a19;
  if (res[0]!=0) res[0][39]=a10;
  if (res[0]!=0) res[0][40]=a28;
  if (res[0]!=0) res[0][41]=a18;
  if (res[0]!=0) res[0][42]=a03;
  if (res[0]!=0) res[0][43]=a21;
  if (res[0]!=0) res[0][44]=a15;
  if (res[0]!=0) res[0][45]=a11;
  if (res[0]!=0) res[0][46]=a25;
  if (res[0]!=0) res[0][47]=a12;
  if (res[0]!=0) res[0][48]=a29;
  if (res[0]!=0) res[0][49]=a13;
  if (res[0]!=0) res[0][50]=a35;
  if (res[0]!=0) res[0][51]=a34;
  if (res[0]!=0) res[0][52]=a19;
  if (res[0]!=0) res[0][53]=a25;
  if (res[0]!=0) res[0][54]=a14;
  if (res[0]!=0) res[0][55]=a24;
  if (res[0]!=0) res[0][56]=a30;
  if (res[0]!=0) res[0][57]=a02;
  if (res[0]!=0) res[0][58]=a04;
  if (res[0]!=0) res[0][59]=a07;
  if (res[0]!=0) res[0][60]=a10;
  if (res[0]!=0) res[0][61]=a12;
  if (res[0]!=0) res[0][62]=a24;
  if (res[0]!=0) res[0][63]=a09;
  return 0;
}

CASADI_SYMBOL_EXPORT int snakecg_na5_mass_matrix(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem){
  return casadi_f0(arg, res, iw, w, mem);
}

CASADI_SYMBOL_EXPORT int snakecg_na5_mass_matrix_checkout(void) {
  return 0;
}

CASADI_SYMBOL_EXPORT void snakecg_na5_mass_matrix_release(int mem) {
}

CASADI_SYMBOL_EXPORT void snakecg_na5_mass_matrix_incref(void) {
}

CASADI_SYMBOL_EXPORT void snakecg_na5_mass_matrix_decref(void) {
}

CASADI_SYMBOL_EXPORT casadi_int snakecg_na5_mass_matrix_n_in(void) { return 2;}

CASADI_SYMBOL_EXPORT casadi_int snakecg_na5_mass_matrix_n_out(void) { return 1;}

CASADI_SYMBOL_EXPORT casadi_real snakecg_na5_mass_matrix_default_in(casadi_int i) {
  switch (i) {
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const char* snakecg_na5_mass_matrix_name_in(casadi_int i) {
  switch (i) {
    case 0: return "q";
    case 1: return "K";
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const char* snakecg_na5_mass_matrix_name_out(casadi_int i) {
  switch (i) {
    case 0: return "M";
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const casadi_int* snakecg_na5_mass_matrix_sparsity_in(casadi_int i) {
  switch (i) {
    case 0: return casadi_s0;
    case 1: return casadi_s1;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const casadi_int* snakecg_na5_mass_matrix_sparsity_out(casadi_int i) {
  switch (i) {
    case 0: return casadi_s2;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT int snakecg_na5_mass_matrix_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w) {
  if (sz_arg) *sz_arg = 2;
  if (sz_res) *sz_res = 1;
  if (sz_iw) *sz_iw = 0;
  if (sz_w) *sz_w = 0;
  return 0;
}

CASADI_SYMBOL_EXPORT int snakecg_na5_mass_matrix_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w) {
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

/* snakecg_na5_mass_matrix_sincos: 235 CasADi instructions, printed one per line */
static void snakecg_na5_mass_matrix_sincos(
    const casadi_real* restrict arg0,
    const casadi_real* restrict arg1,
    const casadi_real* restrict arg2,
    const casadi_real* restrict arg3,
    casadi_real* restrict res0) {
  casadi_real w0, w1, w2, w3, w4, w5, w6, w7, w8, w9;
  casadi_real w10, w11, w12, w13, w14, w15, w16, w17, w18, w19;
  casadi_real w20, w21, w22, w23, w24, w25, w26, w27, w28, w29;
  casadi_real w30, w31, w32, w33, w34, w35;
  w0 = arg1[24];
  res0[0] = w0;
  w1 = 0.0;
  res0[1] = w1;
  w2 = arg1[30];
  w3 = arg2[0];
  w4 = arg2[1];
  w5 = w3 * w4;
  w6 = arg3[0];
  w7 = arg3[1];
  w8 = w6 * w7;
  w5 = w5 - w8;
  w8 = arg2[2];
  w9 = w5 * w8;
  w7 = w3 * w7;
  w4 = w4 * w6;
  w7 = w7 + w4;
  w4 = arg3[2];
  w10 = w7 * w4;
  w9 = w9 - w10;
  w10 = arg2[3];
  w11 = w9 * w10;
  w4 = w5 * w4;
  w8 = w8 * w7;
  w4 = w4 + w8;
  w8 = arg3[3];
  w12 = w4 * w8;
  w11 = w11 - w12;
  w12 = arg2[4];
  w13 = w11 * w12;
  w8 = w9 * w8;
  w10 = w10 * w4;
  w8 = w8 + w10;
  w10 = arg3[4];
  w14 = w8 * w10;
  w13 = w13 - w14;
  w14 = arg3[5];
  w15 = w13 * w14;
  w16 = arg2[5];
  w10 = w11 * w10;
  w12 = w12 * w8;
  w10 = w10 + w12;
  w12 = w16 * w10;
  w15 = w15 + w12;
  w15 = w2 * w15;
  w12 = arg1[29];
  w17 = w12 * w10;
  w17 = w15 + w17;
  w18 = arg1[28];
  w19 = w18 * w8;
  w19 = w17 + w19;
  w20 = arg1[27];
  w21 = w20 * w4;
  w21 = w19 + w21;
  w22 = arg1[26];
  w23 = w22 * w7;
  w23 = w21 + w23;
  w24 = arg1[25];
  w25 = w24 * w6;
  w25 = w23 + w25;
  w25 = -w25;
  res0[2] = w25;
  w26 = -w23;
  res0[3] = w26;
  w27 = -w21;
  res0[4] = w27;
  w28 = -w19;
  res0[5] = w28;
  w29 = -w17;
  res0[6] = w29;
  w30 = -w15;
  res0[7] = w30;
  res0[8] = w1;
  res0[9] = w0;
  w16 = w13 * w16;
  w14 = w10 * w14;
  w16 = w16 - w14;
  w2 = w2 * w16;
  w12 = w12 * w13;
  w12 = w2 + w12;
  w18 = w18 * w11;
  w18 = w12 + w18;
  w20 = w20 * w9;
  w20 = w18 + w20;
  w22 = w22 * w5;
  w22 = w20 + w22;
  w24 = w24 * w3;
  w24 = w22 + w24;
  res0[10] = w24;
  res0[11] = w22;
  res0[12] = w20;
  res0[13] = w18;
  res0[14] = w12;
  res0[15] = w2;
  res0[16] = w25;
  res0[17] = w24;
  w24 = arg1[10];
  w13 = w13 * w24;
  w13 = w2 * w13;
  w10 = w10 * w24;
  w10 = w15 * w10;
  w13 = w13 + w10;
  w10 = arg1[57];
  w24 = w13 + w10;
  w13 = w24 + w13;
  w25 = arg1[56];
  w13 = w13 + w25;
  w25 = arg1[9];
  w11 = w11 * w25;
  w16 = w12 * w11;
  w8 = w8 * w25;
  w25 = w17 * w8;
  w16 = w16 + w25;
  w25 = w13 + w16;
  w16 = w25 + w16;
  w14 = arg1[55];
  w16 = w16 + w14;
  w14 = arg1[8];
  w9 = w9 * w14;
  w0 = w18 * w9;
  w4 = w4 * w14;
  w14 = w19 * w4;
  w0 = w0 + w14;
  w14 = w16 + w0;
  w0 = w14 + w0;
  w1 = arg1[54];
  w0 = w0 + w1;
  w1 = arg1[7];
  w5 = w5 * w1;
  w31 = w20 * w5;
  w7 = w7 * w1;
  w1 = w21 * w7;
  w31 = w31 + w1;
  w1 = w0 + w31;
  w31 = w1 + w31;
  w32 = arg1[53];
  w31 = w31 + w32;
  w32 = arg1[6];
  w33 = arg1[18];
  w32 = w32 - w33;
  w3 = w3 * w32;
  w33 = w22 * w3;
  w32 = w32 * w6;
  w23 = w23 * w32;
  w33 = w33 + w23;
  w23 = w31 + w33;
  w33 = w23 + w33;
  w6 = arg1[52];
  w33 = w33 + w6;
  res0[18] = w33;
  res0[19] = w23;
  w33 = w20 * w3;
  w21 = w21 * w32;
  w33 = w33 + w21;
  w33 = w1 + w33;
  res0[20] = w33;
  w21 = w18 * w5;
  w6 = w19 * w7;
  w21 = w21 + w6;
  w21 = w14 + w21;
  w6 = w18 * w3;
  w19 = w19 * w32;
  w6 = w6 + w19;
  w6 = w21 + w6;
  res0[21] = w6;
  w19 = w12 * w9;
  w34 = w17 * w4;
  w19 = w19 + w34;
  w19 = w25 + w19;
  w34 = w12 * w5;
  w35 = w17 * w7;
  w34 = w34 + w35;
  w34 = w19 + w34;
  w35 = w12 * w3;
  w17 = w17 * w32;
  w35 = w35 + w17;
  w35 = w34 + w35;
  res0[22] = w35;
  w11 = w2 * w11;
  w8 = w15 * w8;
  w11 = w11 + w8;
  w11 = w24 + w11;
  w9 = w2 * w9;
  w4 = w15 * w4;
  w9 = w9 + w4;
  w9 = w11 + w9;
  w5 = w2 * w5;
  w7 = w15 * w7;
  w5 = w5 + w7;
  w5 = w9 + w5;
  w3 = w2 * w3;
  w15 = w15 * w32;
  w3 = w3 + w15;
  w3 = w5 + w3;
  res0[23] = w3;
  res0[24] = w26;
  res0[25] = w22;
  res0[26] = w23;
  res0[27] = w31;
  res0[28] = w1;
  res0[29] = w21;
  res0[30] = w34;
  res0[31] = w5;
  res0[32] = w27;
  res0[33] = w20;
  res0[34] = w33;
  res0[35] = w1;
  res0[36] = w0;
  res0[37] = w14;
  res0[38] = w19;
  res0[39] = w9;
  res0[40] = w28;
  res0[41] = w18;
  res0[42] = w6;
  res0[43] = w21;
  res0[44] = w14;
  res0[45] = w16;
  res0[46] = w25;
  res0[47] = w11;
  res0[48] = w29;
  res0[49] = w12;
  res0[50] = w35;
  res0[51] = w34;
  res0[52] = w19;
  res0[53] = w25;
  res0[54] = w13;
  res0[55] = w24;
  res0[56] = w30;
  res0[57] = w2;
  res0[58] = w3;
  res0[59] = w5;
  res0[60] = w9;
  res0[61] = w11;
  res0[62] = w24;
  res0[63] = w10;
}


CASADI_SYMBOL_EXPORT int snakecg_na5_batch_mass_matrix(casadi_int n, const casadi_real** arg,
    const casadi_int* stride, casadi_real** res) {
  const casadi_real* a[2];
  casadi_real* r[1];
  casadi_int* iw = (casadi_int*) malloc(sizeof(casadi_int) * 1);
  casadi_real* w = (casadi_real*) malloc(sizeof(casadi_real) * 37);
  casadi_int i, k;
  int status = 0;
  if (!iw || !w) { free(iw); free(w); return -1; }
  for (k = 0; k < 2; ++k) a[k] = 0;
  for (k = 0; k < 1; ++k) r[k] = 0;
  if (arg[0] && arg[1] && res[0]) {
    /* cos and sin of q[2..7] of 16 samples at a time, then snakecg_na5_mass_matrix_sincos
     * per sample (a batch of one too, so that a batch equals its samples one by one) */
    const casadi_int na = 6, per = 16;
    casadi_real ang[96], ca[96], sa[96];
    casadi_int i0, m;
    int large;
    for (k = 0; k < 96; ++k) ang[k] = 0;
    for (i0 = 0; i0 < n; i0 += per) {
      m = n - i0 < per ? n - i0 : per;
      large = 0;
      for (i = 0; i < m; ++i) {
        const casadi_real* q = arg[0] + (i0 + i) * stride[0] + 2;
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
        snakecg_na5_mass_matrix_sincos(arg[0] + (i0 + i) * stride[0], arg[1] + (i0 + i) * stride[1], ca + i * na, sa + i * na, res[0] + (i0 + i) * 64);
      }
    }
  } else {
    /* a null input or output (CasADi's convention: zeros in, nothing out): per sample */
    for (i = 0; i < n; ++i) {
      a[0] = arg[0] + i * stride[0];
      a[1] = arg[1] + i * stride[1];
      r[0] = res[0] + i * 64;
      if (snakecg_na5_mass_matrix(a, r, iw, w, 0)) { status = (int) (i + 1); break; }
    }
  }
  free(iw);
  free(w);
  return status;
}
