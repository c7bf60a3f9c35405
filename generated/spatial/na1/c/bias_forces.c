/* GENERATED FILE - DO NOT EDIT. C code emitted by CasADi for bias_forces() of
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
  #define CASADI_PREFIX(ID) snakecg_sp1_bias_forces_ ## ID
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
CASADI_SYMBOL_EXPORT void snakecg_sp1_bias_forces_casadi_version(int* major, int* minor, int* patch) {
  *major = 3;
  *minor = 8;
  *patch = 2;
}
CASADI_SYMBOL_EXPORT int snakecg_sp1_bias_forces_casadi_int_size(void) { return (int) sizeof(casadi_int); }
CASADI_SYMBOL_EXPORT int snakecg_sp1_bias_forces_casadi_real_size(void) { return (int) sizeof(casadi_real); }

static const casadi_int casadi_s0[3] = {8, 1, 1};
static const casadi_int casadi_s1[3] = {7, 1, 1};
static const casadi_int casadi_s2[3] = {71, 1, 1};

/* snakecg_sp1_bias_forces:(q[8],v[7],K[71])->(h[7]) */
static int casadi_f0(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem) {
  casadi_real a00, a01, a02, a03, a04, a05, a06, a07, a08, a09, a10, a11;
  casadi_real a12, a13, a14, a15, a16, a17, a18, a19, a20, a21, a22, a23;
  casadi_real a24, a25, a26, a27, a28, a29, a30, a31, a32, a33, a34, a35;
  casadi_real a36, a37, a38, a39, a40, a41, a42, a43, a44, a45, a46, a47;
  casadi_real a48, a49, a50, a51, a52, a53, a54, a55, a56;
  a00=arg[2]? arg[2][0] : 0;
  a01=arg[1]? arg[1][2] : 0;
  a02=arg[1]? arg[1][4] : 0;
  a03=(a01*a02);
  a04=arg[1]? arg[1][1] : 0;
  a05=arg[1]? arg[1][5] : 0;
  a06=(a04*a05);
  a03=(a03-a06);
  a06=arg[2]? arg[2][54] : 0;
  a07=arg[1]? arg[1][3] : 0;
  a08=(a06*a07);
  a09=arg[2]? arg[2][53] : 0;
  a10=(a09*a02);
  a08=(a08-a10);
  a10=(a08*a02);
  a10=(a03+a10);
  a11=(a09*a05);
  a12=arg[2]? arg[2][55] : 0;
  a13=(a12*a07);
  a11=(a11-a13);
  a13=(a11*a05);
  a10=(a10-a13);
  a13=1.;
  a14=-2.;
  a15=arg[0]? arg[0][4] : 0;
  a16=casadi_sq(a15);
  a16=(a14*a16);
  a17=(a13+a16);
  a18=arg[0]? arg[0][5] : 0;
  a19=casadi_sq(a18);
  a19=(a14*a19);
  a17=(a17+a19);
  a20=arg[2]? arg[2][29] : 0;
  a17=(a17*a20);
  a21=arg[0]? arg[0][6] : 0;
  a22=(2.*a21);
  a23=(a22*a18);
  a24=arg[0]? arg[0][3] : 0;
  a25=(2.*a24);
  a26=(a25*a15);
  a23=(a23+a26);
  a27=arg[2]? arg[2][30] : 0;
  a23=(a23*a27);
  a17=(a17+a23);
  a21=(a14*a21);
  a23=(a21*a15);
  a25=(a25*a18);
  a23=(a23+a25);
  a28=arg[2]? arg[2][31] : 0;
  a23=(a23*a28);
  a17=(a17+a23);
  a10=(a10-a17);
  a10=(a00*a10);
  a23=arg[2]? arg[2][1] : 0;
  a29=arg[2]? arg[2][51] : 0;
  a30=(a29*a07);
  a31=arg[2]? arg[2][50] : 0;
  a32=(a31*a02);
  a30=(a30-a32);
  a32=(a30*a02);
  a03=(a03+a32);
  a32=(a31*a05);
  a33=arg[2]? arg[2][52] : 0;
  a34=(a33*a07);
  a32=(a32-a34);
  a34=(a32*a05);
  a03=(a03-a34);
  a34=arg[2]? arg[2][48] : 0;
  a35=arg[2]? arg[2][58] : 0;
  a36=(a34*a35);
  a37=arg[2]? arg[2][42] : 0;
  a38=arg[0]? arg[0][7] : 0;
  a39=cos(a38);
  a40=(a37*a39);
  a41=arg[2]? arg[2][45] : 0;
  a38=sin(a38);
  a42=(a41*a38);
  a40=(a40+a42);
  a42=arg[2]? arg[2][56] : 0;
  a43=(a40*a42);
  a36=(a36+a43);
  a41=(a41*a39);
  a37=(a37*a38);
  a41=(a41-a37);
  a37=arg[2]? arg[2][57] : 0;
  a43=(a41*a37);
  a36=(a36+a43);
  a43=arg[2]? arg[2][47] : 0;
  a44=arg[1]? arg[1][6] : 0;
  a45=(a43*a44);
  a45=(a07+a45);
  a46=(a36*a45);
  a47=(a43*a35);
  a48=arg[2]? arg[2][41] : 0;
  a49=(a48*a39);
  a50=arg[2]? arg[2][44] : 0;
  a51=(a50*a38);
  a49=(a49+a51);
  a51=(a49*a42);
  a47=(a47+a51);
  a50=(a50*a39);
  a48=(a48*a38);
  a50=(a50-a48);
  a48=(a50*a37);
  a47=(a47+a48);
  a48=(a34*a44);
  a48=(a02+a48);
  a51=(a47*a48);
  a46=(a46-a51);
  a51=(a46*a48);
  a03=(a03+a51);
  a51=(a43*a05);
  a52=arg[2]? arg[2][49] : 0;
  a53=(a52*a07);
  a51=(a51-a53);
  a51=(a44*a51);
  a35=(a52*a35);
  a53=arg[2]? arg[2][43] : 0;
  a54=(a53*a39);
  a55=arg[2]? arg[2][46] : 0;
  a56=(a55*a38);
  a54=(a54+a56);
  a42=(a54*a42);
  a35=(a35+a42);
  a55=(a55*a39);
  a53=(a53*a38);
  a55=(a55-a53);
  a37=(a55*a37);
  a35=(a35+a37);
  a37=(a51*a35);
  a03=(a03+a37);
  a37=(a52*a44);
  a37=(a05+a37);
  a53=(a47*a37);
  a38=(a35*a45);
  a53=(a53-a38);
  a38=(a53*a37);
  a03=(a03-a38);
  a38=(a34*a07);
  a39=(a43*a02);
  a38=(a38-a39);
  a38=(a44*a38);
  a39=(a38*a36);
  a03=(a03-a39);
  a03=(a03-a17);
  a03=(a23*a03);
  a17=(a10+a03);
  if (res[0]!=0) res[0][0]=a17;
  a17=arg[1]? arg[1][0] : 0;
  a39=(a17*a05);
  a01=(a01*a07);
  a39=(a39-a01);
  a01=(a12*a02);
  a42=(a06*a05);
  a01=(a01-a42);
  a42=(a01*a05);
  a42=(a39+a42);
  a08=(a08*a07);
  a42=(a42-a08);
  a08=(a21*a18);
  a08=(a08+a26);
  a08=(a08*a20);
  a26=casadi_sq(a24);
  a14=(a14*a26);
  a13=(a13+a14);
  a19=(a13+a19);
  a19=(a19*a27);
  a08=(a08+a19);
  a19=(a22*a24);
  a14=(2.*a15);
  a14=(a14*a18);
  a19=(a19+a14);
  a19=(a19*a28);
  a08=(a08+a19);
  a42=(a42-a08);
  a42=(a00*a42);
  a19=(a33*a02);
  a18=(a29*a05);
  a19=(a19-a18);
  a18=(a19*a05);
  a39=(a39+a18);
  a30=(a30*a07);
  a39=(a39-a30);
  a30=(a35*a48);
  a18=(a36*a37);
  a30=(a30-a18);
  a18=(a30*a37);
  a39=(a39+a18);
  a18=(a38*a47);
  a39=(a39+a18);
  a46=(a46*a45);
  a39=(a39-a46);
  a46=(a52*a02);
  a18=(a34*a05);
  a46=(a46-a18);
  a44=(a44*a46);
  a46=(a44*a35);
  a39=(a39-a46);
  a39=(a39-a08);
  a39=(a23*a39);
  a08=(a42+a39);
  if (res[0]!=0) res[0][1]=a08;
  a04=(a04*a07);
  a17=(a17*a02);
  a04=(a04-a17);
  a11=(a11*a07);
  a11=(a04+a11);
  a01=(a01*a02);
  a11=(a11-a01);
  a22=(a22*a15);
  a22=(a22+a25);
  a22=(a22*a20);
  a21=(a21*a24);
  a21=(a21+a14);
  a21=(a21*a27);
  a22=(a22+a21);
  a13=(a13+a16);
  a13=(a13*a28);
  a22=(a22+a13);
  a11=(a11-a22);
  a00=(a00*a11);
  a32=(a32*a07);
  a04=(a04+a32);
  a19=(a19*a02);
  a04=(a04-a19);
  a53=(a53*a45);
  a04=(a04+a53);
  a53=(a44*a36);
  a04=(a04+a53);
  a30=(a30*a48);
  a04=(a04-a30);
  a30=(a51*a47);
  a04=(a04-a30);
  a04=(a04-a22);
  a23=(a23*a04);
  a04=(a00+a23);
  if (res[0]!=0) res[0][2]=a04;
  a04=arg[2]? arg[2][65] : 0;
  a22=arg[2]? arg[2][66] : 0;
  a22=(a22-a04);
  a30=(a50*a22);
  a53=(a30*a50);
  a53=(a04+a53);
  a19=arg[2]? arg[2][69] : 0;
  a49=(a19*a49);
  a32=arg[2]? arg[2][70] : 0;
  a50=(a32*a50);
  a49=(a49+a50);
  a50=5.0000000000000000e-01;
  a11=arg[2]? arg[2][67] : 0;
  a50=(a50*a11);
  a11=-5.0000000000000000e-01;
  a11=(a11*a04);
  a50=(a50+a11);
  a11=(a50*a43);
  a49=(a49+a11);
  a11=(2.*a49);
  a11=(a11*a43);
  a53=(a53+a11);
  a11=(a53*a44);
  a13=(a49*a34);
  a40=(a19*a40);
  a28=(a32*a41);
  a40=(a40+a28);
  a28=(a50*a34);
  a40=(a40+a28);
  a28=(a40*a43);
  a13=(a13+a28);
  a28=(a30*a41);
  a13=(a13+a28);
  a28=(a13*a51);
  a11=(a11+a28);
  a49=(a49*a52);
  a19=(a19*a54);
  a32=(a32*a55);
  a19=(a19+a32);
  a50=(a50*a52);
  a19=(a19+a50);
  a50=(a19*a43);
  a49=(a49+a50);
  a30=(a30*a55);
  a49=(a49+a30);
  a30=(a49*a38);
  a11=(a11+a30);
  a30=(a49*a45);
  a50=(a40*a52);
  a32=(a19*a34);
  a50=(a50+a32);
  a32=(a41*a22);
  a54=(a32*a55);
  a50=(a50+a54);
  a54=(a50*a48);
  a30=(a30+a54);
  a22=(a55*a22);
  a22=(a22*a55);
  a22=(a04+a22);
  a19=(2.*a19);
  a19=(a19*a52);
  a22=(a22+a19);
  a19=(a22*a37);
  a30=(a30+a19);
  a19=(a30*a48);
  a11=(a11+a19);
  a36=(a36+a29);
  a19=(a36*a23);
  a11=(a11+a19);
  a19=(a13*a45);
  a32=(a32*a41);
  a04=(a04+a32);
  a40=(2.*a40);
  a40=(a40*a34);
  a04=(a04+a40);
  a40=(a04*a48);
  a19=(a19+a40);
  a40=(a50*a37);
  a19=(a19+a40);
  a40=(a19*a37);
  a11=(a11-a40);
  a35=(a35+a33);
  a40=(a35*a39);
  a11=(a11-a40);
  a40=arg[2]? arg[2][63] : 0;
  a32=(a40*a07);
  a41=arg[2]? arg[2][64] : 0;
  a55=(a41*a02);
  a32=(a32+a55);
  a55=arg[2]? arg[2][61] : 0;
  a55=(a55*a05);
  a32=(a32+a55);
  a55=(a32*a02);
  a55=(a11+a55);
  a54=(a06*a00);
  a55=(a55+a54);
  a54=arg[2]? arg[2][62] : 0;
  a28=(a54*a07);
  a16=arg[2]? arg[2][60] : 0;
  a16=(a16*a02);
  a28=(a28+a16);
  a41=(a41*a05);
  a28=(a28+a41);
  a41=(a28*a05);
  a55=(a55-a41);
  a41=(a12*a42);
  a55=(a55-a41);
  if (res[0]!=0) res[0][3]=a55;
  a55=(a13*a44);
  a04=(a04*a51);
  a55=(a55+a04);
  a04=(a50*a38);
  a55=(a55+a04);
  a53=(a53*a45);
  a13=(a13*a48);
  a53=(a53+a13);
  a13=(a49*a37);
  a53=(a53+a13);
  a37=(a53*a37);
  a55=(a55+a37);
  a35=(a35*a03);
  a55=(a55+a35);
  a30=(a30*a45);
  a55=(a55-a30);
  a47=(a47+a31);
  a30=(a47*a23);
  a55=(a55-a30);
  a30=arg[2]? arg[2][59] : 0;
  a30=(a30*a07);
  a54=(a54*a02);
  a30=(a30+a54);
  a40=(a40*a05);
  a30=(a30+a40);
  a05=(a30*a05);
  a05=(a55+a05);
  a12=(a12*a10);
  a05=(a05+a12);
  a32=(a32*a07);
  a05=(a05-a32);
  a00=(a09*a00);
  a05=(a05-a00);
  if (res[0]!=0) res[0][4]=a05;
  a49=(a49*a44);
  a50=(a50*a51);
  a49=(a49+a50);
  a22=(a22*a38);
  a49=(a49+a22);
  a19=(a19*a45);
  a49=(a49+a19);
  a47=(a47*a39);
  a49=(a49+a47);
  a53=(a53*a48);
  a49=(a49-a53);
  a36=(a36*a03);
  a49=(a49-a36);
  a28=(a28*a07);
  a28=(a49+a28);
  a09=(a09*a42);
  a28=(a28+a09);
  a30=(a30*a02);
  a28=(a28-a30);
  a06=(a06*a10);
  a28=(a28-a06);
  if (res[0]!=0) res[0][5]=a28;
  a11=(a11*a43);
  a55=(a55*a34);
  a11=(a11+a55);
  a49=(a49*a52);
  a11=(a11+a49);
  a49=(a52*a29);
  a55=(a34*a33);
  a49=(a49-a55);
  a03=(a03*a49);
  a11=(a11+a03);
  a33=(a43*a33);
  a52=(a52*a31);
  a33=(a33-a52);
  a39=(a39*a33);
  a11=(a11+a39);
  a34=(a34*a31);
  a43=(a43*a29);
  a34=(a34-a43);
  a23=(a23*a34);
  a11=(a11+a23);
  if (res[0]!=0) res[0][6]=a11;
  return 0;
}

