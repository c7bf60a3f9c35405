/* GENERATED FILE - DO NOT EDIT. C code emitted by CasADi for kinematic_map() of
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
  #define CASADI_PREFIX(ID) snakecg_sp1_kinematic_map_ ## ID
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
CASADI_SYMBOL_EXPORT void snakecg_sp1_kinematic_map_casadi_version(int* major, int* minor, int* patch) {
  *major = 3;
  *minor = 8;
  *patch = 2;
}
CASADI_SYMBOL_EXPORT int snakecg_sp1_kinematic_map_casadi_int_size(void) { return (int) sizeof(casadi_int); }
CASADI_SYMBOL_EXPORT int snakecg_sp1_kinematic_map_casadi_real_size(void) { return (int) sizeof(casadi_real); }

static const casadi_int casadi_s0[3] = {8, 1, 1};
static const casadi_int casadi_s1[3] = {8, 7, 1};

/* snakecg_sp1_kinematic_map:(q[8])->(G[8x7]) */
static int casadi_f0(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem) {
  casadi_real a00, a01, a02, a03, a04, a05, a06, a07, a08, a09, a10, a11;
  casadi_real a12, a13;
  a00=1.;
  a01=-2.;
  a02=arg[0]? arg[0][4] : 0;
  a03=casadi_sq(a02);
  a03=(a01*a03);
  a04=(a00+a03);
  a05=arg[0]? arg[0][5] : 0;
  a06=casadi_sq(a05);
  a06=(a01*a06);
  a04=(a04+a06);
  if (res[0]!=0) res[0][0]=a04;
  a04=arg[0]? arg[0][6] : 0;
  a07=(2.*a04);
  a08=(a07*a05);
  a09=arg[0]? arg[0][3] : 0;
  a10=(2.*a09);
  a11=(a10*a02);
  a08=(a08+a11);
  if (res[0]!=0) res[0][1]=a08;
  a08=(a01*a04);
  a12=(a08*a02);
  a10=(a10*a05);
  a12=(a12+a10);
  if (res[0]!=0) res[0][2]=a12;
  a12=0.;
  if (res[0]!=0) res[0][3]=a12;
  if (res[0]!=0) res[0][4]=a12;
  if (res[0]!=0) res[0][5]=a12;
  if (res[0]!=0) res[0][6]=a12;
  if (res[0]!=0) res[0][7]=a12;
  a13=(a08*a05);
  a13=(a13+a11);
  if (res[0]!=0) res[0][8]=a13;
  a13=casadi_sq(a09);
  a01=(a01*a13);
  a01=(a00+a01);
  a06=(a01+a06);
  if (res[0]!=0) res[0][9]=a06;
  a06=(a07*a09);
  a13=(2.*a02);
  a13=(a13*a05);
  a06=(a06+a13);
  if (res[0]!=0) res[0][10]=a06;
  if (res[0]!=0) res[0][11]=a12;
  if (res[0]!=0) res[0][12]=a12;
  if (res[0]!=0) res[0][13]=a12;
  if (res[0]!=0) res[0][14]=a12;
  if (res[0]!=0) res[0][15]=a12;
  a07=(a07*a02);
  a07=(a07+a10);
  if (res[0]!=0) res[0][16]=a07;
  a08=(a08*a09);
  a08=(a08+a13);
  if (res[0]!=0) res[0][17]=a08;
  a01=(a01+a03);
  if (res[0]!=0) res[0][18]=a01;
  if (res[0]!=0) res[0][19]=a12;
  if (res[0]!=0) res[0][20]=a12;
  if (res[0]!=0) res[0][21]=a12;
  if (res[0]!=0) res[0][22]=a12;
  if (res[0]!=0) res[0][23]=a12;
  if (res[0]!=0) res[0][24]=a12;
  if (res[0]!=0) res[0][25]=a12;
  if (res[0]!=0) res[0][26]=a12;
  a01=5.0000000000000000e-01;
  a04=(a01*a04);
  if (res[0]!=0) res[0][27]=a04;
  a03=(a01*a05);
  if (res[0]!=0) res[0][28]=a03;
  a03=-5.0000000000000000e-01;
  a08=(a03*a02);
  if (res[0]!=0) res[0][29]=a08;
  a13=(a03*a09);
  if (res[0]!=0) res[0][30]=a13;
  if (res[0]!=0) res[0][31]=a12;
  if (res[0]!=0) res[0][32]=a12;
  if (res[0]!=0) res[0][33]=a12;
  if (res[0]!=0) res[0][34]=a12;
  a03=(a03*a05);
  if (res[0]!=0) res[0][35]=a03;
  if (res[0]!=0) res[0][36]=a04;
  a09=(a01*a09);
  if (res[0]!=0) res[0][37]=a09;
  if (res[0]!=0) res[0][38]=a08;
  if (res[0]!=0) res[0][39]=a12;
  if (res[0]!=0) res[0][40]=a12;
  if (res[0]!=0) res[0][41]=a12;
  if (res[0]!=0) res[0][42]=a12;
  a01=(a01*a02);
  if (res[0]!=0) res[0][43]=a01;
  if (res[0]!=0) res[0][44]=a13;
  if (res[0]!=0) res[0][45]=a04;
  if (res[0]!=0) res[0][46]=a03;
  if (res[0]!=0) res[0][47]=a12;
  if (res[0]!=0) res[0][48]=a12;
  if (res[0]!=0) res[0][49]=a12;
  if (res[0]!=0) res[0][50]=a12;
  if (res[0]!=0) res[0][51]=a12;
  if (res[0]!=0) res[0][52]=a12;
  if (res[0]!=0) res[0][53]=a12;
  if (res[0]!=0) res[0][54]=a12;
  if (res[0]!=0) res[0][55]=a00;
  return 0;
}

