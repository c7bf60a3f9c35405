/* GENERATED FILE - DO NOT EDIT. C code emitted by CasADi for bias_forces() of
 * generated/na6/ (see its model.py), plus its batched driver.
 * Regenerate with: python -m snakecg_derive --checked-in
 * spec sha256: 522fe595aab63e52670af90656908e991192d778246ab53ba223a16866b70733
 * tools: sympy 1.14.0, casadi 3.8.2, jinja2 3.1.6
 */
/* How to prefix internal symbols */
#ifdef CASADI_CODEGEN_PREFIX
  #define CASADI_NAMESPACE_CONCAT(NS, ID) _CASADI_NAMESPACE_CONCAT(NS, ID)
  #define _CASADI_NAMESPACE_CONCAT(NS, ID) NS ## ID
  #define CASADI_PREFIX(ID) CASADI_NAMESPACE_CONCAT(CODEGEN_PREFIX, ID)
#else
  #define CASADI_PREFIX(ID) snakecg_na6_bias_forces_ ## ID
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
CASADI_SYMBOL_EXPORT void snakecg_na6_bias_forces_casadi_version(int* major, int* minor, int* patch) {
  *major = 3;
  *minor = 8;
  *patch = 2;
}
CASADI_SYMBOL_EXPORT int snakecg_na6_bias_forces_casadi_int_size(void) { return (int) sizeof(casadi_int); }
CASADI_SYMBOL_EXPORT int snakecg_na6_bias_forces_casadi_real_size(void) { return (int) sizeof(casadi_real); }

static const casadi_int casadi_s0[3] = {9, 1, 1};
static const casadi_int casadi_s1[3] = {71, 1, 1};

