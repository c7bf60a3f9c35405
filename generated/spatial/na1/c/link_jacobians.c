/* GENERATED FILE - DO NOT EDIT. C code emitted by CasADi for link_jacobians() of
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
  #define CASADI_PREFIX(ID) snakecg_sp1_link_jacobians_ ## ID
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
CASADI_SYMBOL_EXPORT void snakecg_sp1_link_jacobians_casadi_version(int* major, int* minor, int* patch) {
  *major = 3;
  *minor = 8;
  *patch = 2;
}
CASADI_SYMBOL_EXPORT int snakecg_sp1_link_jacobians_casadi_int_size(void) { return (int) sizeof(casadi_int); }
CASADI_SYMBOL_EXPORT int snakecg_sp1_link_jacobians_casadi_real_size(void) { return (int) sizeof(casadi_real); }

static const casadi_int casadi_s0[3] = {8, 1, 1};
static const casadi_int casadi_s1[3] = {71, 1, 1};
static const casadi_int casadi_s2[3] = {12, 7, 1};

/* snakecg_sp1_link_jacobians:(q[8],K[71])->(J[12x7]) */
static int casadi_f0(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem) {
  casadi_real a00, a01, a02, a03, a04, a05, a06, a07, a08, a09, a10, a11;
  casadi_real a12, a13, a14, a15, a16;
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
  a07=arg[0]? arg[0][6] : 0;
  a08=(2.*a07);
  a09=(a08*a05);
  a10=arg[0]? arg[0][3] : 0;
  a11=(2.*a10);
  a12=(a11*a02);
  a09=(a09+a12);
  if (res[0]!=0) res[0][1]=a09;
  a07=(a01*a07);
  a13=(a07*a02);
  a11=(a11*a05);
  a13=(a13+a11);
  if (res[0]!=0) res[0][2]=a13;
  a14=0.;
  if (res[0]!=0) res[0][3]=a14;
  if (res[0]!=0) res[0][4]=a14;
  if (res[0]!=0) res[0][5]=a14;
  if (res[0]!=0) res[0][6]=a04;
  if (res[0]!=0) res[0][7]=a09;
  if (res[0]!=0) res[0][8]=a13;
  if (res[0]!=0) res[0][9]=a14;
  if (res[0]!=0) res[0][10]=a14;
  if (res[0]!=0) res[0][11]=a14;
  a15=(a07*a05);
  a15=(a15+a12);
  if (res[0]!=0) res[0][12]=a15;
  a12=casadi_sq(a10);
  a01=(a01*a12);
  a00=(a00+a01);
  a06=(a00+a06);
  if (res[0]!=0) res[0][13]=a06;
  a01=(a08*a10);
  a12=(2.*a02);
  a12=(a12*a05);
  a01=(a01+a12);
  if (res[0]!=0) res[0][14]=a01;
  if (res[0]!=0) res[0][15]=a14;
  if (res[0]!=0) res[0][16]=a14;
  if (res[0]!=0) res[0][17]=a14;
  if (res[0]!=0) res[0][18]=a15;
  if (res[0]!=0) res[0][19]=a06;
  if (res[0]!=0) res[0][20]=a01;
  if (res[0]!=0) res[0][21]=a14;
  if (res[0]!=0) res[0][22]=a14;
  if (res[0]!=0) res[0][23]=a14;
  a08=(a08*a02);
  a08=(a08+a11);
  if (res[0]!=0) res[0][24]=a08;
  a07=(a07*a10);
  a07=(a07+a12);
  if (res[0]!=0) res[0][25]=a07;
  a00=(a00+a03);
  if (res[0]!=0) res[0][26]=a00;
  if (res[0]!=0) res[0][27]=a14;
  if (res[0]!=0) res[0][28]=a14;
  if (res[0]!=0) res[0][29]=a14;
  if (res[0]!=0) res[0][30]=a08;
  if (res[0]!=0) res[0][31]=a07;
  if (res[0]!=0) res[0][32]=a00;
  if (res[0]!=0) res[0][33]=a14;
  if (res[0]!=0) res[0][34]=a14;
  if (res[0]!=0) res[0][35]=a14;
  if (res[0]!=0) res[0][36]=a14;
  if (res[0]!=0) res[0][37]=a14;
  if (res[0]!=0) res[0][38]=a14;
  if (res[0]!=0) res[0][39]=a04;
  if (res[0]!=0) res[0][40]=a09;
  if (res[0]!=0) res[0][41]=a13;
  a03=arg[1]? arg[1][50] : 0;
  a12=(a13*a03);
  a10=arg[1]? arg[1][51] : 0;
  a11=(a01*a10);
  a12=(a12+a11);
  a11=arg[1]? arg[1][52] : 0;
  a02=(a00*a11);
  a12=(a12+a02);
  a02=(a09*a12);
  a05=(a09*a03);
  a16=(a06*a10);
  a05=(a05+a16);
  a16=(a07*a11);
  a05=(a05+a16);
  a16=(a13*a05);
  a02=(a02-a16);
  if (res[0]!=0) res[0][42]=a02;
  a03=(a04*a03);
  a10=(a15*a10);
  a03=(a03+a10);
  a11=(a08*a11);
  a03=(a03+a11);
  a11=(a13*a03);
  a10=(a04*a12);
  a11=(a11-a10);
  if (res[0]!=0) res[0][43]=a11;
  a11=(a04*a05);
  a10=(a09*a03);
  a11=(a11-a10);
  if (res[0]!=0) res[0][44]=a11;
  if (res[0]!=0) res[0][45]=a04;
  if (res[0]!=0) res[0][46]=a09;
  if (res[0]!=0) res[0][47]=a13;
  if (res[0]!=0) res[0][48]=a14;
  if (res[0]!=0) res[0][49]=a14;
  if (res[0]!=0) res[0][50]=a14;
  if (res[0]!=0) res[0][51]=a15;
  if (res[0]!=0) res[0][52]=a06;
  if (res[0]!=0) res[0][53]=a01;
  a11=(a06*a12);
  a10=(a01*a05);
  a11=(a11-a10);
  if (res[0]!=0) res[0][54]=a11;
  a11=(a01*a03);
  a10=(a15*a12);
  a11=(a11-a10);
  if (res[0]!=0) res[0][55]=a11;
  a11=(a15*a05);
  a10=(a06*a03);
  a11=(a11-a10);
  if (res[0]!=0) res[0][56]=a11;
  if (res[0]!=0) res[0][57]=a15;
  if (res[0]!=0) res[0][58]=a06;
  if (res[0]!=0) res[0][59]=a01;
  if (res[0]!=0) res[0][60]=a14;
  if (res[0]!=0) res[0][61]=a14;
  if (res[0]!=0) res[0][62]=a14;
  if (res[0]!=0) res[0][63]=a08;
  if (res[0]!=0) res[0][64]=a07;
  if (res[0]!=0) res[0][65]=a00;
  a11=(a07*a12);
  a10=(a00*a05);
  a11=(a11-a10);
  if (res[0]!=0) res[0][66]=a11;
  a11=(a00*a03);
  a12=(a08*a12);
  a11=(a11-a12);
  if (res[0]!=0) res[0][67]=a11;
  a05=(a08*a05);
  a03=(a07*a03);
  a05=(a05-a03);
  if (res[0]!=0) res[0][68]=a05;
  if (res[0]!=0) res[0][69]=a08;
  if (res[0]!=0) res[0][70]=a07;
  if (res[0]!=0) res[0][71]=a00;
  if (res[0]!=0) res[0][72]=a14;
  if (res[0]!=0) res[0][73]=a14;
  if (res[0]!=0) res[0][74]=a14;
  if (res[0]!=0) res[0][75]=a14;
  if (res[0]!=0) res[0][76]=a14;
  if (res[0]!=0) res[0][77]=a14;
  if (res[0]!=0) res[0][78]=a14;
  if (res[0]!=0) res[0][79]=a14;
  if (res[0]!=0) res[0][80]=a14;
  a14=arg[1]? arg[1][47] : 0;
  a04=(a14*a04);
  a05=arg[1]? arg[1][48] : 0;
  a15=(a05*a15);
  a04=(a04+a15);
  a15=arg[1]? arg[1][49] : 0;
  a08=(a15*a08);
  a04=(a04+a08);
  if (res[0]!=0) res[0][81]=a04;
  a09=(a14*a09);
  a06=(a05*a06);
  a09=(a09+a06);
  a07=(a15*a07);
  a09=(a09+a07);
  if (res[0]!=0) res[0][82]=a09;
  a14=(a14*a13);
  a05=(a05*a01);
  a14=(a14+a05);
  a15=(a15*a00);
  a14=(a14+a15);
  if (res[0]!=0) res[0][83]=a14;
  return 0;
}

