/* GENERATED FILE - DO NOT EDIT. C code emitted by CasADi for link_bias_accelerations() of
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
  #define CASADI_PREFIX(ID) snakecg_sp1_link_bias_accelerations_ ## ID
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
CASADI_SYMBOL_EXPORT void snakecg_sp1_link_bias_accelerations_casadi_version(int* major, int* minor, int* patch) {
  *major = 3;
  *minor = 8;
  *patch = 2;
}
CASADI_SYMBOL_EXPORT int snakecg_sp1_link_bias_accelerations_casadi_int_size(void) { return (int) sizeof(casadi_int); }
CASADI_SYMBOL_EXPORT int snakecg_sp1_link_bias_accelerations_casadi_real_size(void) { return (int) sizeof(casadi_real); }

static const casadi_int casadi_s0[3] = {8, 1, 1};
static const casadi_int casadi_s1[3] = {7, 1, 1};
static const casadi_int casadi_s2[3] = {71, 1, 1};
static const casadi_int casadi_s3[3] = {6, 2, 1};

/* snakecg_sp1_link_bias_accelerations:(q[8],v[7],K[71])->(bias[6x2]) */
static int casadi_f0(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem) {
  casadi_real a00, a01, a02, a03, a04, a05, a06, a07, a08, a09, a10, a11;
  casadi_real a12, a13, a14, a15, a16, a17, a18, a19, a20, a21, a22, a23;
  casadi_real a24, a25, a26;
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
  a20=arg[2]? arg[2][50] : 0;
  a21=(a03*a20);
  a18=arg[2]? arg[2][51] : 0;
  a15=(a14*a18);
  a21=(a21+a15);
  a15=arg[2]? arg[2][52] : 0;
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
  a25=arg[1]? arg[1][6] : 0;
  a20=arg[2]? arg[2][47] : 0;
  a19=(a20*a19);
  a06=arg[2]? arg[2][48] : 0;
  a04=(a06*a04);
  a19=(a19+a04);
  a04=arg[2]? arg[2][49] : 0;
  a12=(a04*a12);
  a19=(a19+a12);
  a12=(a19*a09);
  a03=(a20*a03);
  a14=(a06*a14);
  a03=(a03+a14);
  a16=(a04*a16);
  a03=(a03+a16);
  a16=(a03*a24);
  a12=(a12-a16);
  a12=(a25*a12);
  if (res[0]!=0) res[0][9]=a12;
  a20=(a20*a10);
  a06=(a06*a00);
  a20=(a20+a06);
  a04=(a04*a01);
  a20=(a20+a04);
  a24=(a20*a24);
  a19=(a19*a08);
  a24=(a24-a19);
  a24=(a25*a24);
  if (res[0]!=0) res[0][10]=a24;
  a03=(a03*a08);
  a20=(a20*a09);
  a03=(a03-a20);
  a25=(a25*a03);
  if (res[0]!=0) res[0][11]=a25;
  return 0;
}

CASADI_SYMBOL_EXPORT int snakecg_sp1_link_bias_accelerations(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem){
  return casadi_f0(arg, res, iw, w, mem);
}

CASADI_SYMBOL_EXPORT int snakecg_sp1_link_bias_accelerations_checkout(void) {
  return 0;
}

CASADI_SYMBOL_EXPORT void snakecg_sp1_link_bias_accelerations_release(int mem) {
}

CASADI_SYMBOL_EXPORT void snakecg_sp1_link_bias_accelerations_incref(void) {
}

CASADI_SYMBOL_EXPORT void snakecg_sp1_link_bias_accelerations_decref(void) {
}

CASADI_SYMBOL_EXPORT casadi_int snakecg_sp1_link_bias_accelerations_n_in(void) { return 3;}

CASADI_SYMBOL_EXPORT casadi_int snakecg_sp1_link_bias_accelerations_n_out(void) { return 1;}

CASADI_SYMBOL_EXPORT casadi_real snakecg_sp1_link_bias_accelerations_default_in(casadi_int i) {
  switch (i) {
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const char* snakecg_sp1_link_bias_accelerations_name_in(casadi_int i) {
  switch (i) {
    case 0: return "q";
    case 1: return "v";
    case 2: return "K";
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const char* snakecg_sp1_link_bias_accelerations_name_out(casadi_int i) {
  switch (i) {
    case 0: return "bias";
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const casadi_int* snakecg_sp1_link_bias_accelerations_sparsity_in(casadi_int i) {
  switch (i) {
    case 0: return casadi_s0;
    case 1: return casadi_s1;
    case 2: return casadi_s2;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const casadi_int* snakecg_sp1_link_bias_accelerations_sparsity_out(casadi_int i) {
  switch (i) {
    case 0: return casadi_s3;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT int snakecg_sp1_link_bias_accelerations_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w) {
  if (sz_arg) *sz_arg = 3;
  if (sz_res) *sz_res = 1;
  if (sz_iw) *sz_iw = 0;
  if (sz_w) *sz_w = 0;
  return 0;
}

CASADI_SYMBOL_EXPORT int snakecg_sp1_link_bias_accelerations_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w) {
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

CASADI_SYMBOL_EXPORT int snakecg_sp1_batch_link_bias_accelerations(casadi_int n, const casadi_real** arg,
    const casadi_int* stride, casadi_real** res) {
  const casadi_real* a[3];
  casadi_real* r[1];
  casadi_int* iw = (casadi_int*) malloc(sizeof(casadi_int) * 1);
  casadi_real* w = (casadi_real*) malloc(sizeof(casadi_real) * 28);
  casadi_int i, k;
  int status = 0;
  if (!iw || !w) { free(iw); free(w); return -1; }
  for (k = 0; k < 3; ++k) a[k] = 0;
  for (k = 0; k < 1; ++k) r[k] = 0;
  for (i = 0; i < n; ++i) {
    a[0] = arg[0] + i * stride[0];
    a[1] = arg[1] + i * stride[1];
    a[2] = arg[2] + i * stride[2];
    r[0] = res[0] + i * 12;
    if (snakecg_sp1_link_bias_accelerations(a, r, iw, w, 0)) { status = (int) (i + 1); break; }
  }
  free(iw);
  free(w);
  return status;
}
