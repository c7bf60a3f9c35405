/* GENERATED FILE - DO NOT EDIT. C code emitted by CasADi for derived_parameters() of
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
  #define CASADI_PREFIX(ID) snakecg_na1_derived_parameters_ ## ID
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
CASADI_SYMBOL_EXPORT void snakecg_na1_derived_parameters_casadi_version(int* major, int* minor, int* patch) {
  *major = 3;
  *minor = 8;
  *patch = 2;
}
CASADI_SYMBOL_EXPORT int snakecg_na1_derived_parameters_casadi_int_size(void) { return (int) sizeof(casadi_int); }
CASADI_SYMBOL_EXPORT int snakecg_na1_derived_parameters_casadi_real_size(void) { return (int) sizeof(casadi_real); }

static const casadi_int casadi_s0[3] = {2, 1, 1};
static const casadi_int casadi_s1[3] = {16, 1, 1};

/* snakecg_na1_derived_parameters:(link_mass[2],link_length[2],link_inertia[2],link_com[2])->(K[16]) */
static int casadi_f0(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem) {
  casadi_real a0, a1, a2, a3, a4, a5, a6;
  a0=arg[0]? arg[0][0] : 0;
  if (res[0]!=0) res[0][0]=a0;
  a1=arg[0]? arg[0][1] : 0;
  if (res[0]!=0) res[0][1]=a1;
  a2=arg[1]? arg[1][0] : 0;
  if (res[0]!=0) res[0][2]=a2;
  a3=arg[1]? arg[1][1] : 0;
  if (res[0]!=0) res[0][3]=a3;
  a3=arg[2]? arg[2][0] : 0;
  if (res[0]!=0) res[0][4]=a3;
  a4=arg[2]? arg[2][1] : 0;
  if (res[0]!=0) res[0][5]=a4;
  a5=arg[3]? arg[3][0] : 0;
  if (res[0]!=0) res[0][6]=a5;
  a6=arg[3]? arg[3][1] : 0;
  if (res[0]!=0) res[0][7]=a6;
  a0=(a0+a1);
  if (res[0]!=0) res[0][8]=a0;
  a2=(a2-a5);
  a5=(a2*a1);
  if (res[0]!=0) res[0][9]=a5;
  a0=(a6*a1);
  if (res[0]!=0) res[0][10]=a0;
  a2=casadi_sq(a2);
  a2=(a1*a2);
  if (res[0]!=0) res[0][11]=a2;
  a5=(a5*a6);
  if (res[0]!=0) res[0][12]=a5;
  a6=casadi_sq(a6);
  a1=(a1*a6);
  if (res[0]!=0) res[0][13]=a1;
  a2=(a2+a3);
  if (res[0]!=0) res[0][14]=a2;
  a1=(a1+a4);
  if (res[0]!=0) res[0][15]=a1;
  return 0;
}

CASADI_SYMBOL_EXPORT int snakecg_na1_derived_parameters(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem){
  return casadi_f0(arg, res, iw, w, mem);
}

CASADI_SYMBOL_EXPORT int snakecg_na1_derived_parameters_checkout(void) {
  return 0;
}

CASADI_SYMBOL_EXPORT void snakecg_na1_derived_parameters_release(int mem) {
}

CASADI_SYMBOL_EXPORT void snakecg_na1_derived_parameters_incref(void) {
}

CASADI_SYMBOL_EXPORT void snakecg_na1_derived_parameters_decref(void) {
}

CASADI_SYMBOL_EXPORT casadi_int snakecg_na1_derived_parameters_n_in(void) { return 4;}

CASADI_SYMBOL_EXPORT casadi_int snakecg_na1_derived_parameters_n_out(void) { return 1;}

CASADI_SYMBOL_EXPORT casadi_real snakecg_na1_derived_parameters_default_in(casadi_int i) {
  switch (i) {
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const char* snakecg_na1_derived_parameters_name_in(casadi_int i) {
  switch (i) {
    case 0: return "link_mass";
    case 1: return "link_length";
    case 2: return "link_inertia";
    case 3: return "link_com";
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const char* snakecg_na1_derived_parameters_name_out(casadi_int i) {
  switch (i) {
    case 0: return "K";
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const casadi_int* snakecg_na1_derived_parameters_sparsity_in(casadi_int i) {
  switch (i) {
    case 0: return casadi_s0;
    case 1: return casadi_s0;
    case 2: return casadi_s0;
    case 3: return casadi_s0;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const casadi_int* snakecg_na1_derived_parameters_sparsity_out(casadi_int i) {
  switch (i) {
    case 0: return casadi_s1;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT int snakecg_na1_derived_parameters_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w) {
  if (sz_arg) *sz_arg = 4;
  if (sz_res) *sz_res = 1;
  if (sz_iw) *sz_iw = 0;
  if (sz_w) *sz_w = 0;
  return 0;
}

CASADI_SYMBOL_EXPORT int snakecg_na1_derived_parameters_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w) {
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

CASADI_SYMBOL_EXPORT int snakecg_na1_batch_derived_parameters(casadi_int n, const casadi_real** arg,
    const casadi_int* stride, casadi_real** res) {
  const casadi_real* a[4];
  casadi_real* r[1];
  casadi_int* iw = (casadi_int*) malloc(sizeof(casadi_int) * 1);
  casadi_real* w = (casadi_real*) malloc(sizeof(casadi_real) * 8);
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
    r[0] = res[0] + i * 16;
    if (snakecg_na1_derived_parameters(a, r, iw, w, 0)) { status = (int) (i + 1); break; }
  }
  free(iw);
  free(w);
  return status;
}