CASADI_SYMBOL_EXPORT int snakecg_sp1_link_jacobians(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem){
  return casadi_f0(arg, res, iw, w, mem);
}

CASADI_SYMBOL_EXPORT int snakecg_sp1_link_jacobians_checkout(void) {
  return 0;
}

CASADI_SYMBOL_EXPORT void snakecg_sp1_link_jacobians_release(int mem) {
}

CASADI_SYMBOL_EXPORT void snakecg_sp1_link_jacobians_incref(void) {
}

CASADI_SYMBOL_EXPORT void snakecg_sp1_link_jacobians_decref(void) {
}

CASADI_SYMBOL_EXPORT casadi_int snakecg_sp1_link_jacobians_n_in(void) { return 2;}

CASADI_SYMBOL_EXPORT casadi_int snakecg_sp1_link_jacobians_n_out(void) { return 1;}

CASADI_SYMBOL_EXPORT casadi_real snakecg_sp1_link_jacobians_default_in(casadi_int i) {
  switch (i) {
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const char* snakecg_sp1_link_jacobians_name_in(casadi_int i) {
  switch (i) {
    case 0: return "q";
    case 1: return "K";
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const char* snakecg_sp1_link_jacobians_name_out(casadi_int i) {
  switch (i) {
    case 0: return "J";
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const casadi_int* snakecg_sp1_link_jacobians_sparsity_in(casadi_int i) {
  switch (i) {
    case 0: return casadi_s0;
    case 1: return casadi_s1;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const casadi_int* snakecg_sp1_link_jacobians_sparsity_out(casadi_int i) {
  switch (i) {
    case 0: return casadi_s2;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT int snakecg_sp1_link_jacobians_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w) {
  if (sz_arg) *sz_arg = 2;
  if (sz_res) *sz_res = 1;
  if (sz_iw) *sz_iw = 0;
  if (sz_w) *sz_w = 0;
  return 0;
}

CASADI_SYMBOL_EXPORT int snakecg_sp1_link_jacobians_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w) {
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

CASADI_SYMBOL_EXPORT int snakecg_sp1_batch_link_jacobians(casadi_int n, const casadi_real** arg,
    const casadi_int* stride, casadi_real** res) {
  const casadi_real* a[2];
  casadi_real* r[1];
  casadi_int* iw = (casadi_int*) malloc(sizeof(casadi_int) * 1);
  casadi_real* w = (casadi_real*) malloc(sizeof(casadi_real) * 18);
  casadi_int i, k;
  int status = 0;
  if (!iw || !w) { free(iw); free(w); return -1; }
  for (k = 0; k < 2; ++k) a[k] = 0;
  for (k = 0; k < 1; ++k) r[k] = 0;
  for (i = 0; i < n; ++i) {
    a[0] = arg[0] + i * stride[0];
    a[1] = arg[1] + i * stride[1];
    r[0] = res[0] + i * 84;
    if (snakecg_sp1_link_jacobians(a, r, iw, w, 0)) { status = (int) (i + 1); break; }
  }
  free(iw);
  free(w);
  return status;
}