CASADI_SYMBOL_EXPORT int snakecg_sp1_kinematic_map(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem){
  return casadi_f0(arg, res, iw, w, mem);
}

CASADI_SYMBOL_EXPORT int snakecg_sp1_kinematic_map_checkout(void) {
  return 0;
}

CASADI_SYMBOL_EXPORT void snakecg_sp1_kinematic_map_release(int mem) {
}

CASADI_SYMBOL_EXPORT void snakecg_sp1_kinematic_map_incref(void) {
}

CASADI_SYMBOL_EXPORT void snakecg_sp1_kinematic_map_decref(void) {
}

CASADI_SYMBOL_EXPORT casadi_int snakecg_sp1_kinematic_map_n_in(void) { return 1;}

CASADI_SYMBOL_EXPORT casadi_int snakecg_sp1_kinematic_map_n_out(void) { return 1;}

CASADI_SYMBOL_EXPORT casadi_real snakecg_sp1_kinematic_map_default_in(casadi_int i) {
  switch (i) {
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const char* snakecg_sp1_kinematic_map_name_in(casadi_int i) {
  switch (i) {
    case 0: return "q";
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const char* snakecg_sp1_kinematic_map_name_out(casadi_int i) {
  switch (i) {
    case 0: return "G";
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const casadi_int* snakecg_sp1_kinematic_map_sparsity_in(casadi_int i) {
  switch (i) {
    case 0: return casadi_s0;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const casadi_int* snakecg_sp1_kinematic_map_sparsity_out(casadi_int i) {
  switch (i) {
    case 0: return casadi_s1;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT int snakecg_sp1_kinematic_map_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w) {
  if (sz_arg) *sz_arg = 1;
  if (sz_res) *sz_res = 1;
  if (sz_iw) *sz_iw = 0;
  if (sz_w) *sz_w = 0;
  return 0;
}

CASADI_SYMBOL_EXPORT int snakecg_sp1_kinematic_map_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w) {
  if (sz_arg) *sz_arg = 1*sizeof(const casadi_real*);
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

CASADI_SYMBOL_EXPORT int snakecg_sp1_batch_kinematic_map(casadi_int n, const casadi_real** arg,
    const casadi_int* stride, casadi_real** res) {
  const casadi_real* a[1];
  casadi_real* r[1];
  casadi_int* iw = (casadi_int*) malloc(sizeof(casadi_int) * 1);
  casadi_real* w = (casadi_real*) malloc(sizeof(casadi_real) * 15);
  casadi_int i, k;
  int status = 0;
  if (!iw || !w) { free(iw); free(w); return -1; }
  for (k = 0; k < 1; ++k) a[k] = 0;
  for (k = 0; k < 1; ++k) r[k] = 0;
  for (i = 0; i < n; ++i) {
    a[0] = arg[0] + i * stride[0];
    r[0] = res[0] + i * 56;
    if (snakecg_sp1_kinematic_map(a, r, iw, w, 0)) { status = (int) (i + 1); break; }
  }
  free(iw);
  free(w);
  return status;
}
