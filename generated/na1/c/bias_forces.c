/* GENERATED FILE - DO NOT EDIT. C code emitted by CasADi for bias_forces() of
 * generated/na1/ (see its model.py), plus its batched driver.
 * Regenerate with: python -m snakecg_derive --checked-in
 * spec sha256: cfb213c907b133d8468816b35e2514e88b652abe0e80fc54ab4677cd1d4b1854
 * tools: sympy 1.14.0, casadi 3.8.2, jinja2 3.1.6
 */
/* How to prefix internal symbols */
#ifdef CASADI_CODEGEN_PREFIX
  #define CASADI_NAMESPACE_CONCAT(NS, ID) _CASADI_NAMESPACE_CONCAT(NS, ID)
  #define _CASADI_NAMESPACE_CONCAT(NS, ID) NS ## ID
  #define CASADI_PREFIX(ID) CASADI_NAMESPACE_CONCAT(CODEGEN_PREFIX, ID)
#else
  #define CASADI_PREFIX(ID) snakecg_na1_bias_forces_ ## ID
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
CASADI_SYMBOL_EXPORT void snakecg_na1_bias_forces_casadi_version(int* major, int* minor, int* patch) {
  *major = 3;
  *minor = 8;
  *patch = 2;
}
CASADI_SYMBOL_EXPORT int snakecg_na1_bias_forces_casadi_int_size(void) { return (int) sizeof(casadi_int); }
CASADI_SYMBOL_EXPORT int snakecg_na1_bias_forces_casadi_real_size(void) { return (int) sizeof(casadi_real); }

static const casadi_int casadi_s0[3] = {4, 1, 1};
static const casadi_int casadi_s1[3] = {16, 1, 1};

/* snakecg_na1_bias_forces:(q[4],v[4],K[16])->(h[4]) */
static int casadi_f0(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem) {
  casadi_real a00, a01, a02, a03, a04, a05, a06, a07, a08, a09, a10, a11;
  casadi_real a12;
  a00=arg[1]? arg[1][3] : 0;
  a01=arg[1]? arg[1][2] : 0;
  a00=(a00+a01);
  a00=casadi_sq(a00);
  a02=arg[0]? arg[0][2] : 0;
  a03=cos(a02);
  a04=arg[0]? arg[0][3] : 0;
  a05=cos(a04);
  a06=(a03*a05);
  a02=sin(a02);
  a04=sin(a04);
  a07=(a02*a04);
  a06=(a06-a07);
  a07=arg[2]? arg[2][7] : 0;
  a06=(a06*a07);
  a08=(a00*a06);
  a01=casadi_sq(a01);
  a09=arg[2]? arg[2][2] : 0;
  a10=arg[2]? arg[2][6] : 0;
  a09=(a09-a10);
  a10=(a03*a09);
  a11=(a01*a10);
  a08=(a08+a11);
  a11=arg[2]? arg[2][1] : 0;
  a08=(a08*a11);
  a12=(-a08);
  if (res[0]!=0) res[0][0]=a12;
  a03=(a03*a04);
  a05=(a05*a02);
  a03=(a03+a05);
  a03=(a03*a07);
  a00=(a00*a03);
  a09=(a09*a02);
  a01=(a01*a09);
  a00=(a00+a01);
  a01=(a00*a11);
  a02=(-a01);
  if (res[0]!=0) res[0][1]=a02;
  a02=arg[0]? arg[0][1] : 0;
  a09=(a09+a02);
  a03=(a03+a09);
  a03=(a08*a03);
  a07=arg[0]? arg[0][0] : 0;
  a10=(a10+a07);
  a06=(a06+a10);
  a00=(a00*a06);
  a00=(a00*a11);
  a03=(a03-a00);
  a02=(a08*a02);
  a02=(a03-a02);
  a07=(a01*a07);
  a02=(a02+a07);
  if (res[0]!=0) res[0][2]=a02;
  a08=(a08*a09);
  a03=(a03-a08);
  a01=(a01*a10);
  a03=(a03+a01);
  if (res[0]!=0) res[0][3]=a03;
  return 0;
}

CASADI_SYMBOL_EXPORT int snakecg_na1_bias_forces(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem){
  return casadi_f0(arg, res, iw, w, mem);
}

CASADI_SYMBOL_EXPORT int snakecg_na1_bias_forces_checkout(void) {
  return 0;
}

CASADI_SYMBOL_EXPORT void snakecg_na1_bias_forces_release(int mem) {
}

CASADI_SYMBOL_EXPORT void snakecg_na1_bias_forces_incref(void) {
}

CASADI_SYMBOL_EXPORT void snakecg_na1_bias_forces_decref(void) {
}

CASADI_SYMBOL_EXPORT casadi_int snakecg_na1_bias_forces_n_in(void) { return 3;}

CASADI_SYMBOL_EXPORT casadi_int snakecg_na1_bias_forces_n_out(void) { return 1;}

CASADI_SYMBOL_EXPORT casadi_real snakecg_na1_bias_forces_default_in(casadi_int i) {
  switch (i) {
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const char* snakecg_na1_bias_forces_name_in(casadi_int i) {
  switch (i) {
    case 0: return "q";
    case 1: return "v";
    case 2: return "K";
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const char* snakecg_na1_bias_forces_name_out(casadi_int i) {
  switch (i) {
    case 0: return "h";
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const casadi_int* snakecg_na1_bias_forces_sparsity_in(casadi_int i) {
  switch (i) {
    case 0: return casadi_s0;
    case 1: return casadi_s0;
    case 2: return casadi_s1;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const casadi_int* snakecg_na1_bias_forces_sparsity_out(casadi_int i) {
  switch (i) {
    case 0: return casadi_s0;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT int snakecg_na1_bias_forces_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w) {
  if (sz_arg) *sz_arg = 3;
  if (sz_res) *sz_res = 1;
  if (sz_iw) *sz_iw = 0;
  if (sz_w) *sz_w = 0;
  return 0;
}

CASADI_SYMBOL_EXPORT int snakecg_na1_bias_forces_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w) {
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

CASADI_SYMBOL_EXPORT int snakecg_na1_batch_bias_forces(casadi_int n, const casadi_real** arg,
    const casadi_int* stride, casadi_real** res) {
  const casadi_real* a[3];
  casadi_real* r[1];
  casadi_int* iw = (casadi_int*) malloc(sizeof(casadi_int) * 1);
  casadi_real* w = (casadi_real*) malloc(sizeof(casadi_real) * 14);
  casadi_int i, k;
  int status = 0;
  if (!iw || !w) { free(iw); free(w); return -1; }
  for (k = 0; k < 3; ++k) a[k] = 0;
  for (k = 0; k < 1; ++k) r[k] = 0;
  for (i = 0; i < n; ++i) {
    a[0] = arg[0] + i * stride[0];
    a[1] = arg[1] + i * stride[1];
    a[2] = arg[2] + i * stride[2];
    r[0] = res[0] + i * 4;
    if (snakecg_na1_bias_forces(a, r, iw, w, 0)) { status = (int) (i + 1); break; }
  }
  free(iw);
  free(w);
  return status;
}