CASADI_SYMBOL_EXPORT int snakecg_sp1_bias_forces(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem){
  return casadi_f0(arg, res, iw, w, mem);
}

CASADI_SYMBOL_EXPORT int snakecg_sp1_bias_forces_checkout(void) {
  return 0;
}

CASADI_SYMBOL_EXPORT void snakecg_sp1_bias_forces_release(int mem) {
}

CASADI_SYMBOL_EXPORT void snakecg_sp1_bias_forces_incref(void) {
}

CASADI_SYMBOL_EXPORT void snakecg_sp1_bias_forces_decref(void) {
}

CASADI_SYMBOL_EXPORT casadi_int snakecg_sp1_bias_forces_n_in(void) { return 3;}

CASADI_SYMBOL_EXPORT casadi_int snakecg_sp1_bias_forces_n_out(void) { return 1;}

CASADI_SYMBOL_EXPORT casadi_real snakecg_sp1_bias_forces_default_in(casadi_int i) {
  switch (i) {
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const char* snakecg_sp1_bias_forces_name_in(casadi_int i) {
  switch (i) {
    case 0: return "q";
    case 1: return "v";
    case 2: return "K";
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const char* snakecg_sp1_bias_forces_name_out(casadi_int i) {
  switch (i) {
    case 0: return "h";
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const casadi_int* snakecg_sp1_bias_forces_sparsity_in(casadi_int i) {
  switch (i) {
    case 0: return casadi_s0;
    case 1: return casadi_s1;
    case 2: return casadi_s2;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const casadi_int* snakecg_sp1_bias_forces_sparsity_out(casadi_int i) {
  switch (i) {
    case 0: return casadi_s1;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT int snakecg_sp1_bias_forces_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w) {
  if (sz_arg) *sz_arg = 3;
  if (sz_res) *sz_res = 1;
  if (sz_iw) *sz_iw = 0;
  if (sz_w) *sz_w = 0;
  return 0;
}

CASADI_SYMBOL_EXPORT int snakecg_sp1_bias_forces_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w) {
  if (sz_arg) *sz_arg = 3*sizeof(const casadi_real*);
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

/* snakecg_sp1_bias_forces_sincos: 421 CasADi instructions, printed one per line */
static void snakecg_sp1_bias_forces_sincos(
    const casadi_real* restrict arg0,
    const casadi_real* restrict arg1,
    const casadi_real* restrict arg2,
    const casadi_real* restrict arg3,
    const casadi_real* restrict arg4,
    casadi_real* restrict res0) {
  casadi_real w0, w1, w2, w3, w4, w5, w6, w7, w8, w9;
  casadi_real w10, w11, w12, w13, w14, w15, w16, w17, w18, w19;
  casadi_real w20, w21, w22, w23, w24, w25, w26, w27, w28, w29;
  casadi_real w30, w31, w32, w33, w34, w35, w36, w37, w38, w39;
  casadi_real w40, w41, w42, w43, w44, w45, w46, w47, w48, w49;
  casadi_real w50, w51, w52, w53, w54, w55, w56;
  w0 = arg2[0];
  w1 = arg1[2];
  w2 = arg1[4];
  w3 = w1 * w2;
  w4 = arg1[1];
  w5 = arg1[5];
  w6 = w4 * w5;
  w3 = w3 - w6;
  w6 = arg2[54];
  w7 = arg1[3];
  w8 = w6 * w7;
  w9 = arg2[53];
  w10 = w9 * w2;
  w8 = w8 - w10;
  w10 = w8 * w2;
  w10 = w3 + w10;
  w11 = w9 * w5;
  w12 = arg2[55];
  w13 = w12 * w7;
  w11 = w11 - w13;
  w13 = w11 * w5;
  w10 = w10 - w13;
  w13 = 1.0;
  w14 = (-2.0);
  w15 = arg0[4];
  w16 = w15 * w15;
  w16 = w14 * w16;
  w17 = w13 + w16;
  w18 = arg0[5];
  w19 = w18 * w18;
  w19 = w14 * w19;
  w17 = w17 + w19;
  w20 = arg2[29];
  w17 = w17 * w20;
  w21 = arg0[6];
  w22 = w21 + w21;
  w23 = w22 * w18;
  w24 = arg0[3];
  w25 = w24 + w24;
  w26 = w25 * w15;
  w23 = w23 + w26;
  w27 = arg2[30];
  w23 = w23 * w27;
  w17 = w17 + w23;
  w21 = w14 * w21;
  w23 = w21 * w15;
  w25 = w25 * w18;
  w23 = w23 + w25;
  w28 = arg2[31];
  w23 = w23 * w28;
  w17 = w17 + w23;
  w10 = w10 - w17;
  w10 = w0 * w10;
  w23 = arg2[1];
  w29 = arg2[51];
  w30 = w29 * w7;
  w31 = arg2[50];
  w32 = w31 * w2;
  w30 = w30 - w32;
  w32 = w30 * w2;
  w3 = w3 + w32;
  w32 = w31 * w5;
  w33 = arg2[52];
  w34 = w33 * w7;
  w32 = w32 - w34;
  w34 = w32 * w5;
  w3 = w3 - w34;
  w34 = arg2[48];
  w35 = arg2[58];
  w36 = w34 * w35;
  w37 = arg2[42];
  w38 = arg3[0];
  w39 = w37 * w38;
  w40 = arg2[45];
  w41 = arg4[0];
  w42 = w40 * w41;
  w39 = w39 + w42;
  w42 = arg2[56];
  w43 = w39 * w42;
  w36 = w36 + w43;
  w40 = w40 * w38;
  w37 = w37 * w41;
  w40 = w40 - w37;
  w37 = arg2[57];
  w43 = w40 * w37;
  w36 = w36 + w43;
  w43 = arg2[47];
  w44 = arg1[6];
  w45 = w43 * w44;
  w45 = w7 + w45;
  w46 = w36 * w45;
  w47 = w43 * w35;
  w48 = arg2[41];
  w49 = w48 * w38;
  w50 = arg2[44];
  w51 = w50 * w41;
  w49 = w49 + w51;
  w51 = w49 * w42;
  w47 = w47 + w51;
  w50 = w50 * w38;
  w48 = w48 * w41;
  w50 = w50 - w48;
  w48 = w50 * w37;
  w47 = w47 + w48;
  w48 = w34 * w44;
  w48 = w2 + w48;
  w51 = w47 * w48;
  w46 = w46 - w51;
  w51 = w46 * w48;
  w3 = w3 + w51;
  w51 = w43 * w5;
  w52 = arg2[49];
  w53 = w52 * w7;
  w51 = w51 - w53;
  w51 = w44 * w51;
  w35 = w52 * w35;
  w53 = arg2[43];
  w54 = w53 * w38;
  w55 = arg2[46];
  w56 = w55 * w41;
  w54 = w54 + w56;
  w42 = w54 * w42;
  w35 = w35 + w42;
  w55 = w55 * w38;
  w53 = w53 * w41;
  w55 = w55 - w53;
  w37 = w55 * w37;
  w35 = w35 + w37;
  w37 = w51 * w35;
  w3 = w3 + w37;
  w37 = w52 * w44;
  w37 = w5 + w37;
  w53 = w47 * w37;
  w41 = w35 * w45;
  w53 = w53 - w41;
  w41 = w53 * w37;
  w3 = w3 - w41;
  w41 = w34 * w7;
  w38 = w43 * w2;
  w41 = w41 - w38;
  w41 = w44 * w41;
  w38 = w41 * w36;
  w3 = w3 - w38;
  w3 = w3 - w17;
  w3 = w23 * w3;
  w17 = w10 + w3;
  res0[0] = w17;
  w17 = arg1[0];
  w38 = w17 * w5;
  w1 = w1 * w7;
  w38 = w38 - w1;
  w1 = w12 * w2;
  w42 = w6 * w5;
  w1 = w1 - w42;
  w42 = w1 * w5;
  w42 = w38 + w42;
  w8 = w8 * w7;
  w42 = w42 - w8;
  w8 = w21 * w18;
  w8 = w8 + w26;
  w8 = w8 * w20;
  w26 = w24 * w24;
  w14 = w14 * w26;
  w13 = w13 + w14;
  w19 = w13 + w19;
  w19 = w19 * w27;
  w8 = w8 + w19;
  w19 = w22 * w24;
  w14 = w15 + w15;
  w14 = w14 * w18;
  w19 = w19 + w14;
  w19 = w19 * w28;
  w8 = w8 + w19;
  w42 = w42 - w8;
  w42 = w0 * w42;
  w19 = w33 * w2;
  w18 = w29 * w5;
  w19 = w19 - w18;
  w18 = w19 * w5;
  w38 = w38 + w18;
  w30 = w30 * w7;
  w38 = w38 - w30;
  w30 = w35 * w48;
  w18 = w36 * w37;
  w30 = w30 - w18;
  w18 = w30 * w37;
  w38 = w38 + w18;
  w18 = w41 * w47;
  w38 = w38 + w18;
  w46 = w46 * w45;
  w38 = w38 - w46;
  w46 = w52 * w2;
  w18 = w34 * w5;
  w46 = w46 - w18;
  w44 = w44 * w46;
  w46 = w44 * w35;
  w38 = w38 - w46;
  w38 = w38 - w8;
  w38 = w23 * w38;
  w8 = w42 + w38;
  res0[1] = w8;
  w4 = w4 * w7;
  w17 = w17 * w2;
  w4 = w4 - w17;
  w11 = w11 * w7;
  w11 = w4 + w11;
  w1 = w1 * w2;
  w11 = w11 - w1;
  w22 = w22 * w15;
  w22 = w22 + w25;
  w22 = w22 * w20;
  w21 = w21 * w24;
  w21 = w21 + w14;
  w21 = w21 * w27;
  w22 = w22 + w21;
  w13 = w13 + w16;
  w13 = w13 * w28;
  w22 = w22 + w13;
  w11 = w11 - w22;
  w0 = w0 * w11;
  w32 = w32 * w7;
  w4 = w4 + w32;
  w19 = w19 * w2;
  w4 = w4 - w19;
  w53 = w53 * w45;
  w4 = w4 + w53;
  w53 = w44 * w36;
  w4 = w4 + w53;
  w30 = w30 * w48;
  w4 = w4 - w30;
  w30 = w51 * w47;
  w4 = w4 - w30;
  w4 = w4 - w22;
  w23 = w23 * w4;
  w4 = w0 + w23;
  res0[2] = w4;
  w4 = arg2[65];
  w22 = arg2[66];
  w22 = w22 - w4;
  w30 = w50 * w22;
  w53 = w30 * w50;
  w53 = w4 + w53;
  w19 = arg2[69];
  w49 = w19 * w49;
  w32 = arg2[70];
  w50 = w32 * w50;
  w49 = w49 + w50;
  w50 = 0.5;
  w11 = arg2[67];
  w50 = w50 * w11;
  w11 = (-0.5);
  w11 = w11 * w4;
  w50 = w50 + w11;
  w11 = w50 * w43;
  w49 = w49 + w11;
  w11 = w49 + w49;
  w11 = w11 * w43;
  w53 = w53 + w11;
  w11 = w53 * w44;
  w13 = w49 * w34;
  w39 = w19 * w39;
  w28 = w32 * w40;
  w39 = w39 + w28;
  w28 = w50 * w34;
  w39 = w39 + w28;
  w28 = w39 * w43;
  w13 = w13 + w28;
  w28 = w30 * w40;
  w13 = w13 + w28;
  w28 = w13 * w51;
  w11 = w11 + w28;
  w49 = w49 * w52;
  w19 = w19 * w54;
  w32 = w32 * w55;
  w19 = w19 + w32;
  w50 = w50 * w52;
  w19 = w19 + w50;
  w50 = w19 * w43;
  w49 = w49 + w50;
  w30 = w30 * w55;
  w49 = w49 + w30;
  w30 = w49 * w41;
  w11 = w11 + w30;
  w30 = w49 * w45;
  w50 = w39 * w52;
  w32 = w19 * w34;
  w50 = w50 + w32;
  w32 = w40 * w22;
  w54 = w32 * w55;
  w50 = w50 + w54;
  w54 = w50 * w48;
  w30 = w30 + w54;
  w22 = w55 * w22;
  w22 = w22 * w55;
  w22 = w4 + w22;
  w19 = w19 + w19;
  w19 = w19 * w52;
  w22 = w22 + w19;
  w19 = w22 * w37;
  w30 = w30 + w19;
  w19 = w30 * w48;
  w11 = w11 + w19;
  w36 = w36 + w29;
  w19 = w36 * w23;
  w11 = w11 + w19;
  w19 = w13 * w45;
  w32 = w32 * w40;
  w4 = w4 + w32;
  w39 = w39 + w39;
  w39 = w39 * w34;
  w4 = w4 + w39;
  w39 = w4 * w48;
  w19 = w19 + w39;
  w39 = w50 * w37;
  w19 = w19 + w39;
  w39 = w19 * w37;
  w11 = w11 - w39;
  w35 = w35 + w33;
  w39 = w35 * w38;
  w11 = w11 - w39;
  w39 = arg2[63];
  w32 = w39 * w7;
  w40 = arg2[64];
  w55 = w40 * w2;
  w32 = w32 + w55;
  w55 = arg2[61];
  w55 = w55 * w5;
  w32 = w32 + w55;
  w55 = w32 * w2;
  w55 = w11 + w55;
  w54 = w6 * w0;
  w55 = w55 + w54;
  w54 = arg2[62];
  w28 = w54 * w7;
  w16 = arg2[60];
  w16 = w16 * w2;
  w28 = w28 + w16;
  w40 = w40 * w5;
  w28 = w28 + w40;
  w40 = w28 * w5;
  w55 = w55 - w40;
  w40 = w12 * w42;
  w55 = w55 - w40;
  res0[3] = w55;
  w55 = w13 * w44;
  w4 = w4 * w51;
  w55 = w55 + w4;
  w4 = w50 * w41;
  w55 = w55 + w4;
  w53 = w53 * w45;
  w13 = w13 * w48;
  w53 = w53 + w13;
  w13 = w49 * w37;
  w53 = w53 + w13;
  w37 = w53 * w37;
  w55 = w55 + w37;
  w35 = w35 * w3;
  w55 = w55 + w35;
  w30 = w30 * w45;
  w55 = w55 - w30;
  w47 = w47 + w31;
  w30 = w47 * w23;
  w55 = w55 - w30;
  w30 = arg2[59];
  w30 = w30 * w7;
  w54 = w54 * w2;
  w30 = w30 + w54;
  w39 = w39 * w5;
  w30 = w30 + w39;
  w5 = w30 * w5;
  w5 = w55 + w5;
  w12 = w12 * w10;
  w5 = w5 + w12;
  w32 = w32 * w7;
  w5 = w5 - w32;
  w0 = w9 * w0;
  w5 = w5 - w0;
  res0[4] = w5;
  w49 = w49 * w44;
  w50 = w50 * w51;
  w49 = w49 + w50;
  w22 = w22 * w41;
  w49 = w49 + w22;
  w19 = w19 * w45;
  w49 = w49 + w19;
  w47 = w47 * w38;
  w49 = w49 + w47;
  w53 = w53 * w48;
  w49 = w49 - w53;
  w36 = w36 * w3;
  w49 = w49 - w36;
  w28 = w28 * w7;
  w28 = w49 + w28;
  w9 = w9 * w42;
  w28 = w28 + w9;
  w30 = w30 * w2;
  w28 = w28 - w30;
  w6 = w6 * w10;
  w28 = w28 - w6;
  res0[5] = w28;
  w11 = w11 * w43;
  w55 = w55 * w34;
  w11 = w11 + w55;
  w49 = w49 * w52;
  w11 = w11 + w49;
  w49 = w52 * w29;
  w55 = w34 * w33;
  w49 = w49 - w55;
  w3 = w3 * w49;
  w11 = w11 + w3;
  w33 = w43 * w33;
  w52 = w52 * w31;
  w33 = w33 - w52;
  w38 = w38 * w33;
  w11 = w11 + w38;
  w34 = w34 * w31;
  w43 = w43 * w29;
  w34 = w34 - w43;
  w23 = w23 * w34;
  w11 = w11 + w23;
  res0[6] = w11;
}


CASADI_SYMBOL_EXPORT int snakecg_sp1_sample_batch_bias_forces(casadi_int n, const casadi_real** arg,
    const casadi_int* stride, casadi_real** res) {
  const casadi_real* a[3];
  casadi_real* r[1];
  casadi_int* iw = (casadi_int*) malloc(sizeof(casadi_int) * 1);
  casadi_real* w = (casadi_real*) malloc(sizeof(casadi_real) * 58);
  casadi_int i, k;
  int status = 0;
  if (!iw || !w) { free(iw); free(w); return -1; }
  for (k = 0; k < 3; ++k) a[k] = 0;
  for (k = 0; k < 1; ++k) r[k] = 0;
  if (arg[0] && arg[1] && arg[2] && res[0]) {
    /* cos and sin of q[7..7] of 16 samples at a time, then snakecg_sp1_bias_forces_sincos
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
        snakecg_sp1_bias_forces_sincos(arg[0] + (i0 + i) * stride[0], arg[1] + (i0 + i) * stride[1], arg[2] + (i0 + i) * stride[2], ca + i * na, sa + i * na, res[0] + (i0 + i) * 7);
      }
    }
  } else {
    /* a null input or output (CasADi's convention: zeros in, nothing out): per sample */
    for (i = 0; i < n; ++i) {
      a[0] = arg[0] + i * stride[0];
      a[1] = arg[1] + i * stride[1];
      a[2] = arg[2] + i * stride[2];
      r[0] = res[0] + i * 7;
      if (snakecg_sp1_bias_forces(a, r, iw, w, 0)) { status = (int) (i + 1); break; }
    }
  }
  free(iw);
  free(w);
  return status;
}

/* ------------------------------------------------------------------------------------------
 * GENERATED FILE - DO NOT EDIT. Block driver rendered from derive/spatial/templates/block.c.j2.
 * snakecg_sp1_batch_bias_forces evaluates 16 samples at a time with snakecg_sp1_bias_forces_sincos_block (vectorized across
 * the samples): the inputs of a block are gathered sample-innermost, the cosines and sines of
 * the joint angles q[7..7] computed 16 at a time, and the outputs scattered back to
 * the batch layout. When an input or output is null or K varies per sample, the
 * per-sample driver snakecg_sp1_sample_batch_bias_forces above answers instead. Same return codes.
 * ---------------------------------------------------------------------------------------- */

/* snakecg_sp1_bias_forces_sincos over 16 samples: 421 CasADi instructions, one per line, in a loop the compiler vectorizes across the samples */
#if defined(__GNUC__) && !defined(__clang__) && __GNUC__ >= 11 && defined(__x86_64__) \
    && defined(__linux__)
/* a second copy for processors with AVX2 and FMA, chosen at load time */
__attribute__((target_clones("arch=x86-64-v3", "default")))
#endif
static void snakecg_sp1_bias_forces_sincos_block(
    const casadi_real* restrict arg0,
    const casadi_real* restrict arg1,
    const casadi_real* restrict arg2,
    const casadi_real* restrict arg3,
    const casadi_real* restrict arg4,
    casadi_real* restrict res0) {
  int s;
  for (s = 0; s < 16; ++s) {
    casadi_real w0 = arg2[0];
    casadi_real w1 = arg1[32 + s];
    casadi_real w2 = arg1[64 + s];
    casadi_real w3 = w1 * w2;
    casadi_real w4 = arg1[16 + s];
    casadi_real w5 = arg1[80 + s];
    casadi_real w6 = w4 * w5;
    w3 = w3 - w6;
    w6 = arg2[54];
    casadi_real w7 = arg1[48 + s];
    casadi_real w8 = w6 * w7;
    casadi_real w9 = arg2[53];
    casadi_real w10 = w9 * w2;
    w8 = w8 - w10;
    w10 = w8 * w2;
    w10 = w3 + w10;
    casadi_real w11 = w9 * w5;
    casadi_real w12 = arg2[55];
    casadi_real w13 = w12 * w7;
    w11 = w11 - w13;
    w13 = w11 * w5;
    w10 = w10 - w13;
    w13 = 1.0;
    casadi_real w14 = (-2.0);
    casadi_real w15 = arg0[64 + s];
    casadi_real w16 = w15 * w15;
    w16 = w14 * w16;
    casadi_real w17 = w13 + w16;
    casadi_real w18 = arg0[80 + s];
    casadi_real w19 = w18 * w18;
    w19 = w14 * w19;
    w17 = w17 + w19;
    casadi_real w20 = arg2[29];
    w17 = w17 * w20;
    casadi_real w21 = arg0[96 + s];
    casadi_real w22 = w21 + w21;
    casadi_real w23 = w22 * w18;
    casadi_real w24 = arg0[48 + s];
    casadi_real w25 = w24 + w24;
    casadi_real w26 = w25 * w15;
    w23 = w23 + w26;
    casadi_real w27 = arg2[30];
    w23 = w23 * w27;
    w17 = w17 + w23;
    w21 = w14 * w21;
    w23 = w21 * w15;
    w25 = w25 * w18;
    w23 = w23 + w25;
    casadi_real w28 = arg2[31];
    w23 = w23 * w28;
    w17 = w17 + w23;
    w10 = w10 - w17;
    w10 = w0 * w10;
    w23 = arg2[1];
    casadi_real w29 = arg2[51];
    casadi_real w30 = w29 * w7;
    casadi_real w31 = arg2[50];
    casadi_real w32 = w31 * w2;
    w30 = w30 - w32;
    w32 = w30 * w2;
    w3 = w3 + w32;
    w32 = w31 * w5;
    casadi_real w33 = arg2[52];
    casadi_real w34 = w33 * w7;
    w32 = w32 - w34;
    w34 = w32 * w5;
    w3 = w3 - w34;
    w34 = arg2[48];
    casadi_real w35 = arg2[58];
    casadi_real w36 = w34 * w35;
    casadi_real w37 = arg2[42];
    casadi_real w38 = arg3[0 + s];
    casadi_real w39 = w37 * w38;
    casadi_real w40 = arg2[45];
    casadi_real w41 = arg4[0 + s];
    casadi_real w42 = w40 * w41;
    w39 = w39 + w42;
    w42 = arg2[56];
    casadi_real w43 = w39 * w42;
    w36 = w36 + w43;
    w40 = w40 * w38;
    w37 = w37 * w41;
    w40 = w40 - w37;
    w37 = arg2[57];
    w43 = w40 * w37;
    w36 = w36 + w43;
    w43 = arg2[47];
    casadi_real w44 = arg1[96 + s];
    casadi_real w45 = w43 * w44;
    w45 = w7 + w45;
    casadi_real w46 = w36 * w45;
    casadi_real w47 = w43 * w35;
    casadi_real w48 = arg2[41];
    casadi_real w49 = w48 * w38;
    casadi_real w50 = arg2[44];
    casadi_real w51 = w50 * w41;
    w49 = w49 + w51;
    w51 = w49 * w42;
    w47 = w47 + w51;
    w50 = w50 * w38;
    w48 = w48 * w41;
    w50 = w50 - w48;
    w48 = w50 * w37;
    w47 = w47 + w48;
    w48 = w34 * w44;
    w48 = w2 + w48;
    w51 = w47 * w48;
    w46 = w46 - w51;
    w51 = w46 * w48;
    w3 = w3 + w51;
    w51 = w43 * w5;
    casadi_real w52 = arg2[49];
    casadi_real w53 = w52 * w7;
    w51 = w51 - w53;
    w51 = w44 * w51;
    w35 = w52 * w35;
    w53 = arg2[43];
    casadi_real w54 = w53 * w38;
    casadi_real w55 = arg2[46];
    casadi_real w56 = w55 * w41;
    w54 = w54 + w56;
    w42 = w54 * w42;
    w35 = w35 + w42;
    w55 = w55 * w38;
    w53 = w53 * w41;
    w55 = w55 - w53;
    w37 = w55 * w37;
    w35 = w35 + w37;
    w37 = w51 * w35;
    w3 = w3 + w37;
    w37 = w52 * w44;
    w37 = w5 + w37;
    w53 = w47 * w37;
    w41 = w35 * w45;
    w53 = w53 - w41;
    w41 = w53 * w37;
    w3 = w3 - w41;
    w41 = w34 * w7;
    w38 = w43 * w2;
    w41 = w41 - w38;
    w41 = w44 * w41;
    w38 = w41 * w36;
    w3 = w3 - w38;
    w3 = w3 - w17;
    w3 = w23 * w3;
    w17 = w10 + w3;
    res0[0 + s] = w17;
    w17 = arg1[0 + s];
    w38 = w17 * w5;
    w1 = w1 * w7;
    w38 = w38 - w1;
    w1 = w12 * w2;
    w42 = w6 * w5;
    w1 = w1 - w42;
    w42 = w1 * w5;
    w42 = w38 + w42;
    w8 = w8 * w7;
    w42 = w42 - w8;
    w8 = w21 * w18;
    w8 = w8 + w26;
    w8 = w8 * w20;
    w26 = w24 * w24;
    w14 = w14 * w26;
    w13 = w13 + w14;
    w19 = w13 + w19;
    w19 = w19 * w27;
    w8 = w8 + w19;
    w19 = w22 * w24;
    w14 = w15 + w15;
    w14 = w14 * w18;
    w19 = w19 + w14;
    w19 = w19 * w28;
    w8 = w8 + w19;
    w42 = w42 - w8;
    w42 = w0 * w42;
    w19 = w33 * w2;
    w18 = w29 * w5;
    w19 = w19 - w18;
    w18 = w19 * w5;
    w38 = w38 + w18;
    w30 = w30 * w7;
    w38 = w38 - w30;
    w30 = w35 * w48;
    w18 = w36 * w37;
    w30 = w30 - w18;
    w18 = w30 * w37;
    w38 = w38 + w18;
    w18 = w41 * w47;
    w38 = w38 + w18;
    w46 = w46 * w45;
    w38 = w38 - w46;
    w46 = w52 * w2;
    w18 = w34 * w5;
    w46 = w46 - w18;
    w44 = w44 * w46;
    w46 = w44 * w35;
    w38 = w38 - w46;
    w38 = w38 - w8;
    w38 = w23 * w38;
    w8 = w42 + w38;
    res0[16 + s] = w8;
    w4 = w4 * w7;
    w17 = w17 * w2;
    w4 = w4 - w17;
    w11 = w11 * w7;
    w11 = w4 + w11;
    w1 = w1 * w2;
    w11 = w11 - w1;
    w22 = w22 * w15;
    w22 = w22 + w25;
    w22 = w22 * w20;
    w21 = w21 * w24;
    w21 = w21 + w14;
    w21 = w21 * w27;
    w22 = w22 + w21;
    w13 = w13 + w16;
    w13 = w13 * w28;
    w22 = w22 + w13;
    w11 = w11 - w22;
    w0 = w0 * w11;
    w32 = w32 * w7;
    w4 = w4 + w32;
    w19 = w19 * w2;
    w4 = w4 - w19;
    w53 = w53 * w45;
    w4 = w4 + w53;
    w53 = w44 * w36;
    w4 = w4 + w53;
    w30 = w30 * w48;
    w4 = w4 - w30;
    w30 = w51 * w47;
    w4 = w4 - w30;
    w4 = w4 - w22;
    w23 = w23 * w4;
    w4 = w0 + w23;
    res0[32 + s] = w4;
    w4 = arg2[65];
    w22 = arg2[66];
    w22 = w22 - w4;
    w30 = w50 * w22;
    w53 = w30 * w50;
    w53 = w4 + w53;
    w19 = arg2[69];
    w49 = w19 * w49;
    w32 = arg2[70];
    w50 = w32 * w50;
    w49 = w49 + w50;
    w50 = 0.5;
    w11 = arg2[67];
    w50 = w50 * w11;
    w11 = (-0.5);
    w11 = w11 * w4;
    w50 = w50 + w11;
    w11 = w50 * w43;
    w49 = w49 + w11;
    w11 = w49 + w49;
    w11 = w11 * w43;
    w53 = w53 + w11;
    w11 = w53 * w44;
    w13 = w49 * w34;
    w39 = w19 * w39;
    w28 = w32 * w40;
    w39 = w39 + w28;
    w28 = w50 * w34;
    w39 = w39 + w28;
    w28 = w39 * w43;
    w13 = w13 + w28;
    w28 = w30 * w40;
    w13 = w13 + w28;
    w28 = w13 * w51;
    w11 = w11 + w28;
    w49 = w49 * w52;
    w19 = w19 * w54;
    w32 = w32 * w55;
    w19 = w19 + w32;
    w50 = w50 * w52;
    w19 = w19 + w50;
    w50 = w19 * w43;
    w49 = w49 + w50;
    w30 = w30 * w55;
    w49 = w49 + w30;
    w30 = w49 * w41;
    w11 = w11 + w30;
    w30 = w49 * w45;
    w50 = w39 * w52;
    w32 = w19 * w34;
    w50 = w50 + w32;
    w32 = w40 * w22;
    w54 = w32 * w55;
    w50 = w50 + w54;
    w54 = w50 * w48;
    w30 = w30 + w54;
    w22 = w55 * w22;
    w22 = w22 * w55;
    w22 = w4 + w22;
    w19 = w19 + w19;
    w19 = w19 * w52;
    w22 = w22 + w19;
    w19 = w22 * w37;
    w30 = w30 + w19;
    w19 = w30 * w48;
    w11 = w11 + w19;
    w36 = w36 + w29;
    w19 = w36 * w23;
    w11 = w11 + w19;
    w19 = w13 * w45;
    w32 = w32 * w40;
    w4 = w4 + w32;
    w39 = w39 + w39;
    w39 = w39 * w34;
    w4 = w4 + w39;
    w39 = w4 * w48;
    w19 = w19 + w39;
    w39 = w50 * w37;
    w19 = w19 + w39;
    w39 = w19 * w37;
    w11 = w11 - w39;
    w35 = w35 + w33;
    w39 = w35 * w38;
    w11 = w11 - w39;
    w39 = arg2[63];
    w32 = w39 * w7;
    w40 = arg2[64];
    w55 = w40 * w2;
    w32 = w32 + w55;
    w55 = arg2[61];
    w55 = w55 * w5;
    w32 = w32 + w55;
    w55 = w32 * w2;
    w55 = w11 + w55;
    w54 = w6 * w0;
    w55 = w55 + w54;
    w54 = arg2[62];
    w28 = w54 * w7;
    w16 = arg2[60];
    w16 = w16 * w2;
    w28 = w28 + w16;
    w40 = w40 * w5;
    w28 = w28 + w40;
    w40 = w28 * w5;
    w55 = w55 - w40;
    w40 = w12 * w42;
    w55 = w55 - w40;
    res0[48 + s] = w55;
    w55 = w13 * w44;
    w4 = w4 * w51;
    w55 = w55 + w4;
    w4 = w50 * w41;
    w55 = w55 + w4;
    w53 = w53 * w45;
    w13 = w13 * w48;
    w53 = w53 + w13;
    w13 = w49 * w37;
    w53 = w53 + w13;
    w37 = w53 * w37;
    w55 = w55 + w37;
    w35 = w35 * w3;
    w55 = w55 + w35;
    w30 = w30 * w45;
    w55 = w55 - w30;
    w47 = w47 + w31;
    w30 = w47 * w23;
    w55 = w55 - w30;
    w30 = arg2[59];
    w30 = w30 * w7;
    w54 = w54 * w2;
    w30 = w30 + w54;
    w39 = w39 * w5;
    w30 = w30 + w39;
    w5 = w30 * w5;
    w5 = w55 + w5;
    w12 = w12 * w10;
    w5 = w5 + w12;
    w32 = w32 * w7;
    w5 = w5 - w32;
    w0 = w9 * w0;
    w5 = w5 - w0;
    res0[64 + s] = w5;
    w49 = w49 * w44;
    w50 = w50 * w51;
    w49 = w49 + w50;
    w22 = w22 * w41;
    w49 = w49 + w22;
    w19 = w19 * w45;
    w49 = w49 + w19;
    w47 = w47 * w38;
    w49 = w49 + w47;
    w53 = w53 * w48;
    w49 = w49 - w53;
    w36 = w36 * w3;
    w49 = w49 - w36;
    w28 = w28 * w7;
    w28 = w49 + w28;
    w9 = w9 * w42;
    w28 = w28 + w9;
    w30 = w30 * w2;
    w28 = w28 - w30;
    w6 = w6 * w10;
    w28 = w28 - w6;
    res0[80 + s] = w28;
    w11 = w11 * w43;
    w55 = w55 * w34;
    w11 = w11 + w55;
    w49 = w49 * w52;
    w11 = w11 + w49;
    w49 = w52 * w29;
    w55 = w34 * w33;
    w49 = w49 - w55;
    w3 = w3 * w49;
    w11 = w11 + w3;
    w33 = w43 * w33;
    w52 = w52 * w31;
    w33 = w33 - w52;
    w38 = w38 * w33;
    w11 = w11 + w38;
    w34 = w34 * w31;
    w43 = w43 * w29;
    w34 = w34 - w43;
    w23 = w23 * w34;
    w11 = w11 + w23;
    res0[96 + s] = w11;
  }
}

/* The scatter of one output of a block to the batch layout: entry e of sample i, at
 * x[src[e] * 16 + i] in the block (src null: at x[e * 16 + i]), to y[i * nnz + e], m samples.
 * A full block goes 4 entries by 4 samples at a time, transposed in vector registers and
 * stored 4 entries at once (an AVX2 copy chosen at load time), the rest one by one. */
#include <string.h>
#if defined(__GNUC__) && !defined(__clang__) && __GNUC__ >= 11 && defined(__x86_64__) \
    && defined(__linux__)
typedef casadi_real snakecg_sp1_bias_forces_sincos_block_v4 __attribute__((vector_size(32)));
typedef long long snakecg_sp1_bias_forces_sincos_block_i4 __attribute__((vector_size(32)));
__attribute__((target_clones("arch=x86-64-v3", "default")))
static void snakecg_sp1_bias_forces_sincos_block_scatter(const casadi_real* x, const short* src, casadi_int nnz,
    casadi_real* y, casadi_int m) {
  casadi_int e = 0, i;
  const snakecg_sp1_bias_forces_sincos_block_i4 lo = {0, 4, 2, 6}, hi = {1, 5, 3, 7};
  const snakecg_sp1_bias_forces_sincos_block_i4 first = {0, 1, 4, 5}, second = {2, 3, 6, 7};
  if (m == 16) {
    for (; e + 4 <= nnz; e += 4) {
      const casadi_real* x0 = x + (src ? src[e] : e) * 16;
      const casadi_real* x1 = x + (src ? src[e + 1] : e + 1) * 16;
      const casadi_real* x2 = x + (src ? src[e + 2] : e + 2) * 16;
      const casadi_real* x3 = x + (src ? src[e + 3] : e + 3) * 16;
      for (i = 0; i < 16; i += 4) {
        snakecg_sp1_bias_forces_sincos_block_v4 a, b, c, d, t0, t1, t2, t3, r;
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
static void snakecg_sp1_bias_forces_sincos_block_scatter(const casadi_real* x, const short* src, casadi_int nnz,
    casadi_real* y, casadi_int m) {
  casadi_int e, i;
  for (e = 0; e < nnz; ++e) {
    const casadi_real* x0 = x + (src ? src[e] : e) * 16;
    for (i = 0; i < m; ++i) y[i * nnz + e] = x0[i];
  }
}
#endif

CASADI_SYMBOL_EXPORT int snakecg_sp1_batch_bias_forces(casadi_int n, const casadi_real** arg,
    const casadi_int* stride, casadi_real** res) {
  casadi_real *work, *cq, *sq;
  casadi_real* in0;
  casadi_real* in1;
  casadi_real* out0;
  casadi_int i, i0, m, e, src;
  int large;
  if (!(arg[0] && arg[1] && arg[2] && res[0] && stride[2] == 0)) {
    return snakecg_sp1_sample_batch_bias_forces(n, arg, stride, res);
  }
  work = (casadi_real*) malloc(sizeof(casadi_real) * 384);
  if (!work) return -1;
  cq = work;
  sq = cq + 16;
  in0 = sq + 16;
  in1 = in0 + 128;
  out0 = in1 + 112;
  for (i0 = 0; i0 < n; i0 += 16) {
    m = n - i0 < 16 ? n - i0 : 16;
    /* gather the entries the kernel and the sines and cosines read (the last sample repeated
     * into the unused slots of a partial block) */
    for (i = 0; i < 16; ++i) {
      src = i0 + (i < m ? i : m - 1);
      for (e = 3; e < 8; ++e) in0[e * 16 + i] = arg[0][src * stride[0] + e];
      for (e = 0; e < 7; ++e) in1[e * 16 + i] = arg[1][src * stride[1] + e];
    }
    for (e = 0; e < 1; ++e) {
      const casadi_real* x = in0 + (7 + e) * 16;
      large = 0;
      for (i = 0; i < 16; ++i) large |= !(fabs(x[i]) <= SNAKECG_SINCOS_MAX);
      snakecg_sincos_block(x, cq + e * 16, sq + e * 16);
      if (large) snakecg_sincos_large(x, cq + e * 16, sq + e * 16, 16);
    }
    snakecg_sp1_bias_forces_sincos_block(in0, in1, arg[2], cq, sq, out0);
    /* scatter: the block's outputs to the batch layout */
    snakecg_sp1_bias_forces_sincos_block_scatter(out0, 0, 7, res[0] + i0 * 7, m);
  }
  free(work);
  return 0;
}
