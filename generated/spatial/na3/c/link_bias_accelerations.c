/* GENERATED FILE - DO NOT EDIT. C code emitted by CasADi for link_bias_accelerations() of
 * generated/spatial/na3/ (see its model.py), plus its batched driver.
 * Regenerate with: python -m snakecg_derive.spatial --checked-in
 * spec sha256: 82d64716a2089350522ee6ce607152c94df1120870c00e7b42763fcf4d7df073
 * tools: sympy 1.14.0, casadi 3.8.2, jinja2 3.1.6
 */
/* How to prefix internal symbols */
#ifdef CASADI_CODEGEN_PREFIX
  #define CASADI_NAMESPACE_CONCAT(NS, ID) _CASADI_NAMESPACE_CONCAT(NS, ID)
  #define _CASADI_NAMESPACE_CONCAT(NS, ID) NS ## ID
  #define CASADI_PREFIX(ID) CASADI_NAMESPACE_CONCAT(CODEGEN_PREFIX, ID)
#else
  #define CASADI_PREFIX(ID) snakecg_sp3_link_bias_accelerations_ ## ID
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
CASADI_SYMBOL_EXPORT void snakecg_sp3_link_bias_accelerations_casadi_version(int* major, int* minor, int* patch) {
  *major = 3;
  *minor = 8;
  *patch = 2;
}
CASADI_SYMBOL_EXPORT int snakecg_sp3_link_bias_accelerations_casadi_int_size(void) { return (int) sizeof(casadi_int); }
CASADI_SYMBOL_EXPORT int snakecg_sp3_link_bias_accelerations_casadi_real_size(void) { return (int) sizeof(casadi_real); }

static const casadi_int casadi_s0[3] = {10, 1, 1};
static const casadi_int casadi_s1[3] = {9, 1, 1};
static const casadi_int casadi_s2[3] = {169, 1, 1};
static const casadi_int casadi_s3[3] = {6, 4, 1};

