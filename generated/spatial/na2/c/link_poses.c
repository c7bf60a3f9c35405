/* GENERATED FILE - DO NOT EDIT. C code emitted by CasADi for link_poses() of
 * generated/spatial/na2/ (see its model.py), plus its batched driver.
 * Regenerate with: python -m snakecg_derive.spatial --checked-in
 * spec sha256: 24971844b370b327c8b1ec05d13793d7cad6a8e8fa0affc7182db4e83ce1513f
 * tools: sympy 1.14.0, casadi 3.8.2, jinja2 3.1.6
 */
/* How to prefix internal symbols */
#ifdef CASADI_CODEGEN_PREFIX
  #define CASADI_NAMESPACE_CONCAT(NS, ID) _CASADI_NAMESPACE_CONCAT(NS, ID)
  #define _CASADI_NAMESPACE_CONCAT(NS, ID) NS ## ID
  #define CASADI_PREFIX(ID) CASADI_NAMESPACE_CONCAT(CODEGEN_PREFIX, ID)
#else
  #define CASADI_PREFIX(ID) snakecg_sp2_link_poses_ ## ID
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
CASADI_SYMBOL_EXPORT void snakecg_sp2_link_poses_casadi_version(int* major, int* minor, int* patch) {
  *major = 3;
  *minor = 8;
  *patch = 2;
}
CASADI_SYMBOL_EXPORT int snakecg_sp2_link_poses_casadi_int_size(void) { return (int) sizeof(casadi_int); }
CASADI_SYMBOL_EXPORT int snakecg_sp2_link_poses_casadi_real_size(void) { return (int) sizeof(casadi_real); }

static const casadi_int casadi_s0[3] = {9, 1, 1};
static const casadi_int casadi_s1[3] = {120, 1, 1};
static const casadi_int casadi_s2[3] = {3, 3, 1};
static const casadi_int casadi_s3[3] = {3, 9, 1};

