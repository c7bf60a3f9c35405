/* GENERATED FILE - DO NOT EDIT. C code emitted by CasADi for bias_forces_cs() of
 * generated/na2/ (see its model.py), plus its batched driver.
 * Regenerate with: python -m snakecg_derive --checked-in
 * spec sha256: 1ffd02983b32fea1953b31d6b4da6e985de5a598f8e69763f0a5d6374958d5e8
 * tools: sympy 1.14.0, casadi 3.8.2, jinja2 3.1.6
 */
/* How to prefix internal symbols */
#ifdef CASADI_CODEGEN_PREFIX
  #define CASADI_NAMESPACE_CONCAT(NS, ID) _CASADI_NAMESPACE_CONCAT(NS, ID)
  #define _CASADI_NAMESPACE_CONCAT(NS, ID) NS ## ID
  #define CASADI_PREFIX(ID) CASADI_NAMESPACE_CONCAT(CODEGEN_PREFIX, ID)
#else
  #define CASADI_PREFIX(ID) snakecg_na2_bias_forces_cs_ ## ID
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
CASADI_SYMBOL_EXPORT void snakecg_na2_bias_forces_cs_casadi_version(int* major, int* minor, int* patch) {
  *major = 3;
  *minor = 8;
  *patch = 2;
}
CASADI_SYMBOL_EXPORT int snakecg_na2_bias_forces_cs_casadi_int_size(void) { return (int) sizeof(casadi_int); }
CASADI_SYMBOL_EXPORT int snakecg_na2_bias_forces_cs_casadi_real_size(void) { return (int) sizeof(casadi_real); }

static const casadi_int casadi_s0[3] = {6, 1, 1};
static const casadi_int casadi_s1[3] = {5, 1, 1};
static const casadi_int casadi_s2[3] = {25, 1, 1};

/* snakecg_na2_bias_forces_cs:(cs[6],q[5],v[5],K[25])->(h[5]) */
static int casadi_f0(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem) {
  casadi_real a00, a01, a02, a03, a04, a05, a06, a07, a08, a09, a10, a11;
  casadi_real a12, a13, a14, a15, a16, a17, a18;
  a00=arg[2]? arg[2][3] : 0;
  a01=arg[2]? arg[2][2] : 0;
  a00=(a00+a01);
  a02=casadi_sq(a00);
  a03=arg[0]? arg[0][2] : 0;
  a04=arg[3]? arg[3][10] : 0;
  a05=(a03*a04);
  a06=(a02*a05);
  a01=casadi_sq(a01);
  a07=arg[0]? arg[0][0] : 0;
  a08=arg[3]? arg[3][3] : 0;
  a09=arg[3]? arg[3][9] : 0;
  a08=(a08-a09);
  a07=(a07*a08);
  a09=(a01*a07);
  a06=(a06+a09);
  a09=arg[3]? arg[3][1] : 0;
  a10=(a06*a09);
  a11=arg[3]? arg[3][4] : 0;
  a11=(a11-a04);
  a03=(a03*a11);
  a12=(a02*a03);
  a06=(a06+a12);
  a12=arg[0]? arg[0][4] : 0;
  a13=arg[3]? arg[3][11] : 0;
  a12=(a12*a13);
  a14=arg[2]? arg[2][4] : 0;
  a00=(a00+a14);
  a00=casadi_sq(a00);
  a14=(a12*a00);
  a06=(a06+a14);
  a14=arg[3]? arg[3][2] : 0;
  a06=(a06*a14);
  a15=(a10+a06);
  a16=(-a15);
  if (res[0]!=0) res[0][0]=a16;
  a16=arg[0]? arg[0][3] : 0;
  a04=(a16*a04);
  a17=(a02*a04);
  a18=arg[0]? arg[0][1] : 0;
  a08=(a08*a18);
  a01=(a01*a08);
  a17=(a17+a01);
  a09=(a17*a09);
  a11=(a11*a16);
  a02=(a02*a11);
  a17=(a17+a02);
  a02=arg[0]? arg[0][5] : 0;
  a02=(a02*a13);
  a00=(a02*a00);
  a17=(a17+a00);
  a00=(a17*a14);
  a13=(a09+a00);
  a16=(-a13);
  if (res[0]!=0) res[0][1]=a16;
  a16=arg[1]? arg[1][1] : 0;
  a08=(a08+a16);
  a04=(a04+a08);
  a11=(a11+a04);
  a02=(a02+a11);
  a02=(a06*a02);
  a01=arg[1]? arg[1][0] : 0;
  a07=(a07+a01);
  a05=(a05+a07);
  a03=(a03+a05);
  a12=(a12+a03);
  a17=(a17*a12);
  a17=(a17*a14);
  a02=(a02-a17);
  a09=(a09*a05);
  a09=(a02-a09);
  a10=(a10*a04);
  a09=(a09+a10);
  a16=(a15*a16);
  a16=(a09-a16);
  a01=(a13*a01);
  a16=(a16+a01);
  if (res[0]!=0) res[0][2]=a16;
  a15=(a15*a08);
  a09=(a09-a15);
  a13=(a13*a07);
  a09=(a09+a13);
  if (res[0]!=0) res[0][3]=a09;
  a06=(a06*a11);
  a02=(a02-a06);
  a00=(a00*a03);
  a02=(a02+a00);
  if (res[0]!=0) res[0][4]=a02;
  return 0;
}