/* snakecg_na6_bias_forces:(q[9],v[9],K[71])->(h[9]) */
static int casadi_f0(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem) {
  casadi_real a00, a01, a02, a03, a04, a05, a06, a07, a08, a09, a10, a11;
  casadi_real a12, a13, a14, a15, a16, a17, a18, a19, a20, a21, a22, a23;
  casadi_real a24, a25, a26, a27, a28, a29, a30, a31, a32, a33, a34, a35;
  casadi_real a36, a37, a38, a39, a40, a41, a42, a43, a44, a45, a46, a47;
  casadi_real a48, a49, a50, a51, a52, a53, a54, a55, a56, a57;
  a00=arg[1]? arg[1][3] : 0;
  a01=arg[1]? arg[1][2] : 0;
  a00=(a00+a01);
  a02=casadi_sq(a00);
  a03=arg[0]? arg[0][2] : 0;
  a04=cos(a03);
  a05=arg[0]? arg[0][3] : 0;
  a06=cos(a05);
  a07=(a04*a06);
  a03=sin(a03);
  a05=sin(a05);
  a08=(a03*a05);
  a07=(a07-a08);
  a08=arg[2]? arg[2][22] : 0;
  a09=(a07*a08);
  a10=(a02*a09);
  a01=casadi_sq(a01);
  a11=arg[2]? arg[2][7] : 0;
  a12=arg[2]? arg[2][21] : 0;
  a11=(a11-a12);
  a12=(a04*a11);
  a13=(a01*a12);
  a10=(a10+a13);
  a13=arg[2]? arg[2][1] : 0;
  a14=(a10*a13);
  a15=arg[2]? arg[2][8] : 0;
  a15=(a15-a08);
  a16=(a07*a15);
  a17=(a02*a16);
  a10=(a10+a17);
  a17=arg[0]? arg[0][4] : 0;
  a18=cos(a17);
  a19=(a07*a18);
  a04=(a04*a05);
  a06=(a06*a03);
  a04=(a04+a06);
  a17=sin(a17);
  a06=(a04*a17);
  a19=(a19-a06);
  a06=arg[2]? arg[2][23] : 0;
  a05=(a19*a06);
  a20=arg[1]? arg[1][4] : 0;
  a00=(a00+a20);
  a20=casadi_sq(a00);
  a21=(a05*a20);
  a10=(a10+a21);
  a21=arg[2]? arg[2][2] : 0;
  a22=(a10*a21);
  a23=arg[2]? arg[2][9] : 0;
  a23=(a23-a06);
  a24=(a19*a23);
  a25=(a24*a20);
  a10=(a10+a25);
  a25=arg[1]? arg[1][5] : 0;
  a00=(a00+a25);
  a25=casadi_sq(a00);
  a26=arg[0]? arg[0][5] : 0;
  a27=cos(a26);
  a28=(a19*a27);
  a07=(a07*a17);
  a18=(a18*a04);
  a07=(a07+a18);
  a26=sin(a26);
  a18=(a07*a26);
  a28=(a28-a18);
  a18=arg[2]? arg[2][24] : 0;
  a17=(a28*a18);
  a29=(a25*a17);
  a10=(a10+a29);
  a29=arg[2]? arg[2][3] : 0;
  a30=(a10*a29);
  a31=arg[2]? arg[2][10] : 0;
  a31=(a31-a18);
  a32=(a28*a31);
  a33=(a25*a32);
  a10=(a10+a33);
  a33=arg[1]? arg[1][6] : 0;
  a00=(a00+a33);
  a33=casadi_sq(a00);
  a34=arg[0]? arg[0][6] : 0;
  a35=cos(a34);
  a36=(a28*a35);
  a19=(a19*a26);
  a27=(a27*a07);
  a19=(a19+a27);
  a34=sin(a34);
  a27=(a19*a34);
  a36=(a36-a27);
  a27=arg[2]? arg[2][25] : 0;
  a26=(a36*a27);
  a37=(a33*a26);
  a10=(a10+a37);
  a37=arg[2]? arg[2][4] : 0;
  a38=(a10*a37);
  a39=arg[2]? arg[2][11] : 0;
  a39=(a39-a27);
  a40=(a36*a39);
  a41=(a33*a40);
  a10=(a10+a41);
  a41=arg[1]? arg[1][7] : 0;
  a00=(a00+a41);
  a41=casadi_sq(a00);
  a42=arg[0]? arg[0][7] : 0;
  a43=cos(a42);
  a44=(a36*a43);
  a28=(a28*a34);
  a35=(a35*a19);
  a28=(a28+a35);
  a42=sin(a42);
  a35=(a28*a42);
  a44=(a44-a35);
  a35=arg[2]? arg[2][26] : 0;
  a34=(a44*a35);
  a45=(a41*a34);
  a10=(a10+a45);
  a45=arg[2]? arg[2][5] : 0;
  a46=(a10*a45);
  a47=arg[2]? arg[2][12] : 0;
  a47=(a47-a35);
  a48=(a44*a47);
  a49=(a41*a48);
  a10=(a10+a49);
  a49=arg[1]? arg[1][8] : 0;
  a00=(a00+a49);
  a00=casadi_sq(a00);
  a49=arg[0]? arg[0][8] : 0;
  a50=cos(a49);
  a51=(a44*a50);
  a36=(a36*a42);
  a43=(a43*a28);
  a36=(a36+a43);
  a49=sin(a49);
  a43=(a36*a49);
  a51=(a51-a43);
  a43=arg[2]? arg[2][27] : 0;
  a51=(a51*a43);
  a42=(a00*a51);
  a10=(a10+a42);
  a42=arg[2]? arg[2][6] : 0;
  a10=(a10*a42);
  a52=(a46+a10);
  a53=(a38+a52);
  a54=(a30+a53);
  a55=(a22+a54);
  a56=(a14+a55);
  a57=(-a56);
  if (res[0]!=0) res[0][0]=a57;
  a08=(a04*a08);
  a57=(a02*a08);
  a11=(a11*a03);
  a01=(a01*a11);
  a57=(a57+a01);
  a13=(a57*a13);
  a15=(a15*a04);
  a02=(a02*a15);
  a57=(a57+a02);
  a06=(a07*a06);
  a02=(a06*a20);
  a57=(a57+a02);
  a21=(a57*a21);
  a18=(a19*a18);
  a02=(a25*a18);
  a57=(a57+a02);
  a23=(a23*a07);
  a20=(a23*a20);
  a57=(a57+a20);
  a29=(a57*a29);
  a31=(a31*a19);
  a25=(a25*a31);
  a57=(a57+a25);
  a27=(a28*a27);
  a25=(a33*a27);
  a57=(a57+a25);
  a37=(a57*a37);
  a39=(a39*a28);
  a33=(a33*a39);
  a57=(a57+a33);
  a35=(a36*a35);
  a33=(a41*a35);
  a57=(a57+a33);
  a45=(a57*a45);
  a47=(a47*a36);
  a41=(a41*a47);
  a57=(a57+a41);
  a44=(a44*a49);
  a50=(a50*a36);
  a44=(a44+a50);
  a44=(a44*a43);
  a00=(a00*a44);
  a57=(a57+a00);
  a00=(a57*a42);
  a43=(a45+a00);
  a50=(a37+a43);
  a36=(a29+a50);
  a49=(a21+a36);
  a41=(a13+a49);
  a33=(-a41);
  if (res[0]!=0) res[0][1]=a33;
  a33=arg[0]? arg[0][1] : 0;
  a11=(a11+a33);
  a08=(a08+a11);
  a15=(a15+a08);
  a06=(a06+a15);
  a23=(a23+a06);
  a18=(a18+a23);
  a31=(a31+a18);
  a27=(a27+a31);
  a39=(a39+a27);
  a35=(a35+a39);
  a47=(a47+a35);
  a44=(a44+a47);
  a44=(a10*a44);
  a28=arg[0]? arg[0][0] : 0;
  a12=(a12+a28);
  a09=(a09+a12);
  a16=(a16+a09);
  a05=(a05+a16);
  a24=(a24+a05);
  a17=(a17+a24);
  a32=(a32+a17);
  a26=(a26+a32);
  a40=(a40+a26);
  a34=(a34+a40);
  a48=(a48+a34);
  a51=(a51+a48);
  a57=(a57*a51);
  a57=(a57*a42);
  a44=(a44-a57);
  a45=(a45*a34);
  a45=(a44-a45);
  a46=(a46*a35);
  a45=(a45+a46);
  a37=(a37*a26);
  a37=(a45-a37);
  a38=(a38*a27);
  a37=(a37+a38);
  a29=(a29*a17);
  a29=(a37-a29);
  a30=(a30*a18);
  a29=(a29+a30);
  a21=(a21*a05);
  a21=(a29-a21);
  a22=(a22*a06);
  a21=(a21+a22);
  a13=(a13*a09);
  a13=(a21-a13);
  a14=(a14*a08);
  a13=(a13+a14);
  a33=(a56*a33);
  a33=(a13-a33);
  a28=(a41*a28);
  a33=(a33+a28);
  if (res[0]!=0) res[0][2]=a33;
  a56=(a56*a11);
  a13=(a13-a56);
  a41=(a41*a12);
  a13=(a13+a41);
  if (res[0]!=0) res[0][3]=a13;
  a55=(a55*a15);
  a21=(a21-a55);
  a49=(a49*a16);
  a21=(a21+a49);
  if (res[0]!=0) res[0][4]=a21;
  a54=(a54*a23);
  a29=(a29-a54);
  a36=(a36*a24);
  a29=(a29+a36);
  if (res[0]!=0) res[0][5]=a29;
  a53=(a53*a31);
  a37=(a37-a53);
  a50=(a50*a32);
  a37=(a37+a50);
  if (res[0]!=0) res[0][6]=a37;
  a52=(a52*a39);
  a45=(a45-a52);
  a43=(a43*a40);
  a45=(a45+a43);
  if (res[0]!=0) res[0][7]=a45;
  a10=(a10*a47);
  a44=(a44-a10);
  a00=(a00*a48);
  a44=(a44+a00);
  if (res[0]!=0) res[0][8]=a44;
  return 0;
}

