/* GENERATED FILE - DO NOT EDIT. C code emitted by CasADi for scene_kinematics() of
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
  #define CASADI_PREFIX(ID) snakecg_na1_scene_kinematics_ ## ID
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
#define casadi_s4 CASADI_PREFIX(s4)
#define casadi_s5 CASADI_PREFIX(s5)

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
CASADI_SYMBOL_EXPORT void snakecg_na1_scene_kinematics_casadi_version(int* major, int* minor, int* patch) {
  *major = 3;
  *minor = 8;
  *patch = 2;
}
CASADI_SYMBOL_EXPORT int snakecg_na1_scene_kinematics_casadi_int_size(void) { return (int) sizeof(casadi_int); }
CASADI_SYMBOL_EXPORT int snakecg_na1_scene_kinematics_casadi_real_size(void) { return (int) sizeof(casadi_real); }

static const casadi_int casadi_s0[3] = {4, 1, 1};
static const casadi_int casadi_s1[3] = {16, 1, 1};
static const casadi_int casadi_s2[3] = {3, 2, 1};
static const casadi_int casadi_s3[3] = {6, 4, 1};
static const casadi_int casadi_s4[3] = {4, 4, 1};
static const casadi_int casadi_s5[3] = {2, 2, 1};

/* snakecg_na1_scene_kinematics:(q[4],K[16])->(poses[3x2],J[6x4],M[4x4],cs[2x2]) */
static int casadi_f0(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem) {
  casadi_real a00, a01, a02, a03, a04, a05, a06, a07, a08, a09, a10, a11;
  casadi_real a12;
  a00=arg[0]? arg[0][0] : 0;
  if (res[0]!=0) res[0][0]=a00;
  a01=arg[0]? arg[0][1] : 0;
  if (res[0]!=0) res[0][1]=a01;
  a02=arg[0]? arg[0][2] : 0;
  if (res[0]!=0) res[0][2]=a02;
  a03=cos(a02);
  a04=arg[1]? arg[1][2] : 0;
  a05=arg[1]? arg[1][6] : 0;
  a04=(a04-a05);
  a05=(a03*a04);
  a05=(a00+a05);
  a06=arg[0]? arg[0][3] : 0;
  a07=cos(a06);
  a08=(a03*a07);
  a09=sin(a02);
  a10=sin(a06);
  a11=(a09*a10);
  a08=(a08-a11);
  a11=arg[1]? arg[1][7] : 0;
  a12=(a08*a11);
  a05=(a05+a12);
  if (res[0]!=0) res[0][3]=a05;
  a04=(a04*a09);
  a04=(a01+a04);
  a10=(a03*a10);
  a07=(a07*a09);
  a10=(a10+a07);
  a11=(a10*a11);
  a04=(a04+a11);
  if (res[0]!=0) res[0][4]=a04;
  a06=(a06+a02);
  if (res[0]!=0) res[0][5]=a06;
  a06=1.;
  if (res[1]!=0) res[1][0]=a06;
  a02=0.;
  if (res[1]!=0) res[1][1]=a02;
  if (res[1]!=0) res[1][2]=a02;
  if (res[1]!=0) res[1][3]=a06;
  if (res[1]!=0) res[1][4]=a02;
  if (res[1]!=0) res[1][5]=a02;
  if (res[1]!=0) res[1][6]=a02;
  if (res[1]!=0) res[1][7]=a06;
  if (res[1]!=0) res[1][8]=a02;
  if (res[1]!=0) res[1][9]=a02;
  if (res[1]!=0) res[1][10]=a06;
  if (res[1]!=0) res[1][11]=a02;
  if (res[1]!=0) res[1][12]=a02;
  if (res[1]!=0) res[1][13]=a02;
  if (res[1]!=0) res[1][14]=a06;
  a01=(a01-a04);
  if (res[1]!=0) res[1][15]=a01;
  a05=(a05-a00);
  if (res[1]!=0) res[1][16]=a05;
  if (res[1]!=0) res[1][17]=a06;
  if (res[1]!=0) res[1][18]=a02;
  if (res[1]!=0) res[1][19]=a02;
  if (res[1]!=0) res[1][20]=a02;
  a11=(-a11);
  if (res[1]!=0) res[1][21]=a11;
  if (res[1]!=0) res[1][22]=a12;
  if (res[1]!=0) res[1][23]=a06;
  a06=arg[1]? arg[1][8] : 0;
  if (res[2]!=0) res[2][0]=a06;
  if (res[2]!=0) res[2][1]=a02;
  a12=arg[1]? arg[1][10] : 0;
  a11=(a12*a10);
  a05=arg[1]? arg[1][9] : 0;
  a00=(a05*a09);
  a00=(a11+a00);
  a00=(-a00);
  if (res[2]!=0) res[2][2]=a00;
  a11=(-a11);
  if (res[2]!=0) res[2][3]=a11;
  if (res[2]!=0) res[2][4]=a02;
  if (res[2]!=0) res[2][5]=a06;
  a12=(a12*a08);
  a05=(a05*a03);
  a05=(a12+a05);
  if (res[2]!=0) res[2][6]=a05;
  if (res[2]!=0) res[2][7]=a12;
  if (res[2]!=0) res[2][8]=a00;
  if (res[2]!=0) res[2][9]=a05;
  a05=(a08*a03);
  a00=(a10*a09);
  a05=(a05+a00);
  a00=arg[1]? arg[1][12] : 0;
  a05=(a05*a00);
  a00=arg[1]? arg[1][14] : 0;
  a00=(a05+a00);
  a06=arg[1]? arg[1][15] : 0;
  a05=(a05+a06);
  a00=(a00+a05);
  if (res[2]!=0) res[2][10]=a00;
  if (res[2]!=0) res[2][11]=a05;
  if (res[2]!=0) res[2][12]=a11;
  if (res[2]!=0) res[2][13]=a12;
  if (res[2]!=0) res[2][14]=a05;
  if (res[2]!=0) res[2][15]=a06;
  if (res[3]!=0) res[3][0]=a03;
  if (res[3]!=0) res[3][1]=a09;
  if (res[3]!=0) res[3][2]=a08;
  if (res[3]!=0) res[3][3]=a10;
  return 0;
}

