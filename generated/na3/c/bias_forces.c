/* GENERATED FILE - DO NOT EDIT. C code emitted by CasADi for bias_forces() of
 * generated/na3/ (see its model.py), plus its batched driver.
 * Regenerate with: python -m snakecg_derive --checked-in
 * spec sha256: 69686744596b549bcd3f0673408c86c5f2701602d7e0095fc6e56d39f6e4f511
 * tools: sympy 1.14.0, casadi 3.8.2, jinja2 3.1.6
 */
/* How to prefix internal symbols */
#ifdef CASADI_CODEGEN_PREFIX
  #define CASADI_NAMESPACE_CONCAT(NS, ID) _CASADI_NAMESPACE_CONCAT(NS, ID)
  #define _CASADI_NAMESPACE_CONCAT(NS, ID) NS ## ID
  #define CASADI_PREFIX(ID) CASADI_NAMESPACE_CONCAT(CODEGEN_PREFIX, ID)
#else
  #define CASADI_PREFIX(ID) snakecg_na3_bias_forces_ ## ID
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
CASADI_SYMBOL_EXPORT void snakecg_na3_bias_forces_casadi_version(int* major, int* minor, int* patch) {
  *major = 3;
  *minor = 8;
  *patch = 2;
}
CASADI_SYMBOL_EXPORT int snakecg_na3_bias_forces_casadi_int_size(void) { return (int) sizeof(casadi_int); }
CASADI_SYMBOL_EXPORT int snakecg_na3_bias_forces_casadi_real_size(void) { return (int) sizeof(casadi_real); }

static const casadi_int casadi_s0[3] = {6, 1, 1};
static const casadi_int casadi_s1[3] = {35, 1, 1};

/* snakecg_na3_bias_forces:(q[6],v[6],K[35])->(h[6]) */
static int casadi_f0(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem) {
  casadi_real a00, a01, a02, a03, a04, a05, a06, a07, a08, a09, a10, a11;
  casadi_real a12, a13, a14, a15, a16, a17, a18, a19, a20, a21, a22, a23;
  casadi_real a24, a25, a26, a27, a28, a29, a30;
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
  a08=arg[2]? arg[2][13] : 0;
  a09=(a07*a08);
  a10=(a02*a09);
  a01=casadi_sq(a01);
  a11=arg[2]? arg[2][4] : 0;
  a12=arg[2]? arg[2][12] : 0;
  a11=(a11-a12);
  a12=(a04*a11);
  a13=(a01*a12);
  a10=(a10+a13);
  a13=arg[2]? arg[2][1] : 0;
  a14=(a10*a13);
  a15=arg[2]? arg[2][5] : 0;
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
  a06=arg[2]? arg[2][14] : 0;
  a05=(a19*a06);
  a20=arg[1]? arg[1][4] : 0;
  a00=(a00+a20);
  a20=casadi_sq(a00);
  a21=(a05*a20);
  a10=(a10+a21);
  a21=arg[2]? arg[2][2] : 0;
  a22=(a10*a21);
  a23=arg[2]? arg[2][6] : 0;
  a23=(a23-a06);
  a24=(a19*a23);
  a25=(a24*a20);
  a10=(a10+a25);
  a25=arg[1]? arg[1][5] : 0;
  a00=(a00+a25);
  a00=casadi_sq(a00);
  a25=arg[0]? arg[0][5] : 0;
  a26=cos(a25);
  a27=(a19*a26);
  a07=(a07*a17);
  a18=(a18*a04);
  a07=(a07+a18);
  a25=sin(a25);
  a18=(a07*a25);
  a27=(a27-a18);
  a18=arg[2]? arg[2][15] : 0;
  a27=(a27*a18);
  a17=(a00*a27);
  a10=(a10+a17);
  a17=arg[2]? arg[2][3] : 0;
  a10=(a10*a17);
  a28=(a22+a10);
  a29=(a14+a28);
  a30=(-a29);
  if (res[0]!=0) res[0][0]=a30;
  a08=(a04*a08);
  a30=(a02*a08);
  a11=(a11*a03);
  a01=(a01*a11);
  a30=(a30+a01);
  a13=(a30*a13);
  a15=(a15*a04);
  a02=(a02*a15);
  a30=(a30+a02);
  a06=(a07*a06);
  a02=(a06*a20);
  a30=(a30+a02);
  a21=(a30*a21);
  a19=(a19*a25);
  a26=(a26*a07);
  a19=(a19+a26);
  a19=(a19*a18);
  a00=(a00*a19);
  a30=(a30+a00);
  a23=(a23*a07);
  a20=(a23*a20);
  a30=(a30+a20);
  a20=(a30*a17);
  a07=(a21+a20);
  a00=(a13+a07);
  a18=(-a00);
  if (res[0]!=0) res[0][1]=a18;
  a18=arg[0]? arg[0][1] : 0;
  a11=(a11+a18);
  a08=(a08+a11);
  a15=(a15+a08);
  a06=(a06+a15);
  a23=(a23+a06);
  a19=(a19+a23);
  a19=(a10*a19);
  a26=arg[0]? arg[0][0] : 0;
  a12=(a12+a26);
  a09=(a09+a12);
  a16=(a16+a09);
  a05=(a05+a16);
  a24=(a24+a05);
  a27=(a27+a24);
  a30=(a30*a27);
  a30=(a30*a17);
  a19=(a19-a30);
  a21=(a21*a05);
  a21=(a19-a21);
  a22=(a22*a06);
  a21=(a21+a22);
  a13=(a13*a09);
  a13=(a21-a13);
  a14=(a14*a08);
  a13=(a13+a14);
  a18=(a29*a18);
  a18=(a13-a18);
  a26=(a00*a26);
  a18=(a18+a26);
  if (res[0]!=0) res[0][2]=a18;
  a29=(a29*a11);
  a13=(a13-a29);
  a00=(a00*a12);
  a13=(a13+a00);
  if (res[0]!=0) res[0][3]=a13;
  a28=(a28*a15);
  a21=(a21-a28);
  a07=(a07*a16);
  a21=(a21+a07);
  if (res[0]!=0) res[0][4]=a21;
  a10=(a10*a23);
  a19=(a19-a10);
  a20=(a20*a24);
  a19=(a19+a20);
  if (res[0]!=0) res[0][5]=a19;
  return 0;
}

