/* GENERATED FILE - DO NOT EDIT. C code emitted by CasADi for link_poses() of
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
  #define CASADI_PREFIX(ID) snakecg_na6_link_poses_ ## ID
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

/* Configuration this file was compiled with */
CASADI_SYMBOL_EXPORT void snakecg_na6_link_poses_casadi_version(int* major, int* minor, int* patch) {
  *major = 3;
  *minor = 8;
  *patch = 2;
}
CASADI_SYMBOL_EXPORT int snakecg_na6_link_poses_casadi_int_size(void) { return (int) sizeof(casadi_int); }
CASADI_SYMBOL_EXPORT int snakecg_na6_link_poses_casadi_real_size(void) { return (int) sizeof(casadi_real); }

static const casadi_int casadi_s0[3] = {9, 1, 1};
static const casadi_int casadi_s1[3] = {71, 1, 1};
static const casadi_int casadi_s2[3] = {3, 7, 1};

/* snakecg_na6_link_poses:(q[9],K[71])->(poses[3x7]) */
static int casadi_f0(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem) {
  casadi_real a00, a01, a02, a03, a04, a05, a06, a07, a08, a09, a10, a11;
  a00=arg[0]? arg[0][0] : 0;
  if (res[0]!=0) res[0][0]=a00;
  a01=arg[0]? arg[0][1] : 0;
  if (res[0]!=0) res[0][1]=a01;
  a02=arg[0]? arg[0][2] : 0;
  if (res[0]!=0) res[0][2]=a02;
  a03=cos(a02);
  a04=arg[1]? arg[1][7] : 0;
  a05=arg[1]? arg[1][21] : 0;
  a04=(a04-a05);
  a05=(a03*a04);
  a00=(a00+a05);
  a05=arg[0]? arg[0][3] : 0;
  a06=cos(a05);
  a07=(a03*a06);
  a08=sin(a02);
  a09=sin(a05);
  a10=(a08*a09);
  a07=(a07-a10);
  a10=arg[1]? arg[1][22] : 0;
  a11=(a07*a10);
  a00=(a00+a11);
  if (res[0]!=0) res[0][3]=a00;
  a04=(a04*a08);
  a01=(a01+a04);
  a03=(a03*a09);
  a06=(a06*a08);
  a03=(a03+a06);
  a06=(a03*a10);
  a01=(a01+a06);
  if (res[0]!=0) res[0][4]=a01;
  a05=(a05+a02);
  if (res[0]!=0) res[0][5]=a05;
  a02=arg[1]? arg[1][8] : 0;
  a02=(a02-a10);
  a10=(a07*a02);
  a00=(a00+a10);
  a10=arg[0]? arg[0][4] : 0;
  a06=cos(a10);
  a08=(a07*a06);
  a09=sin(a10);
  a04=(a03*a09);
  a08=(a08-a04);
  a04=arg[1]? arg[1][23] : 0;
  a11=(a08*a04);
  a00=(a00+a11);
  if (res[0]!=0) res[0][6]=a00;
  a02=(a02*a03);
  a01=(a01+a02);
  a07=(a07*a09);
  a06=(a06*a03);
  a07=(a07+a06);
  a06=(a07*a04);
  a01=(a01+a06);
  if (res[0]!=0) res[0][7]=a01;
  a05=(a05+a10);
  if (res[0]!=0) res[0][8]=a05;
  a10=arg[1]? arg[1][9] : 0;
  a10=(a10-a04);
  a04=(a08*a10);
  a00=(a00+a04);
  a04=arg[0]? arg[0][5] : 0;
  a06=cos(a04);
  a03=(a08*a06);
  a09=sin(a04);
  a02=(a07*a09);
  a03=(a03-a02);
  a02=arg[1]? arg[1][24] : 0;
  a11=(a03*a02);
  a00=(a00+a11);
  if (res[0]!=0) res[0][9]=a00;
  a10=(a10*a07);
  a01=(a01+a10);
  a08=(a08*a09);
  a06=(a06*a07);
  a08=(a08+a06);
  a06=(a08*a02);
  a01=(a01+a06);
  if (res[0]!=0) res[0][10]=a01;
  a05=(a05+a04);
  if (res[0]!=0) res[0][11]=a05;
  a04=arg[1]? arg[1][10] : 0;
  a04=(a04-a02);
  a02=(a03*a04);
  a00=(a00+a02);
  a02=arg[0]? arg[0][6] : 0;
  a06=cos(a02);
  a07=(a03*a06);
  a09=sin(a02);
  a10=(a08*a09);
  a07=(a07-a10);
  a10=arg[1]? arg[1][25] : 0;
  a11=(a07*a10);
  a00=(a00+a11);
  if (res[0]!=0) res[0][12]=a00;
  a04=(a04*a08);
  a01=(a01+a04);
  a03=(a03*a09);
  a06=(a06*a08);
  a03=(a03+a06);
  a06=(a03*a10);
  a01=(a01+a06);
  if (res[0]!=0) res[0][13]=a01;
  a05=(a05+a02);
  if (res[0]!=0) res[0][14]=a05;
  a02=arg[1]? arg[1][11] : 0;
  a02=(a02-a10);
  a10=(a07*a02);
  a00=(a00+a10);
  a10=arg[0]? arg[0][7] : 0;
  a06=cos(a10);
  a08=(a07*a06);
  a09=sin(a10);
  a04=(a03*a09);
  a08=(a08-a04);
  a04=arg[1]? arg[1][26] : 0;
  a11=(a08*a04);
  a00=(a00+a11);
  if (res[0]!=0) res[0][15]=a00;
  a02=(a02*a03);
  a01=(a01+a02);
  a07=(a07*a09);
  a06=(a06*a03);
  a07=(a07+a06);
  a06=(a07*a04);
  a01=(a01+a06);
  if (res[0]!=0) res[0][16]=a01;
  a05=(a05+a10);
  if (res[0]!=0) res[0][17]=a05;
  a10=arg[1]? arg[1][12] : 0;
  a10=(a10-a04);
  a04=(a08*a10);
  a00=(a00+a04);
  a04=arg[0]? arg[0][8] : 0;
  a06=cos(a04);
  a03=(a08*a06);
  a09=sin(a04);
  a02=(a07*a09);
  a03=(a03-a02);
  a02=arg[1]? arg[1][27] : 0;
  a03=(a03*a02);
  a00=(a00+a03);
  if (res[0]!=0) res[0][18]=a00;
  a10=(a10*a07);
  a01=(a01+a10);
  a08=(a08*a09);
  a06=(a06*a07);
  a08=(a08+a06);
  a08=(a08*a02);
  a01=(a01+a08);
  if (res[0]!=0) res[0][19]=a01;
  a05=(a05+a04);
  if (res[0]!=0) res[0][20]=a05;
  return 0;
}