/* snakecg_sp3_link_bias_accelerations:(q[10],v[9],K[169])->(bias[6x4]) */
static int casadi_f0(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem) {
  casadi_real a00, a01, a02, a03, a04, a05, a06, a07, a08, a09, a10, a11;
  casadi_real a12, a13, a14, a15, a16, a17, a18, a19, a20, a21, a22, a23;
  casadi_real a24, a25, a26, a27, a28, a29, a30, a31, a32, a33, a34, a35;
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
  if (res[0]!=0) res[0][0]=a23;
  a10=(a10+a11);
  a10=(a10+a13);
  a20=(a10*a20);
  a00=(a00*a02);
  a00=(a00+a07);
  a17=(a00*a17);
  a20=(a20+a17);
  a01=(a01*a06);
  a01=(a01+a05);
  a22=(a01*a22);
  a20=(a20+a22);
  a22=(a24*a20);
  a08=(a10*a08);
  a15=(a00*a15);
  a08=(a08+a15);
  a18=(a01*a18);
  a08=(a08+a18);
  a21=(a08*a21);
  a22=(a22-a21);
  if (res[0]!=0) res[0][1]=a22;
  a25=(a08*a25);
  a20=(a09*a20);
  a25=(a25-a20);
  if (res[0]!=0) res[0][2]=a25;
  a20=0.;
  if (res[0]!=0) res[0][3]=a20;
  if (res[0]!=0) res[0][4]=a20;
  if (res[0]!=0) res[0][5]=a20;
  a20=arg[2]? arg[2][124] : 0;
  a21=(a03*a20);
  a18=arg[2]? arg[2][125] : 0;
  a15=(a14*a18);
  a21=(a21+a15);
  a15=arg[2]? arg[2][126] : 0;
  a05=(a16*a15);
  a21=(a21+a05);
  a05=(a21*a08);
  a06=(a10*a20);
  a17=(a00*a18);
  a06=(a06+a17);
  a17=(a01*a15);
  a06=(a06+a17);
  a17=(a06*a09);
  a05=(a05-a17);
  a17=(a09*a05);
  a23=(a23+a17);
  a06=(a06*a24);
  a20=(a19*a20);
  a18=(a04*a18);
  a20=(a20+a18);
  a15=(a12*a15);
  a20=(a20+a15);
  a15=(a20*a08);
  a06=(a06-a15);
  a15=(a24*a06);
  a23=(a23-a15);
  if (res[0]!=0) res[0][6]=a23;
  a20=(a20*a09);
  a21=(a21*a24);
  a20=(a20-a21);
  a21=(a24*a20);
  a22=(a22+a21);
  a05=(a08*a05);
  a22=(a22-a05);
  if (res[0]!=0) res[0][7]=a22;
  a06=(a08*a06);
  a25=(a25+a06);
  a20=(a09*a20);
  a25=(a25-a20);
  if (res[0]!=0) res[0][8]=a25;
  a20=arg[1]? arg[1][6] : 0;
  a06=arg[2]? arg[2][103] : 0;
  a05=(a06*a19);
  a21=arg[2]? arg[2][104] : 0;
  a15=(a21*a04);
  a05=(a05+a15);
  a15=arg[2]? arg[2][105] : 0;
  a18=(a15*a12);
  a05=(a05+a18);
  a18=(a05*a09);
  a17=(a06*a03);
  a07=(a21*a14);
  a17=(a17+a07);
  a07=(a15*a16);
  a17=(a17+a07);
  a07=(a17*a24);
  a18=(a18-a07);
  a18=(a20*a18);
  if (res[0]!=0) res[0][9]=a18;
  a06=(a06*a10);
  a21=(a21*a00);
  a06=(a06+a21);
  a15=(a15*a01);
  a06=(a06+a15);
  a15=(a06*a24);
  a21=(a05*a08);
  a15=(a15-a21);
  a15=(a20*a15);
  if (res[0]!=0) res[0][10]=a15;
  a21=(a17*a08);
  a07=(a06*a09);
  a21=(a21-a07);
  a21=(a20*a21);
  if (res[0]!=0) res[0][11]=a21;
  a07=arg[2]? arg[2][129] : 0;
  a02=(a05*a07);
  a13=arg[2]? arg[2][97] : 0;
  a11=(a13*a19);
  a26=arg[2]? arg[2][98] : 0;
  a27=(a26*a04);
  a11=(a11+a27);
  a27=arg[2]? arg[2][99] : 0;
  a28=(a27*a12);
  a11=(a11+a28);
  a28=arg[0]? arg[0][7] : 0;
  a29=cos(a28);
  a30=(a11*a29);
  a31=arg[2]? arg[2][100] : 0;
  a19=(a31*a19);
  a32=arg[2]? arg[2][101] : 0;
  a04=(a32*a04);
  a19=(a19+a04);
  a04=arg[2]? arg[2][102] : 0;
  a12=(a04*a12);
  a19=(a19+a12);
  a28=sin(a28);
  a12=(a19*a28);
  a30=(a30+a12);
  a12=arg[2]? arg[2][127] : 0;
  a33=(a30*a12);
  a02=(a02+a33);
  a19=(a19*a29);
  a11=(a11*a28);
  a19=(a19-a11);
  a11=arg[2]? arg[2][128] : 0;
  a33=(a19*a11);
  a02=(a02+a33);
  a33=(a15*a02);
  a23=(a23+a33);
  a33=(a17*a20);
  a09=(a09+a33);
  a33=(a17*a07);
  a34=(a13*a03);
  a35=(a26*a14);
  a34=(a34+a35);
  a35=(a27*a16);
  a34=(a34+a35);
  a35=(a34*a29);
  a03=(a31*a03);
  a14=(a32*a14);
  a03=(a03+a14);
  a16=(a04*a16);
  a03=(a03+a16);
  a16=(a03*a28);
  a35=(a35+a16);
  a16=(a35*a12);
  a33=(a33+a16);
  a03=(a03*a29);
  a34=(a34*a28);
  a03=(a03-a34);
  a34=(a03*a11);
  a33=(a33+a34);
  a34=(a06*a20);
  a08=(a08+a34);
  a34=(a33*a08);
  a07=(a06*a07);
  a13=(a13*a10);
  a26=(a26*a00);
  a13=(a13+a26);
  a27=(a27*a01);
  a13=(a13+a27);
  a27=(a13*a29);
  a31=(a31*a10);
  a32=(a32*a00);
  a31=(a31+a32);
  a04=(a04*a01);
  a31=(a31+a04);
  a04=(a31*a28);
  a27=(a27+a04);
  a12=(a27*a12);
  a07=(a07+a12);
  a31=(a31*a29);
  a13=(a13*a28);
  a31=(a31-a13);
  a11=(a31*a11);
  a07=(a07+a11);
  a11=(a07*a09);
  a34=(a34-a11);
  a11=(a09*a34);
  a23=(a23+a11);
  a11=(a21*a33);
  a23=(a23-a11);
  a20=(a05*a20);
  a24=(a24+a20);
  a20=(a07*a24);
  a11=(a02*a08);
  a20=(a20-a11);
  a11=(a24*a20);
  a23=(a23-a11);
  if (res[0]!=0) res[0][12]=a23;
  a11=(a21*a07);
  a22=(a22+a11);
  a11=(a02*a09);
  a13=(a33*a24);
  a11=(a11-a13);
  a13=(a24*a11);
  a22=(a22+a13);
  a02=(a18*a02);
  a22=(a22-a02);
  a34=(a08*a34);
  a22=(a22-a34);
  if (res[0]!=0) res[0][13]=a22;
  a33=(a18*a33);
  a25=(a25+a33);
  a20=(a08*a20);
  a25=(a25+a20);
  a07=(a15*a07);
  a25=(a25-a07);
  a11=(a09*a11);
  a25=(a25-a11);
  if (res[0]!=0) res[0][14]=a25;
  a11=arg[1]? arg[1][7] : 0;
  a07=arg[2]? arg[2][114] : 0;
  a20=(a05*a07);
  a33=arg[2]? arg[2][112] : 0;
  a34=(a33*a30);
  a20=(a20+a34);
  a34=arg[2]? arg[2][113] : 0;
  a02=(a34*a19);
  a20=(a20+a02);
  a02=(a20*a09);
  a13=(a17*a07);
  a28=(a33*a35);
  a13=(a13+a28);
  a28=(a34*a03);
  a13=(a13+a28);
  a28=(a13*a24);
  a02=(a02-a28);
  a02=(a11*a02);
  a18=(a18+a02);
  if (res[0]!=0) res[0][15]=a18;
  a07=(a06*a07);
  a33=(a33*a27);
  a07=(a07+a33);
  a34=(a34*a31);
  a07=(a07+a34);
  a34=(a07*a24);
  a33=(a20*a08);
  a34=(a34-a33);
  a34=(a11*a34);
  a15=(a15+a34);
  if (res[0]!=0) res[0][16]=a15;
  a34=(a13*a08);
  a33=(a07*a09);
  a34=(a34-a33);
  a34=(a11*a34);
  a21=(a21+a34);
  if (res[0]!=0) res[0][17]=a21;
  a34=arg[2]? arg[2][132] : 0;
  a33=(a20*a34);
  a02=arg[2]? arg[2][108] : 0;
  a28=(a05*a02);
  a29=arg[2]? arg[2][106] : 0;
  a12=(a29*a30);
  a28=(a28+a12);
  a12=arg[2]? arg[2][107] : 0;
  a04=(a12*a19);
  a28=(a28+a04);
  a04=arg[0]? arg[0][8] : 0;
  a01=cos(a04);
  a32=(a28*a01);
  a00=arg[2]? arg[2][111] : 0;
  a05=(a05*a00);
  a10=arg[2]? arg[2][109] : 0;
  a30=(a10*a30);
  a05=(a05+a30);
  a30=arg[2]? arg[2][110] : 0;
  a19=(a30*a19);
  a05=(a05+a19);
  a04=sin(a04);
  a19=(a05*a04);
  a32=(a32+a19);
  a19=arg[2]? arg[2][130] : 0;
  a26=(a32*a19);
  a33=(a33+a26);
  a05=(a05*a01);
  a28=(a28*a04);
  a05=(a05-a28);
  a28=arg[2]? arg[2][131] : 0;
  a26=(a05*a28);
  a33=(a33+a26);
  a26=(a15*a33);
  a23=(a23+a26);
  a26=(a13*a11);
  a09=(a09+a26);
  a26=(a13*a34);
  a16=(a17*a02);
  a14=(a29*a35);
  a16=(a16+a14);
  a14=(a12*a03);
  a16=(a16+a14);
  a14=(a16*a01);
  a17=(a17*a00);
  a35=(a10*a35);
  a17=(a17+a35);
  a03=(a30*a03);
  a17=(a17+a03);
  a03=(a17*a04);
  a14=(a14+a03);
  a03=(a14*a19);
  a26=(a26+a03);
  a17=(a17*a01);
  a16=(a16*a04);
  a17=(a17-a16);
  a16=(a17*a28);
  a26=(a26+a16);
  a16=(a07*a11);
  a08=(a08+a16);
  a16=(a26*a08);
  a34=(a07*a34);
  a02=(a06*a02);
  a29=(a29*a27);
  a02=(a02+a29);
  a12=(a12*a31);
  a02=(a02+a12);
  a12=(a02*a01);
  a06=(a06*a00);
  a10=(a10*a27);
  a06=(a06+a10);
  a30=(a30*a31);
  a06=(a06+a30);
  a30=(a06*a04);
  a12=(a12+a30);
  a19=(a12*a19);
  a34=(a34+a19);
  a06=(a06*a01);
  a02=(a02*a04);
  a06=(a06-a02);
  a28=(a06*a28);
  a34=(a34+a28);
  a28=(a34*a09);
  a16=(a16-a28);
  a28=(a09*a16);
  a23=(a23+a28);
  a28=(a21*a26);
  a23=(a23-a28);
  a11=(a20*a11);
  a24=(a24+a11);
  a11=(a34*a24);
  a28=(a33*a08);
  a11=(a11-a28);
  a28=(a24*a11);
  a23=(a23-a28);
  if (res[0]!=0) res[0][18]=a23;
  a23=(a21*a34);
  a22=(a22+a23);
  a23=(a33*a09);
  a28=(a26*a24);
  a23=(a23-a28);
  a28=(a24*a23);
  a22=(a22+a28);
  a33=(a18*a33);
  a22=(a22-a33);
  a16=(a08*a16);
  a22=(a22-a16);
  if (res[0]!=0) res[0][19]=a22;
  a26=(a18*a26);
  a25=(a25+a26);
  a11=(a08*a11);
  a25=(a25+a11);
  a34=(a15*a34);
  a25=(a25-a34);
  a23=(a09*a23);
  a25=(a25-a23);
  if (res[0]!=0) res[0][20]=a25;
  a25=arg[1]? arg[1][8] : 0;
  a23=arg[2]? arg[2][123] : 0;
  a20=(a20*a23);
  a34=arg[2]? arg[2][121] : 0;
  a32=(a34*a32);
  a20=(a20+a32);
  a32=arg[2]? arg[2][122] : 0;
  a05=(a32*a05);
  a20=(a20+a05);
  a05=(a20*a09);
  a13=(a13*a23);
  a14=(a34*a14);
  a13=(a13+a14);
  a17=(a32*a17);
  a13=(a13+a17);
  a17=(a13*a24);
  a05=(a05-a17);
  a05=(a25*a05);
  a18=(a18+a05);
  if (res[0]!=0) res[0][21]=a18;
  a07=(a07*a23);
  a34=(a34*a12);
  a07=(a07+a34);
  a32=(a32*a06);
  a07=(a07+a32);
  a24=(a07*a24);
  a20=(a20*a08);
  a24=(a24-a20);
  a24=(a25*a24);
  a15=(a15+a24);
  if (res[0]!=0) res[0][22]=a15;
  a13=(a13*a08);
  a07=(a07*a09);
  a13=(a13-a07);
  a25=(a25*a13);
  a21=(a21+a25);
  if (res[0]!=0) res[0][23]=a21;
  return 0;
}