CASADI_SYMBOL_EXPORT int snakecg_na3_bias_forces(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem){
  return casadi_f0(arg, res, iw, w, mem);
}

CASADI_SYMBOL_EXPORT int snakecg_na3_bias_forces_checkout(void) {
  return 0;
}

CASADI_SYMBOL_EXPORT void snakecg_na3_bias_forces_release(int mem) {
}

CASADI_SYMBOL_EXPORT void snakecg_na3_bias_forces_incref(void) {
}

CASADI_SYMBOL_EXPORT void snakecg_na3_bias_forces_decref(void) {
}

CASADI_SYMBOL_EXPORT casadi_int snakecg_na3_bias_forces_n_in(void) { return 3;}

CASADI_SYMBOL_EXPORT casadi_int snakecg_na3_bias_forces_n_out(void) { return 1;}

CASADI_SYMBOL_EXPORT casadi_real snakecg_na3_bias_forces_default_in(casadi_int i) {
  switch (i) {
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const char* snakecg_na3_bias_forces_name_in(casadi_int i) {
  switch (i) {
    case 0: return "q";
    case 1: return "v";
    case 2: return "K";
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const char* snakecg_na3_bias_forces_name_out(casadi_int i) {
  switch (i) {
    case 0: return "h";
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const casadi_int* snakecg_na3_bias_forces_sparsity_in(casadi_int i) {
  switch (i) {
    case 0: return casadi_s0;
    case 1: return casadi_s0;
    case 2: return casadi_s1;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const casadi_int* snakecg_na3_bias_forces_sparsity_out(casadi_int i) {
  switch (i) {
    case 0: return casadi_s0;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT int snakecg_na3_bias_forces_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w) {
  if (sz_arg) *sz_arg = 3;
  if (sz_res) *sz_res = 1;
  if (sz_iw) *sz_iw = 0;
  if (sz_w) *sz_w = 0;
  return 0;
}

CASADI_SYMBOL_EXPORT int snakecg_na3_bias_forces_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w) {
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

CASADI_SYMBOL_EXPORT int snakecg_na3_batch_bias_forces(casadi_int n, const casadi_real** arg,
    const casadi_int* stride, casadi_real** res) {
  const casadi_real* a[3];
  casadi_real* r[1];
  casadi_int* iw = (casadi_int*) malloc(sizeof(casadi_int) * 1);
  casadi_real* w = (casadi_real*) malloc(sizeof(casadi_real) * 32);
  casadi_int i, k;
  int status = 0;
  if (!iw || !w) { free(iw); free(w); return -1; }
  for (k = 0; k < 3; ++k) a[k] = 0;
  for (k = 0; k < 1; ++k) r[k] = 0;
  for (i = 0; i < n; ++i) {
    a[0] = arg[0] + i * stride[0];
    a[1] = arg[1] + i * stride[1];
    a[2] = arg[2] + i * stride[2];
    r[0] = res[0] + i * 6;
    if (snakecg_na3_bias_forces(a, r, iw, w, 0)) { status = (int) (i + 1); break; }
  }
  free(iw);
  free(w);
  return status;
}