CASADI_SYMBOL_EXPORT int snakecg_na6_bias_forces(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem){
  return casadi_f0(arg, res, iw, w, mem);
}

CASADI_SYMBOL_EXPORT int snakecg_na6_bias_forces_checkout(void) {
  return 0;
}

CASADI_SYMBOL_EXPORT void snakecg_na6_bias_forces_release(int mem) {
}

CASADI_SYMBOL_EXPORT void snakecg_na6_bias_forces_incref(void) {
}

CASADI_SYMBOL_EXPORT void snakecg_na6_bias_forces_decref(void) {
}

CASADI_SYMBOL_EXPORT casadi_int snakecg_na6_bias_forces_n_in(void) { return 3;}

CASADI_SYMBOL_EXPORT casadi_int snakecg_na6_bias_forces_n_out(void) { return 1;}

CASADI_SYMBOL_EXPORT casadi_real snakecg_na6_bias_forces_default_in(casadi_int i) {
  switch (i) {
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const char* snakecg_na6_bias_forces_name_in(casadi_int i) {
  switch (i) {
    case 0: return "q";
    case 1: return "v";
    case 2: return "K";
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const char* snakecg_na6_bias_forces_name_out(casadi_int i) {
  switch (i) {
    case 0: return "h";
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const casadi_int* snakecg_na6_bias_forces_sparsity_in(casadi_int i) {
  switch (i) {
    case 0: return casadi_s0;
    case 1: return casadi_s0;
    case 2: return casadi_s1;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const casadi_int* snakecg_na6_bias_forces_sparsity_out(casadi_int i) {
  switch (i) {
    case 0: return casadi_s0;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT int snakecg_na6_bias_forces_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w) {
  if (sz_arg) *sz_arg = 3;
  if (sz_res) *sz_res = 1;
  if (sz_iw) *sz_iw = 0;
  if (sz_w) *sz_w = 0;
  return 0;
}

CASADI_SYMBOL_EXPORT int snakecg_na6_bias_forces_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w) {
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

CASADI_SYMBOL_EXPORT int snakecg_na6_batch_bias_forces(casadi_int n, const casadi_real** arg,
    const casadi_int* stride, casadi_real** res) {
  const casadi_real* a[3];
  casadi_real* r[1];
  casadi_int* iw = (casadi_int*) malloc(sizeof(casadi_int) * 1);
  casadi_real* w = (casadi_real*) malloc(sizeof(casadi_real) * 59);
  casadi_int i, k;
  int status = 0;
  if (!iw || !w) { free(iw); free(w); return -1; }
  for (k = 0; k < 3; ++k) a[k] = 0;
  for (k = 0; k < 1; ++k) r[k] = 0;
  for (i = 0; i < n; ++i) {
    a[0] = arg[0] + i * stride[0];
    a[1] = arg[1] + i * stride[1];
    a[2] = arg[2] + i * stride[2];
    r[0] = res[0] + i * 9;
    if (snakecg_na6_bias_forces(a, r, iw, w, 0)) { status = (int) (i + 1); break; }
  }
  free(iw);
  free(w);
  return status;
}