/* snakecg_sp2_link_poses:(q[9],K[120])->(position[3x3],rotation[3x9]) */
static int casadi_f0(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem) {
  casadi_real a00, a01, a02, a03, a04, a05, a06, a07, a08, a09, a10, a11;
  casadi_real a12, a13, a14, a15, a16, a17, a18, a19, a20, a21, a22, a23;
  casadi_real a24, a25, a26, a27, a28, a29, a30, a31, a32, a33;
  a00=arg[0]? arg[0][0] : 0;
  if (res[0]!=0) res[0][0]=a00;
  a01=arg[0]? arg[0][1] : 0;
  if (res[0]!=0) res[0][1]=a01;
  a02=arg[0]? arg[0][2] : 0;
  if (res[0]!=0) res[0][2]=a02;
  a03=1.;
  a04=-2.;
  a05=arg[0]? arg[0][4] : 0;
  a06=casadi_sq(a05);
  a06=(a04*a06);
  a07=(a03+a06);
  a08=arg[0]? arg[0][5] : 0;
  a09=casadi_sq(a08);
  a09=(a04*a09);
  a07=(a07+a09);
  a10=arg[1]? arg[1][87] : 0;
  a11=(a07*a10);
  a12=arg[0]? arg[0][6] : 0;
  a13=(a04*a12);
  a14=(a13*a08);
  a15=arg[0]? arg[0][3] : 0;
  a16=(2.*a15);
  a17=(a16*a05);
  a14=(a14+a17);
  a18=arg[1]? arg[1][88] : 0;
  a19=(a14*a18);
  a11=(a11+a19);
  a12=(2.*a12);
  a19=(a12*a05);
  a16=(a16*a08);
  a19=(a19+a16);
  a20=arg[1]? arg[1][89] : 0;
  a21=(a19*a20);
  a11=(a11+a21);
  a11=(a11+a00);
  if (res[0]!=0) res[0][3]=a11;
  a00=(a12*a08);
  a00=(a00+a17);
  a17=(a00*a10);
  a21=casadi_sq(a15);
  a04=(a04*a21);
  a03=(a03+a04);
  a09=(a03+a09);
  a04=(a09*a18);
  a17=(a17+a04);
  a04=(a13*a15);
  a21=(2.*a05);
  a21=(a21*a08);
  a04=(a04+a21);
  a08=(a04*a20);
  a17=(a17+a08);
  a17=(a17+a01);
  if (res[0]!=0) res[0][4]=a17;
  a13=(a13*a05);
  a13=(a13+a16);
  a10=(a13*a10);
  a12=(a12*a15);
  a12=(a12+a21);
  a18=(a12*a18);
  a10=(a10+a18);
  a03=(a03+a06);
  a20=(a03*a20);
  a10=(a10+a20);
  a10=(a10+a02);
  if (res[0]!=0) res[0][5]=a10;
  a02=arg[1]? arg[1][75] : 0;
  a20=(a02*a07);
  a06=arg[1]? arg[1][76] : 0;
  a18=(a06*a14);
  a20=(a20+a18);
  a18=arg[1]? arg[1][77] : 0;
  a21=(a18*a19);
  a20=(a20+a21);
  a21=arg[1]? arg[1][92] : 0;
  a15=(a20*a21);
  a16=arg[1]? arg[1][69] : 0;
  a05=(a16*a07);
  a01=arg[1]? arg[1][70] : 0;
  a08=(a01*a14);
  a05=(a05+a08);
  a08=arg[1]? arg[1][71] : 0;
  a22=(a08*a19);
  a05=(a05+a22);
  a22=arg[0]? arg[0][7] : 0;
  a23=cos(a22);
  a24=(a05*a23);
  a25=arg[1]? arg[1][72] : 0;
  a26=(a25*a07);
  a27=arg[1]? arg[1][73] : 0;
  a28=(a27*a14);
  a26=(a26+a28);
  a28=arg[1]? arg[1][74] : 0;
  a29=(a28*a19);
  a26=(a26+a29);
  a22=sin(a22);
  a29=(a26*a22);
  a24=(a24+a29);
  a29=arg[1]? arg[1][90] : 0;
  a30=(a24*a29);
  a15=(a15+a30);
  a26=(a26*a23);
  a05=(a05*a22);
  a26=(a26-a05);
  a05=arg[1]? arg[1][91] : 0;
  a30=(a26*a05);
  a15=(a15+a30);
  a15=(a15+a11);
  if (res[0]!=0) res[0][6]=a15;
  a15=(a02*a00);
  a11=(a06*a09);
  a15=(a15+a11);
  a11=(a18*a04);
  a15=(a15+a11);
  a11=(a15*a21);
  a30=(a16*a00);
  a31=(a01*a09);
  a30=(a30+a31);
  a31=(a08*a04);
  a30=(a30+a31);
  a31=(a30*a23);
  a32=(a25*a00);
  a33=(a27*a09);
  a32=(a32+a33);
  a33=(a28*a04);
  a32=(a32+a33);
  a33=(a32*a22);
  a31=(a31+a33);
  a33=(a31*a29);
  a11=(a11+a33);
  a32=(a32*a23);
  a30=(a30*a22);
  a32=(a32-a30);
  a30=(a32*a05);
  a11=(a11+a30);
  a11=(a11+a17);
  if (res[0]!=0) res[0][7]=a11;
  a02=(a02*a13);
  a06=(a06*a12);
  a02=(a02+a06);
  a18=(a18*a03);
  a02=(a02+a18);
  a21=(a02*a21);
  a16=(a16*a13);
  a01=(a01*a12);
  a16=(a16+a01);
  a08=(a08*a03);
  a16=(a16+a08);
  a08=(a16*a23);
  a25=(a25*a13);
  a27=(a27*a12);
  a25=(a25+a27);
  a28=(a28*a03);
  a25=(a25+a28);
  a28=(a25*a22);
  a08=(a08+a28);
  a29=(a08*a29);
  a21=(a21+a29);
  a25=(a25*a23);
  a16=(a16*a22);
  a25=(a25-a16);
  a05=(a25*a05);
  a21=(a21+a05);
  a21=(a21+a10);
  if (res[0]!=0) res[0][8]=a21;
  if (res[1]!=0) res[1][0]=a07;
  if (res[1]!=0) res[1][1]=a00;
  if (res[1]!=0) res[1][2]=a13;
  if (res[1]!=0) res[1][3]=a14;
  if (res[1]!=0) res[1][4]=a09;
  if (res[1]!=0) res[1][5]=a12;
  if (res[1]!=0) res[1][6]=a19;
  if (res[1]!=0) res[1][7]=a04;
  if (res[1]!=0) res[1][8]=a03;
  a03=arg[1]? arg[1][57] : 0;
  a04=(a20*a03);
  a19=arg[1]? arg[1][51] : 0;
  a12=(a19*a24);
  a04=(a04+a12);
  a12=arg[1]? arg[1][54] : 0;
  a09=(a12*a26);
  a04=(a04+a09);
  if (res[1]!=0) res[1][9]=a04;
  a04=(a15*a03);
  a09=(a19*a31);
  a04=(a04+a09);
  a09=(a12*a32);
  a04=(a04+a09);
  if (res[1]!=0) res[1][10]=a04;
  a03=(a02*a03);
  a19=(a19*a08);
  a03=(a03+a19);
  a12=(a12*a25);
  a03=(a03+a12);
  if (res[1]!=0) res[1][11]=a03;
  a03=arg[1]? arg[1][58] : 0;
  a12=(a20*a03);
  a19=arg[1]? arg[1][52] : 0;
  a04=(a19*a24);
  a12=(a12+a04);
  a04=arg[1]? arg[1][55] : 0;
  a09=(a04*a26);
  a12=(a12+a09);
  if (res[1]!=0) res[1][12]=a12;
  a12=(a15*a03);
  a09=(a19*a31);
  a12=(a12+a09);
  a09=(a04*a32);
  a12=(a12+a09);
  if (res[1]!=0) res[1][13]=a12;
  a03=(a02*a03);
  a19=(a19*a08);
  a03=(a03+a19);
  a04=(a04*a25);
  a03=(a03+a04);
  if (res[1]!=0) res[1][14]=a03;
  a03=arg[1]? arg[1][59] : 0;
  a04=(a20*a03);
  a19=arg[1]? arg[1][53] : 0;
  a12=(a19*a24);
  a04=(a04+a12);
  a12=arg[1]? arg[1][56] : 0;
  a09=(a12*a26);
  a04=(a04+a09);
  if (res[1]!=0) res[1][15]=a04;
  a04=(a15*a03);
  a09=(a19*a31);
  a04=(a04+a09);
  a09=(a12*a32);
  a04=(a04+a09);
  if (res[1]!=0) res[1][16]=a04;
  a03=(a02*a03);
  a19=(a19*a08);
  a03=(a03+a19);
  a12=(a12*a25);
  a03=(a03+a12);
  if (res[1]!=0) res[1][17]=a03;
  a03=arg[1]? arg[1][86] : 0;
  a12=(a20*a03);
  a19=arg[1]? arg[1][84] : 0;
  a04=(a19*a24);
  a12=(a12+a04);
  a04=arg[1]? arg[1][85] : 0;
  a09=(a04*a26);
  a12=(a12+a09);
  a09=arg[1]? arg[1][66] : 0;
  a14=(a12*a09);
  a13=arg[1]? arg[1][60] : 0;
  a00=arg[1]? arg[1][80] : 0;
  a07=(a20*a00);
  a21=arg[1]? arg[1][78] : 0;
  a10=(a21*a24);
  a07=(a07+a10);
  a10=arg[1]? arg[1][79] : 0;
  a05=(a10*a26);
  a07=(a07+a05);
  a05=arg[0]? arg[0][8] : 0;
  a16=cos(a05);
  a22=(a07*a16);
  a23=arg[1]? arg[1][83] : 0;
  a20=(a20*a23);
  a29=arg[1]? arg[1][81] : 0;
  a24=(a29*a24);
  a20=(a20+a24);
  a24=arg[1]? arg[1][82] : 0;
  a26=(a24*a26);
  a20=(a20+a26);
  a05=sin(a05);
  a26=(a20*a05);
  a22=(a22+a26);
  a26=(a13*a22);
  a14=(a14+a26);
  a26=arg[1]? arg[1][63] : 0;
  a20=(a20*a16);
  a07=(a07*a05);
  a20=(a20-a07);
  a07=(a26*a20);
  a14=(a14+a07);
  if (res[1]!=0) res[1][18]=a14;
  a14=(a15*a03);
  a07=(a19*a31);
  a14=(a14+a07);
  a07=(a04*a32);
  a14=(a14+a07);
  a07=(a14*a09);
  a28=(a15*a00);
  a27=(a21*a31);
  a28=(a28+a27);
  a27=(a10*a32);
  a28=(a28+a27);
  a27=(a28*a16);
  a15=(a15*a23);
  a31=(a29*a31);
  a15=(a15+a31);
  a32=(a24*a32);
  a15=(a15+a32);
  a32=(a15*a05);
  a27=(a27+a32);
  a32=(a13*a27);
  a07=(a07+a32);
  a15=(a15*a16);
  a28=(a28*a05);
  a15=(a15-a28);
  a28=(a26*a15);
  a07=(a07+a28);
  if (res[1]!=0) res[1][19]=a07;
  a03=(a02*a03);
  a19=(a19*a08);
  a03=(a03+a19);
  a04=(a04*a25);
  a03=(a03+a04);
  a09=(a03*a09);
  a00=(a02*a00);
  a21=(a21*a08);
  a00=(a00+a21);
  a10=(a10*a25);
  a00=(a00+a10);
  a10=(a00*a16);
  a02=(a02*a23);
  a29=(a29*a08);
  a02=(a02+a29);
  a24=(a24*a25);
  a02=(a02+a24);
  a24=(a02*a05);
  a10=(a10+a24);
  a13=(a13*a10);
  a09=(a09+a13);
  a02=(a02*a16);
  a00=(a00*a05);
  a02=(a02-a00);
  a26=(a26*a02);
  a09=(a09+a26);
  if (res[1]!=0) res[1][20]=a09;
  a09=arg[1]? arg[1][67] : 0;
  a26=(a12*a09);
  a00=arg[1]? arg[1][61] : 0;
  a05=(a00*a22);
  a26=(a26+a05);
  a05=arg[1]? arg[1][64] : 0;
  a16=(a05*a20);
  a26=(a26+a16);
  if (res[1]!=0) res[1][21]=a26;
  a26=(a14*a09);
  a16=(a00*a27);
  a26=(a26+a16);
  a16=(a05*a15);
  a26=(a26+a16);
  if (res[1]!=0) res[1][22]=a26;
  a09=(a03*a09);
  a00=(a00*a10);
  a09=(a09+a00);
  a05=(a05*a02);
  a09=(a09+a05);
  if (res[1]!=0) res[1][23]=a09;
  a09=arg[1]? arg[1][68] : 0;
  a12=(a12*a09);
  a05=arg[1]? arg[1][62] : 0;
  a22=(a05*a22);
  a12=(a12+a22);
  a22=arg[1]? arg[1][65] : 0;
  a20=(a22*a20);
  a12=(a12+a20);
  if (res[1]!=0) res[1][24]=a12;
  a14=(a14*a09);
  a27=(a05*a27);
  a14=(a14+a27);
  a15=(a22*a15);
  a14=(a14+a15);
  if (res[1]!=0) res[1][25]=a14;
  a03=(a03*a09);
  a05=(a05*a10);
  a03=(a03+a05);
  a22=(a22*a02);
  a03=(a03+a22);
  if (res[1]!=0) res[1][26]=a03;
  return 0;
}