CASADI_SYMBOL_EXPORT int snakecg_na6_link_poses(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem){
  return casadi_f0(arg, res, iw, w, mem);
}

CASADI_SYMBOL_EXPORT int snakecg_na6_link_poses_checkout(void) {
  return 0;
}

CASADI_SYMBOL_EXPORT void snakecg_na6_link_poses_release(int mem) {
}

CASADI_SYMBOL_EXPORT void snakecg_na6_link_poses_incref(void) {
}

CASADI_SYMBOL_EXPORT void snakecg_na6_link_poses_decref(void) {
}

CASADI_SYMBOL_EXPORT casadi_int snakecg_na6_link_poses_n_in(void) { return 2;}

CASADI_SYMBOL_EXPORT casadi_int snakecg_na6_link_poses_n_out(void) { return 1;}

CASADI_SYMBOL_EXPORT casadi_real snakecg_na6_link_poses_default_in(casadi_int i) {
  switch (i) {
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const char* snakecg_na6_link_poses_name_in(casadi_int i) {
  switch (i) {
    case 0: return "q";
    case 1: return "K";
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const char* snakecg_na6_link_poses_name_out(casadi_int i) {
  switch (i) {
    case 0: return "poses";
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const casadi_int* snakecg_na6_link_poses_sparsity_in(casadi_int i) {
  switch (i) {
    case 0: return casadi_s0;
    case 1: return casadi_s1;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const casadi_int* snakecg_na6_link_poses_sparsity_out(casadi_int i) {
  switch (i) {
    case 0: return casadi_s2;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT int snakecg_na6_link_poses_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w) {
  if (sz_arg) *sz_arg = 2;
  if (sz_res) *sz_res = 1;
  if (sz_iw) *sz_iw = 0;
  if (sz_w) *sz_w = 0;
  return 0;
}

CASADI_SYMBOL_EXPORT int snakecg_na6_link_poses_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w) {
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

CASADI_SYMBOL_EXPORT int snakecg_na6_batch_link_poses(casadi_int n, const casadi_real** arg,
    const casadi_int* stride, casadi_real** res) {
  const casadi_real* a[2];
  casadi_real* r[1];
  casadi_int* iw = (casadi_int*) malloc(sizeof(casadi_int) * 1);
  casadi_real* w = (casadi_real*) malloc(sizeof(casadi_real) * 13);
  casadi_int i, k;
  int status = 0;
  if (!iw || !w) { free(iw); free(w); return -1; }
  for (k = 0; k < 2; ++k) a[k] = 0;
  for (k = 0; k < 1; ++k) r[k] = 0;
  for (i = 0; i < n; ++i) {
    a[0] = arg[0] + i * stride[0];
    a[1] = arg[1] + i * stride[1];
    r[0] = res[0] + i * 21;
    if (snakecg_na6_link_poses(a, r, iw, w, 0)) { status = (int) (i + 1); break; }
  }
  free(iw);
  free(w);
  return status;
}