CASADI_SYMBOL_EXPORT int snakecg_na1_scene_kinematics(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem){
  return casadi_f0(arg, res, iw, w, mem);
}

CASADI_SYMBOL_EXPORT int snakecg_na1_scene_kinematics_checkout(void) {
  return 0;
}

CASADI_SYMBOL_EXPORT void snakecg_na1_scene_kinematics_release(int mem) {
}

CASADI_SYMBOL_EXPORT void snakecg_na1_scene_kinematics_incref(void) {
}

CASADI_SYMBOL_EXPORT void snakecg_na1_scene_kinematics_decref(void) {
}

CASADI_SYMBOL_EXPORT casadi_int snakecg_na1_scene_kinematics_n_in(void) { return 2;}

CASADI_SYMBOL_EXPORT casadi_int snakecg_na1_scene_kinematics_n_out(void) { return 4;}

CASADI_SYMBOL_EXPORT casadi_real snakecg_na1_scene_kinematics_default_in(casadi_int i) {
  switch (i) {
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const char* snakecg_na1_scene_kinematics_name_in(casadi_int i) {
  switch (i) {
    case 0: return "q";
    case 1: return "K";
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const char* snakecg_na1_scene_kinematics_name_out(casadi_int i) {
  switch (i) {
    case 0: return "poses";
    case 1: return "J";
    case 2: return "M";
    case 3: return "cs";
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const casadi_int* snakecg_na1_scene_kinematics_sparsity_in(casadi_int i) {
  switch (i) {
    case 0: return casadi_s0;
    case 1: return casadi_s1;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const casadi_int* snakecg_na1_scene_kinematics_sparsity_out(casadi_int i) {
  switch (i) {
    case 0: return casadi_s2;
    case 1: return casadi_s3;
    case 2: return casadi_s4;
    case 3: return casadi_s5;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT int snakecg_na1_scene_kinematics_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w) {
  if (sz_arg) *sz_arg = 2;
  if (sz_res) *sz_res = 4;
  if (sz_iw) *sz_iw = 0;
  if (sz_w) *sz_w = 0;
  return 0;
}

CASADI_SYMBOL_EXPORT int snakecg_na1_scene_kinematics_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w) {
  if (sz_arg) *sz_arg = 2*sizeof(const casadi_real*);
  if (sz_res) *sz_res = 4*sizeof(casadi_real*);
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

CASADI_SYMBOL_EXPORT int snakecg_na1_batch_scene_kinematics(casadi_int n, const casadi_real** arg,
    const casadi_int* stride, casadi_real** res) {
  const casadi_real* a[2];
  casadi_real* r[4];
  casadi_int* iw = (casadi_int*) malloc(sizeof(casadi_int) * 1);
  casadi_real* w = (casadi_real*) malloc(sizeof(casadi_real) * 14);
  casadi_int i, k;
  int status = 0;
  if (!iw || !w) { free(iw); free(w); return -1; }
  for (k = 0; k < 2; ++k) a[k] = 0;
  for (k = 0; k < 4; ++k) r[k] = 0;
  for (i = 0; i < n; ++i) {
    a[0] = arg[0] + i * stride[0];
    a[1] = arg[1] + i * stride[1];
    r[0] = res[0] + i * 6;
    r[1] = res[1] + i * 24;
    r[2] = res[2] + i * 16;
    r[3] = res[3] + i * 4;
    if (snakecg_na1_scene_kinematics(a, r, iw, w, 0)) { status = (int) (i + 1); break; }
  }
  free(iw);
  free(w);
  return status;
}