CASADI_SYMBOL_EXPORT int snakecg_sp2_link_poses(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem){
  return casadi_f0(arg, res, iw, w, mem);
}

CASADI_SYMBOL_EXPORT int snakecg_sp2_link_poses_checkout(void) {
  return 0;
}

CASADI_SYMBOL_EXPORT void snakecg_sp2_link_poses_release(int mem) {
}

CASADI_SYMBOL_EXPORT void snakecg_sp2_link_poses_incref(void) {
}

CASADI_SYMBOL_EXPORT void snakecg_sp2_link_poses_decref(void) {
}

CASADI_SYMBOL_EXPORT casadi_int snakecg_sp2_link_poses_n_in(void) { return 2;}

CASADI_SYMBOL_EXPORT casadi_int snakecg_sp2_link_poses_n_out(void) { return 2;}

CASADI_SYMBOL_EXPORT casadi_real snakecg_sp2_link_poses_default_in(casadi_int i) {
  switch (i) {
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const char* snakecg_sp2_link_poses_name_in(casadi_int i) {
  switch (i) {
    case 0: return "q";
    case 1: return "K";
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const char* snakecg_sp2_link_poses_name_out(casadi_int i) {
  switch (i) {
    case 0: return "position";
    case 1: return "rotation";
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const casadi_int* snakecg_sp2_link_poses_sparsity_in(casadi_int i) {
  switch (i) {
    case 0: return casadi_s0;
    case 1: return casadi_s1;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const casadi_int* snakecg_sp2_link_poses_sparsity_out(casadi_int i) {
  switch (i) {
    case 0: return casadi_s2;
    case 1: return casadi_s3;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT int snakecg_sp2_link_poses_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w) {
  if (sz_arg) *sz_arg = 2;
  if (sz_res) *sz_res = 2;
  if (sz_iw) *sz_iw = 0;
  if (sz_w) *sz_w = 0;
  return 0;
}

CASADI_SYMBOL_EXPORT int snakecg_sp2_link_poses_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w) {
  if (sz_arg) *sz_arg = 2*sizeof(const casadi_real*);
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

/* snakecg_sp2_link_poses_sincos: 373 CasADi instructions, printed one per line */
static void snakecg_sp2_link_poses_sincos(
    const casadi_real* restrict arg0,
    const casadi_real* restrict arg1,
    const casadi_real* restrict arg2,
    const casadi_real* restrict arg3,
    casadi_real* restrict res0,
    casadi_real* restrict res1) {
  casadi_real w0, w1, w2, w3, w4, w5, w6, w7, w8, w9;
  casadi_real w10, w11, w12, w13, w14, w15, w16, w17, w18, w19;
  casadi_real w20, w21, w22, w23, w24, w25, w26, w27, w28, w29;
  casadi_real w30, w31, w32, w33;
  w0 = arg0[0];
  res0[0] = w0;
  w1 = arg0[1];
  res0[1] = w1;
  w2 = arg0[2];
  res0[2] = w2;
  w3 = 1.0;
  w4 = (-2.0);
  w5 = arg0[4];
  w6 = w5 * w5;
  w6 = w4 * w6;
  w7 = w3 + w6;
  w8 = arg0[5];
  w9 = w8 * w8;
  w9 = w4 * w9;
  w7 = w7 + w9;
  w10 = arg1[87];
  w11 = w7 * w10;
  w12 = arg0[6];
  w13 = w4 * w12;
  w14 = w13 * w8;
  w15 = arg0[3];
  w16 = w15 + w15;
  w17 = w16 * w5;
  w14 = w14 + w17;
  w18 = arg1[88];
  w19 = w14 * w18;
  w11 = w11 + w19;
  w12 = w12 + w12;
  w19 = w12 * w5;
  w16 = w16 * w8;
  w19 = w19 + w16;
  w20 = arg1[89];
  w21 = w19 * w20;
  w11 = w11 + w21;
  w11 = w11 + w0;
  res0[3] = w11;
  w0 = w12 * w8;
  w0 = w0 + w17;
  w17 = w0 * w10;
  w21 = w15 * w15;
  w4 = w4 * w21;
  w3 = w3 + w4;
  w9 = w3 + w9;
  w4 = w9 * w18;
  w17 = w17 + w4;
  w4 = w13 * w15;
  w21 = w5 + w5;
  w21 = w21 * w8;
  w4 = w4 + w21;
  w8 = w4 * w20;
  w17 = w17 + w8;
  w17 = w17 + w1;
  res0[4] = w17;
  w13 = w13 * w5;
  w13 = w13 + w16;
  w10 = w13 * w10;
  w12 = w12 * w15;
  w12 = w12 + w21;
  w18 = w12 * w18;
  w10 = w10 + w18;
  w3 = w3 + w6;
  w20 = w3 * w20;
  w10 = w10 + w20;
  w10 = w10 + w2;
  res0[5] = w10;
  w2 = arg1[75];
  w20 = w2 * w7;
  w6 = arg1[76];
  w18 = w6 * w14;
  w20 = w20 + w18;
  w18 = arg1[77];
  w21 = w18 * w19;
  w20 = w20 + w21;
  w21 = arg1[92];
  w15 = w20 * w21;
  w16 = arg1[69];
  w5 = w16 * w7;
  w1 = arg1[70];
  w8 = w1 * w14;
  w5 = w5 + w8;
  w8 = arg1[71];
  w22 = w8 * w19;
  w5 = w5 + w22;
  w22 = arg2[0];
  w23 = w5 * w22;
  w24 = arg1[72];
  w25 = w24 * w7;
  w26 = arg1[73];
  w27 = w26 * w14;
  w25 = w25 + w27;
  w27 = arg1[74];
  w28 = w27 * w19;
  w25 = w25 + w28;
  w28 = arg3[0];
  w29 = w25 * w28;
  w23 = w23 + w29;
  w29 = arg1[90];
  w30 = w23 * w29;
  w15 = w15 + w30;
  w25 = w25 * w22;
  w5 = w5 * w28;
  w25 = w25 - w5;
  w5 = arg1[91];
  w30 = w25 * w5;
  w15 = w15 + w30;
  w15 = w15 + w11;
  res0[6] = w15;
  w15 = w2 * w0;
  w11 = w6 * w9;
  w15 = w15 + w11;
  w11 = w18 * w4;
  w15 = w15 + w11;
  w11 = w15 * w21;
  w30 = w16 * w0;
  w31 = w1 * w9;
  w30 = w30 + w31;
  w31 = w8 * w4;
  w30 = w30 + w31;
  w31 = w30 * w22;
  w32 = w24 * w0;
  w33 = w26 * w9;
  w32 = w32 + w33;
  w33 = w27 * w4;
  w32 = w32 + w33;
  w33 = w32 * w28;
  w31 = w31 + w33;
  w33 = w31 * w29;
  w11 = w11 + w33;
  w32 = w32 * w22;
  w30 = w30 * w28;
  w32 = w32 - w30;
  w30 = w32 * w5;
  w11 = w11 + w30;
  w11 = w11 + w17;
  res0[7] = w11;
  w2 = w2 * w13;
  w6 = w6 * w12;
  w2 = w2 + w6;
  w18 = w18 * w3;
  w2 = w2 + w18;
  w21 = w2 * w21;
  w16 = w16 * w13;
  w1 = w1 * w12;
  w16 = w16 + w1;
  w8 = w8 * w3;
  w16 = w16 + w8;
  w8 = w16 * w22;
  w24 = w24 * w13;
  w26 = w26 * w12;
  w24 = w24 + w26;
  w27 = w27 * w3;
  w24 = w24 + w27;
  w27 = w24 * w28;
  w8 = w8 + w27;
  w29 = w8 * w29;
  w21 = w21 + w29;
  w24 = w24 * w22;
  w16 = w16 * w28;
  w24 = w24 - w16;
  w5 = w24 * w5;
  w21 = w21 + w5;
  w21 = w21 + w10;
  res0[8] = w21;
  res1[0] = w7;
  res1[1] = w0;
  res1[2] = w13;
  res1[3] = w14;
  res1[4] = w9;
  res1[5] = w12;
  res1[6] = w19;
  res1[7] = w4;
  res1[8] = w3;
  w3 = arg1[57];
  w4 = w20 * w3;
  w19 = arg1[51];
  w12 = w19 * w23;
  w4 = w4 + w12;
  w12 = arg1[54];
  w9 = w12 * w25;
  w4 = w4 + w9;
  res1[9] = w4;
  w4 = w15 * w3;
  w9 = w19 * w31;
  w4 = w4 + w9;
  w9 = w12 * w32;
  w4 = w4 + w9;
  res1[10] = w4;
  w3 = w2 * w3;
  w19 = w19 * w8;
  w3 = w3 + w19;
  w12 = w12 * w24;
  w3 = w3 + w12;
  res1[11] = w3;
  w3 = arg1[58];
  w12 = w20 * w3;
  w19 = arg1[52];
  w4 = w19 * w23;
  w12 = w12 + w4;
  w4 = arg1[55];
  w9 = w4 * w25;
  w12 = w12 + w9;
  res1[12] = w12;
  w12 = w15 * w3;
  w9 = w19 * w31;
  w12 = w12 + w9;
  w9 = w4 * w32;
  w12 = w12 + w9;
  res1[13] = w12;
  w3 = w2 * w3;
  w19 = w19 * w8;
  w3 = w3 + w19;
  w4 = w4 * w24;
  w3 = w3 + w4;
  res1[14] = w3;
  w3 = arg1[59];
  w4 = w20 * w3;
  w19 = arg1[53];
  w12 = w19 * w23;
  w4 = w4 + w12;
  w12 = arg1[56];
  w9 = w12 * w25;
  w4 = w4 + w9;
  res1[15] = w4;
  w4 = w15 * w3;
  w9 = w19 * w31;
  w4 = w4 + w9;
  w9 = w12 * w32;
  w4 = w4 + w9;
  res1[16] = w4;
  w3 = w2 * w3;
  w19 = w19 * w8;
  w3 = w3 + w19;
  w12 = w12 * w24;
  w3 = w3 + w12;
  res1[17] = w3;
  w3 = arg1[86];
  w12 = w20 * w3;
  w19 = arg1[84];
  w4 = w19 * w23;
  w12 = w12 + w4;
  w4 = arg1[85];
  w9 = w4 * w25;
  w12 = w12 + w9;
  w9 = arg1[66];
  w14 = w12 * w9;
  w13 = arg1[60];
  w0 = arg1[80];
  w7 = w20 * w0;
  w21 = arg1[78];
  w10 = w21 * w23;
  w7 = w7 + w10;
  w10 = arg1[79];
  w5 = w10 * w25;
  w7 = w7 + w5;
  w5 = arg2[1];
  w16 = w7 * w5;
  w28 = arg1[83];
  w20 = w20 * w28;
  w22 = arg1[81];
  w23 = w22 * w23;
  w20 = w20 + w23;
  w23 = arg1[82];
  w25 = w23 * w25;
  w20 = w20 + w25;
  w25 = arg3[1];
  w29 = w20 * w25;
  w16 = w16 + w29;
  w29 = w13 * w16;
  w14 = w14 + w29;
  w29 = arg1[63];
  w20 = w20 * w5;
  w7 = w7 * w25;
  w20 = w20 - w7;
  w7 = w29 * w20;
  w14 = w14 + w7;
  res1[18] = w14;
  w14 = w15 * w3;
  w7 = w19 * w31;
  w14 = w14 + w7;
  w7 = w4 * w32;
  w14 = w14 + w7;
  w7 = w14 * w9;
  w27 = w15 * w0;
  w26 = w21 * w31;
  w27 = w27 + w26;
  w26 = w10 * w32;
  w27 = w27 + w26;
  w26 = w27 * w5;
  w15 = w15 * w28;
  w31 = w22 * w31;
  w15 = w15 + w31;
  w32 = w23 * w32;
  w15 = w15 + w32;
  w32 = w15 * w25;
  w26 = w26 + w32;
  w32 = w13 * w26;
  w7 = w7 + w32;
  w15 = w15 * w5;
  w27 = w27 * w25;
  w15 = w15 - w27;
  w27 = w29 * w15;
  w7 = w7 + w27;
  res1[19] = w7;
  w3 = w2 * w3;
  w19 = w19 * w8;
  w3 = w3 + w19;
  w4 = w4 * w24;
  w3 = w3 + w4;
  w9 = w3 * w9;
  w0 = w2 * w0;
  w21 = w21 * w8;
  w0 = w0 + w21;
  w10 = w10 * w24;
  w0 = w0 + w10;
  w10 = w0 * w5;
  w2 = w2 * w28;
  w22 = w22 * w8;
  w2 = w2 + w22;
  w23 = w23 * w24;
  w2 = w2 + w23;
  w23 = w2 * w25;
  w10 = w10 + w23;
  w13 = w13 * w10;
  w9 = w9 + w13;
  w2 = w2 * w5;
  w0 = w0 * w25;
  w2 = w2 - w0;
  w29 = w29 * w2;
  w9 = w9 + w29;
  res1[20] = w9;
  w9 = arg1[67];
  w29 = w12 * w9;
  w0 = arg1[61];
  w25 = w0 * w16;
  w29 = w29 + w25;
  w25 = arg1[64];
  w5 = w25 * w20;
  w29 = w29 + w5;
  res1[21] = w29;
  w29 = w14 * w9;
  w5 = w0 * w26;
  w29 = w29 + w5;
  w5 = w25 * w15;
  w29 = w29 + w5;
  res1[22] = w29;
  w9 = w3 * w9;
  w0 = w0 * w10;
  w9 = w9 + w0;
  w25 = w25 * w2;
  w9 = w9 + w25;
  res1[23] = w9;
  w9 = arg1[68];
  w12 = w12 * w9;
  w25 = arg1[62];
  w16 = w25 * w16;
  w12 = w12 + w16;
  w16 = arg1[65];
  w20 = w16 * w20;
  w12 = w12 + w20;
  res1[24] = w12;
  w14 = w14 * w9;
  w26 = w25 * w26;
  w14 = w14 + w26;
  w15 = w16 * w15;
  w14 = w14 + w15;
  res1[25] = w14;
  w3 = w3 * w9;
  w25 = w25 * w10;
  w3 = w3 + w25;
  w16 = w16 * w2;
  w3 = w3 + w16;
  res1[26] = w3;
}


CASADI_SYMBOL_EXPORT int snakecg_sp2_batch_link_poses(casadi_int n, const casadi_real** arg,
    const casadi_int* stride, casadi_real** res) {
  const casadi_real* a[2];
  casadi_real* r[2];
  casadi_int* iw = (casadi_int*) malloc(sizeof(casadi_int) * 1);
  casadi_real* w = (casadi_real*) malloc(sizeof(casadi_real) * 35);
  casadi_int i, k;
  int status = 0;
  if (!iw || !w) { free(iw); free(w); return -1; }
  for (k = 0; k < 2; ++k) a[k] = 0;
  for (k = 0; k < 2; ++k) r[k] = 0;
  if (arg[0] && arg[1] && res[0] && res[1]) {
    /* cos and sin of q[7..8] of 16 samples at a time, then snakecg_sp2_link_poses_sincos
     * per sample (a batch of one too, so that a batch equals its samples one by one) */
    const casadi_int na = 2, per = 16;
    casadi_real ang[32], ca[32], sa[32];
    casadi_int i0, m;
    int large;
    for (k = 0; k < 32; ++k) ang[k] = 0;
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
        snakecg_sp2_link_poses_sincos(arg[0] + (i0 + i) * stride[0], arg[1] + (i0 + i) * stride[1], ca + i * na, sa + i * na, res[0] + (i0 + i) * 9, res[1] + (i0 + i) * 27);
      }
    }
  } else {
    /* a null input or output (CasADi's convention: zeros in, nothing out): per sample */
    for (i = 0; i < n; ++i) {
      a[0] = arg[0] + i * stride[0];
      a[1] = arg[1] + i * stride[1];
      r[0] = res[0] + i * 9;
      r[1] = res[1] + i * 27;
      if (snakecg_sp2_link_poses(a, r, iw, w, 0)) { status = (int) (i + 1); break; }
    }
  }
  free(iw);
  free(w);
  return status;
}