CASADI_SYMBOL_EXPORT int snakecg_na2_bias_forces_cs(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem){
  return casadi_f0(arg, res, iw, w, mem);
}

CASADI_SYMBOL_EXPORT int snakecg_na2_bias_forces_cs_checkout(void) {
  return 0;
}

CASADI_SYMBOL_EXPORT void snakecg_na2_bias_forces_cs_release(int mem) {
}

CASADI_SYMBOL_EXPORT void snakecg_na2_bias_forces_cs_incref(void) {
}

CASADI_SYMBOL_EXPORT void snakecg_na2_bias_forces_cs_decref(void) {
}

CASADI_SYMBOL_EXPORT casadi_int snakecg_na2_bias_forces_cs_n_in(void) { return 4;}

CASADI_SYMBOL_EXPORT casadi_int snakecg_na2_bias_forces_cs_n_out(void) { return 1;}

CASADI_SYMBOL_EXPORT casadi_real snakecg_na2_bias_forces_cs_default_in(casadi_int i) {
  switch (i) {
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const char* snakecg_na2_bias_forces_cs_name_in(casadi_int i) {
  switch (i) {
    case 0: return "cs";
    case 1: return "q";
    case 2: return "v";
    case 3: return "K";
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const char* snakecg_na2_bias_forces_cs_name_out(casadi_int i) {
  switch (i) {
    case 0: return "h";
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const casadi_int* snakecg_na2_bias_forces_cs_sparsity_in(casadi_int i) {
  switch (i) {
    case 0: return casadi_s0;
    case 1: return casadi_s1;
    case 2: return casadi_s1;
    case 3: return casadi_s2;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const casadi_int* snakecg_na2_bias_forces_cs_sparsity_out(casadi_int i) {
  switch (i) {
    case 0: return casadi_s1;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT int snakecg_na2_bias_forces_cs_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w) {
  if (sz_arg) *sz_arg = 4;
  if (sz_res) *sz_res = 1;
  if (sz_iw) *sz_iw = 0;
  if (sz_w) *sz_w = 0;
  return 0;
}

CASADI_SYMBOL_EXPORT int snakecg_na2_bias_forces_cs_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w) {
  if (sz_arg) *sz_arg = 4*sizeof(const casadi_real*);
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

CASADI_SYMBOL_EXPORT int snakecg_na2_batch_bias_forces_cs(casadi_int n, const casadi_real** arg,
    const casadi_int* stride, casadi_real** res) {
  const casadi_real* a[4];
  casadi_real* r[1];
  casadi_int* iw = (casadi_int*) malloc(sizeof(casadi_int) * 1);
  casadi_real* w = (casadi_real*) malloc(sizeof(casadi_real) * 20);
  casadi_int i, k;
  int status = 0;
  if (!iw || !w) { free(iw); free(w); return -1; }
  for (k = 0; k < 4; ++k) a[k] = 0;
  for (k = 0; k < 1; ++k) r[k] = 0;
  for (i = 0; i < n; ++i) {
    a[0] = arg[0] + i * stride[0];
    a[1] = arg[1] + i * stride[1];
    a[2] = arg[2] + i * stride[2];
    a[3] = arg[3] + i * stride[3];
    r[0] = res[0] + i * 5;
    if (snakecg_na2_bias_forces_cs(a, r, iw, w, 0)) { status = (int) (i + 1); break; }
  }
  free(iw);
  free(w);
  return status;
}