CASADI_SYMBOL_EXPORT int snakecg_sp3_link_bias_accelerations(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem){
  return casadi_f0(arg, res, iw, w, mem);
}

CASADI_SYMBOL_EXPORT int snakecg_sp3_link_bias_accelerations_checkout(void) {
  return 0;
}

CASADI_SYMBOL_EXPORT void snakecg_sp3_link_bias_accelerations_release(int mem) {
}

CASADI_SYMBOL_EXPORT void snakecg_sp3_link_bias_accelerations_incref(void) {
}

CASADI_SYMBOL_EXPORT void snakecg_sp3_link_bias_accelerations_decref(void) {
}

CASADI_SYMBOL_EXPORT casadi_int snakecg_sp3_link_bias_accelerations_n_in(void) { return 3;}

CASADI_SYMBOL_EXPORT casadi_int snakecg_sp3_link_bias_accelerations_n_out(void) { return 1;}

CASADI_SYMBOL_EXPORT casadi_real snakecg_sp3_link_bias_accelerations_default_in(casadi_int i) {
  switch (i) {
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const char* snakecg_sp3_link_bias_accelerations_name_in(casadi_int i) {
  switch (i) {
    case 0: return "q";
    case 1: return "v";
    case 2: return "K";
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const char* snakecg_sp3_link_bias_accelerations_name_out(casadi_int i) {
  switch (i) {
    case 0: return "bias";
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const casadi_int* snakecg_sp3_link_bias_accelerations_sparsity_in(casadi_int i) {
  switch (i) {
    case 0: return casadi_s0;
    case 1: return casadi_s1;
    case 2: return casadi_s2;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const casadi_int* snakecg_sp3_link_bias_accelerations_sparsity_out(casadi_int i) {
  switch (i) {
    case 0: return casadi_s3;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT int snakecg_sp3_link_bias_accelerations_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w) {
  if (sz_arg) *sz_arg = 3;
  if (sz_res) *sz_res = 1;
  if (sz_iw) *sz_iw = 0;
  if (sz_w) *sz_w = 0;
  return 0;
}

CASADI_SYMBOL_EXPORT int snakecg_sp3_link_bias_accelerations_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w) {
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

/* snakecg_sp3_link_bias_accelerations_sincos: 470 CasADi instructions, printed one per line */
static void snakecg_sp3_link_bias_accelerations_sincos(
    const casadi_real* restrict arg0,
    const casadi_real* restrict arg1,
    const casadi_real* restrict arg2,
    const casadi_real* restrict arg3,
    const casadi_real* restrict arg4,
    casadi_real* restrict res0) {
  casadi_real w0, w1, w2, w3, w4, w5, w6, w7, w8, w9;
  casadi_real w10, w11, w12, w13, w14, w15, w16, w17, w18, w19;
  casadi_real w20, w21, w22, w23, w24, w25, w26, w27, w28, w29;
  casadi_real w30, w31, w32, w33, w34, w35;
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
  res0[0] = w23;
  w10 = w10 + w11;
  w10 = w10 + w13;
  w20 = w10 * w20;
  w0 = w0 * w2;
  w0 = w0 + w7;
  w17 = w0 * w17;
  w20 = w20 + w17;
  w1 = w1 * w6;
  w1 = w1 + w5;
  w22 = w1 * w22;
  w20 = w20 + w22;
  w22 = w24 * w20;
  w8 = w10 * w8;
  w15 = w0 * w15;
  w8 = w8 + w15;
  w18 = w1 * w18;
  w8 = w8 + w18;
  w21 = w8 * w21;
  w22 = w22 - w21;
  res0[1] = w22;
  w25 = w8 * w25;
  w20 = w9 * w20;
  w25 = w25 - w20;
  res0[2] = w25;
  w20 = 0.0;
  res0[3] = w20;
  res0[4] = w20;
  res0[5] = w20;
  w20 = arg2[124];
  w21 = w3 * w20;
  w18 = arg2[125];
  w15 = w14 * w18;
  w21 = w21 + w15;
  w15 = arg2[126];
  w5 = w16 * w15;
  w21 = w21 + w5;
  w5 = w21 * w8;
  w6 = w10 * w20;
  w17 = w0 * w18;
  w6 = w6 + w17;
  w17 = w1 * w15;
  w6 = w6 + w17;
  w17 = w6 * w9;
  w5 = w5 - w17;
  w17 = w9 * w5;
  w23 = w23 + w17;
  w6 = w6 * w24;
  w20 = w19 * w20;
  w18 = w4 * w18;
  w20 = w20 + w18;
  w15 = w12 * w15;
  w20 = w20 + w15;
  w15 = w20 * w8;
  w6 = w6 - w15;
  w15 = w24 * w6;
  w23 = w23 - w15;
  res0[6] = w23;
  w20 = w20 * w9;
  w21 = w21 * w24;
  w20 = w20 - w21;
  w21 = w24 * w20;
  w22 = w22 + w21;
  w5 = w8 * w5;
  w22 = w22 - w5;
  res0[7] = w22;
  w6 = w8 * w6;
  w25 = w25 + w6;
  w20 = w9 * w20;
  w25 = w25 - w20;
  res0[8] = w25;
  w20 = arg1[6];
  w6 = arg2[103];
  w5 = w6 * w19;
  w21 = arg2[104];
  w15 = w21 * w4;
  w5 = w5 + w15;
  w15 = arg2[105];
  w18 = w15 * w12;
  w5 = w5 + w18;
  w18 = w5 * w9;
  w17 = w6 * w3;
  w7 = w21 * w14;
  w17 = w17 + w7;
  w7 = w15 * w16;
  w17 = w17 + w7;
  w7 = w17 * w24;
  w18 = w18 - w7;
  w18 = w20 * w18;
  res0[9] = w18;
  w6 = w6 * w10;
  w21 = w21 * w0;
  w6 = w6 + w21;
  w15 = w15 * w1;
  w6 = w6 + w15;
  w15 = w6 * w24;
  w21 = w5 * w8;
  w15 = w15 - w21;
  w15 = w20 * w15;
  res0[10] = w15;
  w21 = w17 * w8;
  w7 = w6 * w9;
  w21 = w21 - w7;
  w21 = w20 * w21;
  res0[11] = w21;
  w7 = arg2[129];
  w2 = w5 * w7;
  w13 = arg2[97];
  w11 = w13 * w19;
  w26 = arg2[98];
  w27 = w26 * w4;
  w11 = w11 + w27;
  w27 = arg2[99];
  w28 = w27 * w12;
  w11 = w11 + w28;
  w28 = arg3[0];
  w29 = w11 * w28;
  w30 = arg2[100];
  w19 = w30 * w19;
  w31 = arg2[101];
  w4 = w31 * w4;
  w19 = w19 + w4;
  w4 = arg2[102];
  w12 = w4 * w12;
  w19 = w19 + w12;
  w12 = arg4[0];
  w32 = w19 * w12;
  w29 = w29 + w32;
  w32 = arg2[127];
  w33 = w29 * w32;
  w2 = w2 + w33;
  w19 = w19 * w28;
  w11 = w11 * w12;
  w19 = w19 - w11;
  w11 = arg2[128];
  w33 = w19 * w11;
  w2 = w2 + w33;
  w33 = w15 * w2;
  w23 = w23 + w33;
  w33 = w17 * w20;
  w9 = w9 + w33;
  w33 = w17 * w7;
  w34 = w13 * w3;
  w35 = w26 * w14;
  w34 = w34 + w35;
  w35 = w27 * w16;
  w34 = w34 + w35;
  w35 = w34 * w28;
  w3 = w30 * w3;
  w14 = w31 * w14;
  w3 = w3 + w14;
  w16 = w4 * w16;
  w3 = w3 + w16;
  w16 = w3 * w12;
  w35 = w35 + w16;
  w16 = w35 * w32;
  w33 = w33 + w16;
  w3 = w3 * w28;
  w34 = w34 * w12;
  w3 = w3 - w34;
  w34 = w3 * w11;
  w33 = w33 + w34;
  w34 = w6 * w20;
  w8 = w8 + w34;
  w34 = w33 * w8;
  w7 = w6 * w7;
  w13 = w13 * w10;
  w26 = w26 * w0;
  w13 = w13 + w26;
  w27 = w27 * w1;
  w13 = w13 + w27;
  w27 = w13 * w28;
  w30 = w30 * w10;
  w31 = w31 * w0;
  w30 = w30 + w31;
  w4 = w4 * w1;
  w30 = w30 + w4;
  w4 = w30 * w12;
  w27 = w27 + w4;
  w32 = w27 * w32;
  w7 = w7 + w32;
  w30 = w30 * w28;
  w13 = w13 * w12;
  w30 = w30 - w13;
  w11 = w30 * w11;
  w7 = w7 + w11;
  w11 = w7 * w9;
  w34 = w34 - w11;
  w11 = w9 * w34;
  w23 = w23 + w11;
  w11 = w21 * w33;
  w23 = w23 - w11;
  w20 = w5 * w20;
  w24 = w24 + w20;
  w20 = w7 * w24;
  w11 = w2 * w8;
  w20 = w20 - w11;
  w11 = w24 * w20;
  w23 = w23 - w11;
  res0[12] = w23;
  w11 = w21 * w7;
  w22 = w22 + w11;
  w11 = w2 * w9;
  w13 = w33 * w24;
  w11 = w11 - w13;
  w13 = w24 * w11;
  w22 = w22 + w13;
  w2 = w18 * w2;
  w22 = w22 - w2;
  w34 = w8 * w34;
  w22 = w22 - w34;
  res0[13] = w22;
  w33 = w18 * w33;
  w25 = w25 + w33;
  w20 = w8 * w20;
  w25 = w25 + w20;
  w7 = w15 * w7;
  w25 = w25 - w7;
  w11 = w9 * w11;
  w25 = w25 - w11;
  res0[14] = w25;
  w11 = arg1[7];
  w7 = arg2[114];
  w20 = w5 * w7;
  w33 = arg2[112];
  w34 = w33 * w29;
  w20 = w20 + w34;
  w34 = arg2[113];
  w2 = w34 * w19;
  w20 = w20 + w2;
  w2 = w20 * w9;
  w13 = w17 * w7;
  w12 = w33 * w35;
  w13 = w13 + w12;
  w12 = w34 * w3;
  w13 = w13 + w12;
  w12 = w13 * w24;
  w2 = w2 - w12;
  w2 = w11 * w2;
  w18 = w18 + w2;
  res0[15] = w18;
  w7 = w6 * w7;
  w33 = w33 * w27;
  w7 = w7 + w33;
  w34 = w34 * w30;
  w7 = w7 + w34;
  w34 = w7 * w24;
  w33 = w20 * w8;
  w34 = w34 - w33;
  w34 = w11 * w34;
  w15 = w15 + w34;
  res0[16] = w15;
  w34 = w13 * w8;
  w33 = w7 * w9;
  w34 = w34 - w33;
  w34 = w11 * w34;
  w21 = w21 + w34;
  res0[17] = w21;
  w34 = arg2[132];
  w33 = w20 * w34;
  w2 = arg2[108];
  w12 = w5 * w2;
  w28 = arg2[106];
  w32 = w28 * w29;
  w12 = w12 + w32;
  w32 = arg2[107];
  w4 = w32 * w19;
  w12 = w12 + w4;
  w4 = arg3[1];
  w1 = w12 * w4;
  w31 = arg2[111];
  w5 = w5 * w31;
  w0 = arg2[109];
  w29 = w0 * w29;
  w5 = w5 + w29;
  w29 = arg2[110];
  w19 = w29 * w19;
  w5 = w5 + w19;
  w19 = arg4[1];
  w10 = w5 * w19;
  w1 = w1 + w10;
  w10 = arg2[130];
  w26 = w1 * w10;
  w33 = w33 + w26;
  w5 = w5 * w4;
  w12 = w12 * w19;
  w5 = w5 - w12;
  w12 = arg2[131];
  w26 = w5 * w12;
  w33 = w33 + w26;
  w26 = w15 * w33;
  w23 = w23 + w26;
  w26 = w13 * w11;
  w9 = w9 + w26;
  w26 = w13 * w34;
  w16 = w17 * w2;
  w14 = w28 * w35;
  w16 = w16 + w14;
  w14 = w32 * w3;
  w16 = w16 + w14;
  w14 = w16 * w4;
  w17 = w17 * w31;
  w35 = w0 * w35;
  w17 = w17 + w35;
  w3 = w29 * w3;
  w17 = w17 + w3;
  w3 = w17 * w19;
  w14 = w14 + w3;
  w3 = w14 * w10;
  w26 = w26 + w3;
  w17 = w17 * w4;
  w16 = w16 * w19;
  w17 = w17 - w16;
  w16 = w17 * w12;
  w26 = w26 + w16;
  w16 = w7 * w11;
  w8 = w8 + w16;
  w16 = w26 * w8;
  w34 = w7 * w34;
  w2 = w6 * w2;
  w28 = w28 * w27;
  w2 = w2 + w28;
  w32 = w32 * w30;
  w2 = w2 + w32;
  w32 = w2 * w4;
  w6 = w6 * w31;
  w0 = w0 * w27;
  w6 = w6 + w0;
  w29 = w29 * w30;
  w6 = w6 + w29;
  w29 = w6 * w19;
  w32 = w32 + w29;
  w10 = w32 * w10;
  w34 = w34 + w10;
  w6 = w6 * w4;
  w2 = w2 * w19;
  w6 = w6 - w2;
  w12 = w6 * w12;
  w34 = w34 + w12;
  w12 = w34 * w9;
  w16 = w16 - w12;
  w12 = w9 * w16;
  w23 = w23 + w12;
  w12 = w21 * w26;
  w23 = w23 - w12;
  w11 = w20 * w11;
  w24 = w24 + w11;
  w11 = w34 * w24;
  w12 = w33 * w8;
  w11 = w11 - w12;
  w12 = w24 * w11;
  w23 = w23 - w12;
  res0[18] = w23;
  w23 = w21 * w34;
  w22 = w22 + w23;
  w23 = w33 * w9;
  w12 = w26 * w24;
  w23 = w23 - w12;
  w12 = w24 * w23;
  w22 = w22 + w12;
  w33 = w18 * w33;
  w22 = w22 - w33;
  w16 = w8 * w16;
  w22 = w22 - w16;
  res0[19] = w22;
  w26 = w18 * w26;
  w25 = w25 + w26;
  w11 = w8 * w11;
  w25 = w25 + w11;
  w34 = w15 * w34;
  w25 = w25 - w34;
  w23 = w9 * w23;
  w25 = w25 - w23;
  res0[20] = w25;
  w25 = arg1[8];
  w23 = arg2[123];
  w20 = w20 * w23;
  w34 = arg2[121];
  w1 = w34 * w1;
  w20 = w20 + w1;
  w1 = arg2[122];
  w5 = w1 * w5;
  w20 = w20 + w5;
  w5 = w20 * w9;
  w13 = w13 * w23;
  w14 = w34 * w14;
  w13 = w13 + w14;
  w17 = w1 * w17;
  w13 = w13 + w17;
  w17 = w13 * w24;
  w5 = w5 - w17;
  w5 = w25 * w5;
  w18 = w18 + w5;
  res0[21] = w18;
  w7 = w7 * w23;
  w34 = w34 * w32;
  w7 = w7 + w34;
  w1 = w1 * w6;
  w7 = w7 + w1;
  w24 = w7 * w24;
  w20 = w20 * w8;
  w24 = w24 - w20;
  w24 = w25 * w24;
  w15 = w15 + w24;
  res0[22] = w15;
  w13 = w13 * w8;
  w7 = w7 * w9;
  w13 = w13 - w7;
  w25 = w25 * w13;
  w21 = w21 + w25;
  res0[23] = w21;
}


CASADI_SYMBOL_EXPORT int snakecg_sp3_batch_link_bias_accelerations(casadi_int n, const casadi_real** arg,
    const casadi_int* stride, casadi_real** res) {
  const casadi_real* a[3];
  casadi_real* r[1];
  casadi_int* iw = (casadi_int*) malloc(sizeof(casadi_int) * 1);
  casadi_real* w = (casadi_real*) malloc(sizeof(casadi_real) * 37);
  casadi_int i, k;
  int status = 0;
  if (!iw || !w) { free(iw); free(w); return -1; }
  for (k = 0; k < 3; ++k) a[k] = 0;
  for (k = 0; k < 1; ++k) r[k] = 0;
  if (arg[0] && arg[1] && arg[2] && res[0]) {
    /* cos and sin of q[7..9] of 16 samples at a time, then snakecg_sp3_link_bias_accelerations_sincos
     * per sample (a batch of one too, so that a batch equals its samples one by one) */
    const casadi_int na = 3, per = 16;
    casadi_real ang[48], ca[48], sa[48];
    casadi_int i0, m;
    int large;
    for (k = 0; k < 48; ++k) ang[k] = 0;
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
        snakecg_sp3_link_bias_accelerations_sincos(arg[0] + (i0 + i) * stride[0], arg[1] + (i0 + i) * stride[1], arg[2] + (i0 + i) * stride[2], ca + i * na, sa + i * na, res[0] + (i0 + i) * 24);
      }
    }
  } else {
    /* a null input or output (CasADi's convention: zeros in, nothing out): per sample */
    for (i = 0; i < n; ++i) {
      a[0] = arg[0] + i * stride[0];
      a[1] = arg[1] + i * stride[1];
      a[2] = arg[2] + i * stride[2];
      r[0] = res[0] + i * 24;
      if (snakecg_sp3_link_bias_accelerations(a, r, iw, w, 0)) { status = (int) (i + 1); break; }
    }
  }
  free(iw);
  free(w);
  return status;
}
